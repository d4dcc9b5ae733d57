#include "accuracy_sweep.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <limits>
#include <sstream>

#include <particle_sandbox/diagnostics.hpp>

#include "run_options.hpp"

namespace psb::cli {

std::vector<AccuracyScene> standardScenes(const std::filesystem::path& root) {
    const std::filesystem::path bench = root / "bench" / "scenes";
    const std::filesystem::path assets = root / "assets" / "scenes";
    return {
        {"dilute-gas", bench / "dilute-gas.json", 20.0},
        {"dense-gas", bench / "dense-gas.json", 4.0},
        {"newtons-cradle", assets / "02-newtons-cradle.json", 2.0},
        {"bullet-into-crowd", assets / "06-bullet-into-crowd.json", 0.4},
        {"bullet-through-row", bench / "bullet-through-row.json", 0.2},
        {"mass-ratio-pair", bench / "mass-ratio-pair.json", 20.0},
        {"inelastic-gas", bench / "inelastic-gas.json", 4.0},
        // Under gravity, with the exact mode as the reference.
        {"bouncing-ball", bench / "bouncing-ball.json", 4.0},
        {"projectile-into-falling-crowd", bench / "projectile-into-falling-crowd.json", 1.5},
        {"pile-under-gravity", assets / "07-pile-under-gravity.json", 4.0},
        // Rolling, with closed forms the exact mode follows to 1e-9 (tests/core/exact).
        {"rolling-slope", bench / "rolling-slope.json", 1.0},
        {"slip-to-roll", bench / "slip-to-roll.json", 2.0},
    };
}

SweepPlan fullPlan() {
    return {{4.0, 2.0, 1.0, 0.5, 0.25, 0.125, 0.0625}, {2, 4, 8, 16, 32}, 1.0, 3};
}

SweepPlan quickPlan() {
    return {{1.0, 0.5}, {2}, 0.05, 1};
}

namespace {

double smallestRadius(const ParticleArrays& p) {
    double r = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i)
        r = (i == 0) ? p.radius[i] : std::min(r, p.radius[i]);
    return r;
}

}  // namespace

RunTotals runMeasured(const Scene& scene, StepMode mode, double dt, int substeps, double duration,
                      bool checkMoves) {
    Scene s = scene;
    const bool exact = mode == StepMode::Exact;
    const int k = mode == StepMode::Substep ? substeps : 1;
    const double h = dt / k;
    s.solver.mode = exact ? StepMode::Exact : StepMode::Discrete;
    s.dt = h;
    s.solver.substeps = 1;
    World world = makeWorld(s);

    RunTotals r;
    r.particles = world.size();
    r.kineticEnergyInitial = kineticEnergy(world);
    r.wallLength = s.world.walls ? 2.0 * (s.world.width + s.world.height) : 0.0;
    const std::uint64_t frames = stepsFor(duration, dt);
    using Clock = std::chrono::steady_clock;
    Clock::duration spent{};
    const std::clock_t cpu0 = std::clock();
    for (std::uint64_t f = 0; f < frames; ++f) {
        for (int sub = 0; sub < k; ++sub) {
            if (!exact && checkMoves) {
                const MoveCheck c = checkMove(world.particles(), h, s.world.gravity);
                r.missed += c.missed;
                r.maxOverlapOverRadius = std::max(r.maxOverlapOverRadius, c.maxOverlapOverRadius);
            }
            const auto t0 = Clock::now();
            world.step(h);
            spent += Clock::now() - t0;
        }
    }
    r.wallSeconds = std::chrono::duration<double>(spent).count();
    // CPU time is read around the whole loop (a clock() call per step would cost more than a
    // step of a small scene), so it is only the step's cost when no checks ran in between.
    const bool checked = !exact && checkMoves;
    r.cpuSeconds = checked ? std::numeric_limits<double>::quiet_NaN()
                           : static_cast<double>(std::clock() - cpu0) / CLOCKS_PER_SEC;
    const StepCounters& c = world.counters();
    r.simTime = world.time();
    r.steps = exact ? frames : c.steps;
    r.collisions = c.collisions;
    r.wallCollisions = c.wallCollisions;
    r.wallImpulse = c.wallImpulse;
    r.kineticEnergyFinal = kineticEnergy(world);
    const ParticleArrays& p = world.particles();
    r.smallestRadius = smallestRadius(p);
    r.finalPositions.reserve(p.size());
    for (std::size_t i = 0; i < p.size(); ++i)
        r.finalPositions.emplace_back(p.x[i], p.y[i]);
    if (exact) {
        // The exact mode reports the deepest overlap it met at a collision (rounding only).
        const double rmin = smallestRadius(world.particles());
        r.maxOverlapOverRadius = rmin > 0.0 ? c.maxOverlap / rmin : 0.0;
    }
    return r;
}

