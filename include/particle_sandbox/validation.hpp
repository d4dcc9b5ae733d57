#pragma once
/// \file
/// Whether a world definition and solver settings are acceptable, without making a world.

#include <string>
#include <string_view>
#include <vector>

#include <particle_sandbox/solver_settings.hpp>
#include <particle_sandbox/world_def.hpp>

namespace psb {

/// One thing wrong with a WorldDef or SolverSettings.
struct SettingProblem {
    std::string_view setting;  ///< the field: "width", "height", "gravity", "restitution",
                               ///< "friction", "tangential restitution", "substeps", "mode",
                               ///< "broadphase" or "obstacles"
    std::string message;       ///< what is wrong with it, e.g. "must be finite and > 0 (got -1)"
    /// For a value refused only in combination with another setting, that setting's name (the
    /// setting that refuses it); otherwise empty.
    std::string_view because;
};

/// Everything World would refuse about `def` and `solver`, in the order World checks them
/// (the box and the laws, then the solver, then combinations); empty when a World(def, solver)
/// would be made. Never throws. World's own InvalidArgument reads "<where>: <setting> <message>"
/// for the first problem. Each obstacle's own geometry (finite, inside the box, of non-zero
/// length) is World's to check: its message names the obstacle by index.
[[nodiscard]] std::vector<SettingProblem> validate(const WorldDef& def,
                                                   const SolverSettings& solver);

/// "<setting> <message>": a problem as one phrase.
[[nodiscard]] std::string describe(const SettingProblem& problem);

}  // namespace psb
