#include "runner.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <particle_sandbox/csv.hpp>
#include <particle_sandbox/diagnostics.hpp>
#include <particle_sandbox/error.hpp>
#include <particle_sandbox/validation.hpp>

#include "time_series_csv.hpp"

namespace psb::cli {

SolverSettings effectiveSolver(const Scene& scene, const RunOptions& o) {
    SolverSettings s = scene.solver;
    if (o.mode) s.mode = *o.mode;
    if (o.substeps) s.substeps = *o.substeps;
    if (o.broadphase) s.broadphase = *o.broadphase;
    // World's own reasons, each named after the option that caused it: the mode (also for a
    // value refused in combination with it), the broadphase, then anything else.
    const std::vector<SettingProblem> problems = validate(scene.world, s);
    const auto why = [](const SettingProblem& p) { return "World: " + describe(p); };
    for (const SettingProblem& p : problems) {
        if (p.setting == "mode" || p.because == "mode") {
            throw UsageError("--mode " + std::string(toString(s.mode)) + ": refused (" + why(p) +
                             ")");
        }
    }
    for (const SettingProblem& p : problems) {
        if (p.setting == "broadphase") {
            throw UsageError("--broadphase " + std::string(toString(s.broadphase)) + ": refused (" +
                             why(p) + ")");
        }
    }
    if (!problems.empty()) throw UsageError("solver settings refused (" + why(problems[0]) + ")");
    return s;
}

double effectiveDt(const Scene& scene, const RunOptions& o) {
    return o.dt ? *o.dt : scene.dt;
}

std::uint64_t countEscaped(const World& world) {
    const ParticleArrays& p = world.particles();
    const double w = world.def().width, h = world.def().height;
    std::uint64_t n = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        // Written so that a NaN position counts as escaped.
        if (!(p.x[i] >= 0.0 && p.x[i] <= w && p.y[i] >= 0.0 && p.y[i] <= h)) ++n;
    }
    return n;
}

std::vector<ParticleId> trackedIds(const World& world, const std::vector<std::uint32_t>& numbers) {
    std::vector<ParticleId> live = world.ids();
    std::vector<ParticleId> ids;
    for (const std::uint32_t n : numbers) {
        const auto it = std::find_if(live.begin(), live.end(),
                                     [n](ParticleId id) { return particleNumber(id) == n; });
        if (it == live.end()) {
            throw UsageError(
                "--track: no particle " + std::to_string(n) + ": the scene has " +
                std::to_string(live.size()) + " particles" +
                (live.empty() ? std::string() : ", numbered 1 to " + std::to_string(live.size())));
        }
        ids.push_back(*it);
    }
    return ids;
}