std::vector<AccuracyRow> runSweep(const std::vector<AccuracyScene>& scenes, const SweepPlan& plan,
                                  const RowFn& onRow) {
    std::vector<AccuracyRow> rows;
    for (const AccuracyScene& as : scenes) {
        const Scene scene = loadScene(as.file);
        const double frame = scene.dt;
        const double duration = as.duration * plan.durationScale;
        auto measure = [&](StepMode mode, double dt, int k) {
            RunTotals t = runMeasured(scene, mode, dt, k, duration);
            // Runs of a millisecond are at the mercy of one preemption: repeat those until
            // 0.1 s has been timed (at most 50 runs), and keep the fastest.
            double timed = t.wallSeconds;
            for (int rep = 1; rep < plan.repeats || (plan.repeats > 1 && timed < 0.1 && rep < 50);
                 ++rep) {
                const RunTotals again = runMeasured(scene, mode, dt, k, duration, false);
                t.wallSeconds = std::min(t.wallSeconds, again.wallSeconds);
                t.cpuSeconds = std::isnan(t.cpuSeconds) ? again.cpuSeconds
                                                        : std::min(t.cpuSeconds, again.cpuSeconds);
                timed += again.wallSeconds;
            }
            return t;
        };
        auto add = [&](StepMode mode, double dt, int k, const RunTotals& exactTotals,
                       const RunTotals& totals) {
            AccuracyRow row{as.name, mode, dt, k, totals, compareToExact(totals, exactTotals)};
            if (onRow) onRow(row);
            rows.push_back(std::move(row));
        };
        const RunTotals exact = measure(StepMode::Exact, frame, 1);
        add(StepMode::Exact, frame, 1, exact, exact);
        for (double f : plan.dtFactors) {
            add(StepMode::Discrete, frame * f, 1, exact, measure(StepMode::Discrete, frame * f, 1));
        }
        for (int k : plan.substeps) {
            add(StepMode::Substep, frame, k, exact, measure(StepMode::Substep, frame, k));
        }
    }
    return rows;
}

namespace {

std::string num(double v, const char* nanText) {
    if (std::isnan(v)) return nanText;
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3g", v);
    return buf;
}

std::string full(double v) {
    if (std::isnan(v)) return "";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

}  // namespace

std::string accuracyCsv(const std::vector<AccuracyRow>& rows) {
    std::ostringstream o;
    o << "scene,mode,dt_s,substeps,particles,steps,sim_s,wall_s,wall_s_per_sim_s,cpu_s_per_sim_s,"
         "ns_per_particle_step,collisions,wall_collisions,collisions_vs_exact,missed,max_overlap_"
         "over_r,"
         "ke_error,wall_pressure_n_per_m,pressure_vs_exact,position_error_over_r\n";
    for (const AccuracyRow& r : rows) {
        const RunTotals& t = r.totals;
        const ErrorMeasures& e = r.errors;
        o << r.scene << ',' << toString(r.mode) << ',' << full(r.dt) << ',' << r.substeps << ','
          << t.particles << ',' << t.steps << ',' << full(t.simTime) << ',' << full(t.wallSeconds)
          << ',' << full(e.wallSecondsPerSimSecond) << ',' << full(e.cpuSecondsPerSimSecond) << ','
          << full(e.nsPerParticleStep) << ',' << t.collisions << ',' << t.wallCollisions << ','
          << full(e.collisionRatio) << ',' << e.missed << ',' << full(e.maxOverlapOverRadius) << ','
          << full(e.kineticEnergyError) << ',' << full(wallPressure(t)) << ','
          << full(e.pressureRatio) << ',' << full(e.positionErrorOverRadius) << '\n';
    }
    return o.str();
}

std::string accuracyMarkdown(const std::vector<AccuracyRow>& rows) {
    std::ostringstream o;
    o << "| scene | mode | dt (ms) | k | wall s / sim s | CPU s / sim s | ns / particle-step | "
         "collisions / exact"
         " | missed | max overlap / r | KE error | pressure / exact | position error / r |\n"
         "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const AccuracyRow& r : rows) {
        const ErrorMeasures& e = r.errors;
        o << "| " << r.scene << " | " << toString(r.mode) << " | " << num(r.dt * 1e3, "—") << " | "
          << r.substeps << " | " << num(e.wallSecondsPerSimSecond, "—") << " | "
          << num(e.cpuSecondsPerSimSecond, "—") << " | " << num(e.nsPerParticleStep, "—") << " | "
          << num(e.collisionRatio, "—") << " | " << e.missed << " | "
          << num(e.maxOverlapOverRadius, "—") << " | " << num(e.kineticEnergyError, "—") << " | "
          << num(e.pressureRatio, "—") << " | " << num(e.positionErrorOverRadius, "—") << " |\n";
    }
    return o.str();
}

}  // namespace psb::cli
