#pragma once
// Running a scene headless and measuring what happened.

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include <particle_sandbox/bins.hpp>
#include <particle_sandbox/math.hpp>
#include <particle_sandbox/observables.hpp>
#include <particle_sandbox/scene.hpp>
#include <particle_sandbox/time_series.hpp>
#include <particle_sandbox/trajectory.hpp>

#include "run_options.hpp"

namespace psb::cli {

/// What a run did: the content of the JSON report.
struct RunReport {
    SolverSettings solver;          ///< the settings used (scene overridden by options)
    double dt = 0.0;                ///< seconds per step: the scene's frame length, or --dt
    BroadPhaseKind broadphaseUsed;  ///< what `auto` resolved to
    int threads = 1;                ///< as requested
    std::uint64_t particles = 0;
    std::uint64_t steps = 0;  ///< calls of World::step (each of dt seconds)
    double simTime = 0.0;     ///< seconds
    double wallSeconds = 0.0;
    std::uint64_t collisions = 0;
    std::uint64_t wallCollisions = 0;
    std::uint64_t obstacles = 0;           ///< fixed pegs and segments in the world
    std::uint64_t obstacleCollisions = 0;  ///< rebounds off them
    double kineticEnergyInitial = 0.0, kineticEnergyFinal = 0.0;  ///< joules
    /// Gravitational potential energy (diagnostics.hpp's reference: the floor), joules; the
    /// report lists it, and kinetic + potential, only when `gravity`.
    bool gravity = false;
    double potentialEnergyInitial = 0.0, potentialEnergyFinal = 0.0;
    /// Rotational kinetic energy Σ ½ I ω², joules, and the total angular momentum (orbital +
    /// spin, about the box's top-left corner), kg·m²/s. `rotation`: the world kept rotation by
    /// the end of the run (World::rotationInUse), and the time series has both columns.
    bool rotation = false;
    double rotationalEnergyInitial = 0.0, rotationalEnergyFinal = 0.0;
    double angularMomentumInitial = 0.0, angularMomentumFinal = 0.0;
    Vec2 momentumInitial = Vec2::Zero(), momentumFinal = Vec2::Zero();  ///< kg·m/s
    double wallImpulse = 0.0;                                           ///< kg·m/s
    /// Exact mode: steps that ended before their end (an event budget ran out). The runner
    /// sets none, so a run it reports is whole; a non-zero count fails the run.
    std::uint64_t cutShort = 0;
    double maxOverlap = 0.0;  ///< metres
    std::uint64_t escaped = 0;
    /// The scene's bins at the end, when it has bins.
    std::optional<BinsMeasurement> bins;
    /// Each of the scene's ball droppers: balls it released during the run and balls it has
    /// left to drop at the end.
    struct DropperCount {
        std::uint64_t released = 0;
        std::uint64_t left = 0;
    };
    std::vector<DropperCount> droppers;
    /// --warmup's simulated seconds, run before everything above was counted (0: none).
    double warmup = 0.0;
    /// --observables: what the window over the measured part found.
    std::optional<ObservablesResult> observables;
};

/// The scene's solver settings with the command line's overrides applied. Throws UsageError
/// when the world refuses the result (e.g. a mode this build lacks), naming the option.
[[nodiscard]] SolverSettings effectiveSolver(const Scene& scene, const RunOptions& options);

/// The frame length the run steps by: --dt when given, else the scene's (Scene::dt).
[[nodiscard]] double effectiveDt(const Scene& scene, const RunOptions& options);

/// Called after each step with (steps done, steps in all).
using ProgressFn = std::function<void(std::uint64_t, std::uint64_t)>;

/// Runs `scene` for stepsFor(options.warmup, dt) steps of warm-up, then for
/// stepsFor(options.duration, dt) measured steps of dt = effectiveDt(scene, options), and
/// returns the report of the measured steps (with options.observables, the observables window
/// opened after the warm-up and closed at the end, sampled after every step). `world`
/// receives the final state (for --save). When `series` is given it is replaced by one sized
/// for the whole run and receives the initial state, every options.timeseriesEvery-th step and
/// the final state; a run that would need more than kMaxTimeSeriesRows samples throws
/// UsageError naming --timeseries-every before any step. When `track` is given it is replaced
/// by a trajectory of the particles options.track names, sampled at the same instants as
/// `series`; a number that names no particle of the scene throws UsageError naming --track
/// before any step.
[[nodiscard]] RunReport runScene(const Scene& scene, const RunOptions& options, World& world,
                                 const ProgressFn& progress = {}, TimeSeries* series = nullptr,
                                 Trajectory* track = nullptr);

/// The ids of the particles numbered `numbers` in `world` (their id's slot). Throws UsageError
/// naming --track and the first number that names no particle.
[[nodiscard]] std::vector<ParticleId> trackedIds(const World& world,
                                                 const std::vector<std::uint32_t>& numbers);

/// Particles whose centre lies outside the box [0, width] × [0, height].
[[nodiscard]] std::uint64_t countEscaped(const World& world);

}  // namespace psb::cli