RunReport runScene(const Scene& scene, const RunOptions& options, World& world,
                   const ProgressFn& progress, TimeSeries* series, Trajectory* track) {
    // What the options' parser checks for particle-sim, checked again for callers that build
    // RunOptions themselves (the Python module's sweep): a negative time would be a step count
    // past 10^19.
    const auto check = [](double v, bool zero, const char* what) {
        if (!std::isfinite(v) || v < 0.0 || (!zero && v == 0.0)) {
            throw InvalidArgument(std::string(what) + ": must be finite and " +
                                  (zero ? ">= 0" : "> 0") + " seconds (got " + csv::number(v) +
                                  ")");
        }
    };
    check(options.duration, true, "duration");
    check(options.warmup, true, "warmup");
    if (options.dt) check(*options.dt, false, "dt");
    Scene s = scene;
    s.solver = effectiveSolver(scene, options);
    s.dt = effectiveDt(scene, options);
    world = makeWorld(s);
    world.setThreads(options.threads);

    RunReport r;
    const std::uint64_t warmupSteps = stepsFor(options.warmup, s.dt);
    const std::uint64_t measuredSteps = stepsFor(options.duration, s.dt);
    if (warmupSteps > 0) {
        // Run, then measure: what the report counts starts after the warm-up.
        for (std::uint64_t k = 0; k < warmupSteps; ++k) {
            world.step(s.dt);
            if (progress) progress(k + 1, warmupSteps + measuredSteps);
        }
        world.resetCounters();
        r.warmup = world.time();
    }
    r.solver = s.solver;
    r.dt = s.dt;
    r.threads = options.threads;
    r.particles = world.size();
    r.steps = measuredSteps;
    r.kineticEnergyInitial = kineticEnergy(world);
    r.gravity = !world.def().gravity.isZero();
    r.potentialEnergyInitial = potentialEnergy(world);
    r.rotationalEnergyInitial = rotationalEnergy(world);
    r.angularMomentumInitial = angularMomentum(world);
    r.momentumInitial = momentum(world);
    const double overlapInitial = maxOverlap(world);

    const auto every =
        static_cast<std::uint64_t>(std::max<std::int64_t>(1, options.timeseriesEvery));
    if (series != nullptr) {
        // The initial state, each every-th step, and the last step when it is not one of those.
        const std::uint64_t rows = 1 + r.steps / every + (r.steps % every != 0 ? 1 : 0);
        if (rows > kMaxTimeSeriesRows) {
            throw UsageError("--timeseries-every: " + std::to_string(rows) +
                             " rows is more than the limit of " +
                             std::to_string(kMaxTimeSeriesRows) + "; use --timeseries-every " +
                             std::to_string(r.steps / (kMaxTimeSeriesRows - 2) + 1) + " or more");
        }
        *series = TimeSeries(static_cast<std::size_t>(rows));
        series->record(world);
    }
    if (track != nullptr) {
        const std::vector<ParticleId> ids = trackedIds(world, options.track);
        const std::uint64_t rows = 1 + r.steps / every + (r.steps % every != 0 ? 1 : 0);
        if (rows * ids.size() > kMaxTimeSeriesRows) {
            throw UsageError("--track: " + std::to_string(rows * ids.size()) +
                             " rows is more than the limit of " +
                             std::to_string(kMaxTimeSeriesRows) +
                             "; track fewer particles or use a larger --timeseries-every");
        }
        *track = Trajectory(ids, static_cast<std::size_t>(rows * ids.size()));
        track->record(world);
    }

    std::optional<ObservablesWindow> window;
    if (options.observables) {
        ObservablesSettings settings =
            suggestedObservablesSettings(world, s.dt, true, options.gr.has_value());
        if (options.maxLag) {
            const double interval = settings.stateEvery * s.dt;
            settings.maxLag = static_cast<std::uint32_t>(
                std::clamp(std::round(*options.maxLag / interval), 1.0, 1e6));
            // Long lags are where the averages are thin (the VACF's tail): a new time origin
            // every sixteenth of the longest lag, not every half.
            settings.originEvery = std::max(1u, settings.maxLag / 16);
        }
        window.emplace(settings);
        window->open(world);
    }
    const auto start = std::chrono::steady_clock::now();
    for (std::uint64_t k = 0; k < r.steps; ++k) {
        world.step(s.dt);
        if (window) window->sample(world);
        if ((k + 1) % every == 0 || k + 1 == r.steps) {
            if (series != nullptr) series->record(world);
            if (track != nullptr) track->record(world);
        }
        if (progress) progress(warmupSteps + k + 1, warmupSteps + r.steps);
    }
    if (window) r.observables = window->close(world);
    r.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    r.broadphaseUsed = world.broadPhaseInUse();  // after the run: what the steps used
    const StepCounters& c = world.counters();
    r.simTime = world.time() - r.warmup;
    r.collisions = c.collisions;
    r.wallCollisions = c.wallCollisions;
    r.obstacles = world.obstacles().size();
    r.obstacleCollisions = c.obstacleCollisions;
    r.wallImpulse = c.wallImpulse;
    r.cutShort = c.cutShort;
    // What detection met during the run, and what the states at both ends hold (the exact
    // mode meets overlaps only at collisions, where rounding keeps them at a few ulps).
    r.maxOverlap = std::max({c.maxOverlap, overlapInitial, maxOverlap(world)});
    r.kineticEnergyFinal = kineticEnergy(world);
    r.potentialEnergyFinal = potentialEnergy(world);
    r.rotationalEnergyFinal = rotationalEnergy(world);
    r.angularMomentumFinal = angularMomentum(world);
    r.rotation = world.rotationInUse();
    r.momentumFinal = momentum(world);
    r.escaped = countEscaped(world);
    if (scene.bins) r.bins = measureBins(*scene.bins, world.particles());
    for (std::size_t k = 0; k < world.droppers().size(); ++k) {
        const Dropper& d = world.droppers()[k];
        r.droppers.push_back({d.released - scene.droppers[k].released, d.balls});
    }
    return r;
}

}  // namespace psb::cli
