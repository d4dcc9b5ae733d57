#pragma once
/// \file
/// How a world is stepped: the speed/accuracy choice.

#include <optional>
#include <string_view>

namespace psb {

/// How World::step advances time.
enum class StepMode {
    Discrete,  ///< one move and one collision pass per dt (the original program's step, fixed)
    Substep,   ///< `substeps` discrete steps of dt / substeps
    Exact,     ///< event-driven: every collision resolved at its exact time
};

/// Which broadphase finds the candidate pairs in the discrete and substep modes.
enum class BroadPhaseKind {
    Auto,      ///< chosen from the particle count and the spread of radii
    AllPairs,  ///< every pair tested: O(n²), the reference
    Grid,      ///< uniform grid built by counting sort
    Quadtree,  ///< region quadtree
};

/// Most substeps per step: beyond this one step(dt) would take minutes, not milliseconds.
inline constexpr int kMaxSubsteps = 100'000;

/// How a world steps: the solver block of a scene without its frame length (Scene::dt, which
/// World::step takes as its argument).
struct SolverSettings {
    StepMode mode = StepMode::Discrete;
    int substeps = 1;  ///< in [1, kMaxSubsteps]; used by StepMode::Substep
    BroadPhaseKind broadphase = BroadPhaseKind::Auto;
};

/// Lower-case names as scene files and command lines spell them ("discrete", "all-pairs", ...).
[[nodiscard]] std::string_view toString(StepMode mode);
[[nodiscard]] std::string_view toString(BroadPhaseKind kind);
[[nodiscard]] std::optional<StepMode> parseStepMode(std::string_view name);
[[nodiscard]] std::optional<BroadPhaseKind> parseBroadPhase(std::string_view name);

}  // namespace psb
