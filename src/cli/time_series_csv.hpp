#pragma once
// particle-sim --timeseries: a run's observables as CSV, one row per sample (the columns are
// data_tables.hpp's, shared with the app's export); with --track, the chosen particles' paths.

#include <cstdint>
#include <filesystem>
#include <string>

#include <particle_sandbox/time_series.hpp>

namespace psb::cli {

/// The header line: column names with their units after the last underscore.
inline constexpr const char* kTimeSeriesCsvHeader =
    "time_s,kinetic_energy_J,momentum_x_kg_m_per_s,momentum_y_kg_m_per_s,com_x_m,com_y_m,"
    "collisions,collision_rate_per_s";

/// The two columns added after collision_rate_per_s when the world has gravity.
inline constexpr const char* kTimeSeriesCsvGravityColumns =
    ",potential_energy_J,mechanical_energy_J";

/// The two columns added last when the world keeps rotation (discs that turn).
inline constexpr const char* kTimeSeriesCsvRotationColumns =
    ",rotational_energy_J,angular_momentum_kg_m2_per_s";

/// Most rows --timeseries writes (about 1 GB of text); a run that would write more is refused.
inline constexpr std::uint64_t kMaxTimeSeriesRows = 10'000'000;

/// The header and one row per sample of `series`, oldest first, each line ending in '\n'
/// (psb::timeSeriesTable). Values are written as the shortest decimal that reads back
/// bit-exact, times to 12 significant digits (0.3, not 0.30000000000000004). With `gravity`
/// each row also has the potential and the mechanical (kinetic + potential) energy.
/// With `rotation` (RunReport::rotation) each row ends with the rotational energy and the
/// angular momentum (kRotationColumns).
[[nodiscard]] std::string timeSeriesCsv(const TimeSeries& series, bool gravity = false,
                                        bool rotation = false);

/// Where --track writes the trajectories: beside the --timeseries file, "-track" added to its
/// name (runs/gas.csv: runs/gas-track.csv).
[[nodiscard]] std::filesystem::path trackPath(const std::filesystem::path& timeseries);

}  // namespace psb::cli
