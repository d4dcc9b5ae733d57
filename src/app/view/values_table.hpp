#pragma once
// The values table (PhET's "More Data"), as plain rows: every particle's signed position,
// velocity, momentum, kinetic energy and mass, and their totals (the momentum as a vector), with
// each column's name and unit; in a world that keeps rotation also each angular velocity and
// rotational kinetic energy. The panel's Values table window shows it, with the position,
// velocity and mass cells editable; the text F12 writes beside a screenshot lists it.

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <particle_sandbox/axes.hpp>
#include <particle_sandbox/world.hpp>

#include "session/edit_prompt.hpp"

namespace psb::app {

/// Rows the table lists at most; beyond, the totals and the selected particle's row.
inline constexpr std::size_t kValuesMaxRows = 60;

struct ValuesColumn {
    const char* name;  ///< "vx"
    const char* unit;  ///< "m/s"
    /// The particle's field a cell of this column edits (none: computed, read only).
    std::optional<ParticleField> field;
};

/// The most columns a table has.
inline constexpr std::size_t kValuesColumns = 10;
/// x, y, vx, vy, px, py, kinetic energy, mass: the order of ValuesRow::values; with `rotation`
/// (World::rotationInUse) omega (rad/s) after vy and the rotational kinetic energy after the
/// kinetic energy.
[[nodiscard]] std::vector<ValuesColumn> valuesColumns(bool rotation = false);

struct ValuesRow {
    ParticleId id;
    std::uint64_t number = 0;    ///< particleNumber(id)
    std::vector<double> values;  ///< one per column
};

struct ValuesTable {
    std::vector<ValuesColumn> columns;  ///< valuesColumns(rotation in use)
    std::vector<ValuesRow> rows;        ///< by number
    /// Sums: px, py, the kinetic energies and the mass (position, velocity and angular velocity
    /// columns: NaN, as a sum of positions means nothing).
    std::vector<double> totals;
    std::size_t particles = 0;
    /// Why rows were left out (more than kValuesMaxRows particles); empty when all are listed.
    std::string note;
    /// Which way y and turning count (axesNote).
    std::string axes;
};

/// "y up from the floor; vy, py up; omega counterclockwise (Show: y up)" or its y-down
/// counterpart: what a signed y number means, said beside the numbers.
[[nodiscard]] std::string axesNote(const Axes& axes, bool rotation);

/// The table of `world`: every particle when there are at most kValuesMaxRows, else only
/// `selected`'s row (if any); the totals always cover every particle. In `axes` (the y up
/// option): y, vy, py and omega as the user reads them.
[[nodiscard]] ValuesTable valuesTable(const World& world, std::optional<ParticleId> selected,
                                      const Axes& axes = {});

/// A cell as shown: three significant figures, signed ("-2.50"), "" for NaN.
[[nodiscard]] std::string valuesCell(double value);

/// The table as text lines (a header naming each unit, a row per particle, the totals), for
/// the screenshot's text file.
[[nodiscard]] std::vector<std::string> valuesLines(const ValuesTable& table);

}  // namespace psb::app
