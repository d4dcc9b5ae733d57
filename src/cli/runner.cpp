#include "runner.hpp"

#include <chrono>

#include <particle_sandbox/diagnostics.hpp>
#include <particle_sandbox/error.hpp>

namespace psb::cli {
namespace {}  // namespace

SolverSettings effectiveSolver(const Scene& scene, const RunOptions& o) {
    SolverSettings s = scene.solver;
    if (o.mode) s.mode = *o.mode;
    if (o.dt) s.dt = *o.dt;
    if (o.substeps) s.substeps = *o.substeps;
    if (o.broadphase) s.broadphase = *o.broadphase;
    auto refused = [&](const SolverSettings& probe) -> std::optional<std::string> {
        try {
            World w(scene.world, probe);
        } catch (const InvalidArgument& e) {
            return std::string(e.what());
        }
        return std::nullopt;
    };
    SolverSettings mode{};
    mode.mode = s.mode;
    if (auto why = refused(mode)) {
        throw UsageError("--mode " + std::string(toString(s.mode)) + ": refused (" + *why + ")");
    }
    SolverSettings broad{};
    broad.broadphase = s.broadphase;
    if (auto why = refused(broad)) {
        throw UsageError("--broadphase " + std::string(toString(s.broadphase)) + ": refused (" +
                         *why + ")");
    }
    if (auto why = refused(s)) throw UsageError("solver settings refused (" + *why + ")");
    return s;
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

RunReport runScene(const Scene& scene, const RunOptions& options, World& world,
                   const ProgressFn& progress) {
    Scene s = scene;
    s.solver = effectiveSolver(scene, options);
    world = makeWorld(s);
    world.setThreads(options.threads);

    RunReport r;
    r.solver = s.solver;
    r.threads = options.threads;
    r.particles = world.size();
    r.steps = stepsFor(options.duration, s.solver.dt);
    r.kineticEnergyInitial = kineticEnergy(world);
    r.momentumInitial = momentum(world);

    const auto start = std::chrono::steady_clock::now();
    for (std::uint64_t k = 0; k < r.steps; ++k) {
        world.step(s.solver.dt);
        if (progress) progress(k + 1, r.steps);
    }
    r.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    r.broadphaseUsed = world.broadPhaseInUse();  // after the run: what the steps used
    const StepCounters& c = world.counters();
    r.simTime = world.time();
    r.collisions = c.collisions;
    r.wallCollisions = c.wallCollisions;
    r.wallImpulse = c.wallImpulse;
    r.maxOverlap = c.maxOverlap;
    r.kineticEnergyFinal = kineticEnergy(world);
    r.momentumFinal = momentum(world);
    r.escaped = countEscaped(world);
    return r;
}

}  // namespace psb::cli
