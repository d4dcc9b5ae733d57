// The gas benchmark: particle-steps per second of the discrete step, per broadphase, thread
// count and N, with memory per particle; and the cost of features a scene does not use.
//
// Names: gas/<broadphase>/threads:<t>/n:<N>, spread/<broadphase>/span:1000/n:<N> and
// feature/<feature>:<off|on>/n:<N>. Counters:
// items_per_second = particle-steps per second; bytes_per_particle = World::memoryBytes() / N
// (particle arrays, id table and step scratch, by capacity); <stage>_us = mean microseconds per
// step spent in that stage.

#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "gas_scene.hpp"
#include "run_benchmarks.hpp"

namespace psb::bench {
namespace {

/// Steps run before timing: the first reorders storage and sizes every scratch buffer. Any
/// kReorderInterval consecutive steps after it include exactly one more reorder.
constexpr int kWarmup = 3;

void reportProfile(benchmark::State& state, const StepProfile& sum, const World& w, std::size_t n) {
    const double steps = static_cast<double>(state.iterations());
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(n));
    state.counters["bytes_per_particle"] =
        static_cast<double>(w.memoryBytes()) / static_cast<double>(n);
    state.counters["find_pairs_us"] = 1e3 * sum.ms("find pairs") / steps;
    state.counters["resolve_separate_us"] = 1e3 * (sum.ms("resolve") + sum.ms("separate")) / steps;
    state.counters["move_us"] = 1e3 * sum.ms("move") / steps;
    state.counters["gravity_us"] = 1e3 * sum.ms("gravity") / steps;
    state.counters["walls_us"] = 1e3 * sum.ms("walls") / steps;
    state.counters["reorder_us"] = 1e3 * sum.ms("reorder") / steps;
    state.SetLabel(std::string(toString(w.broadPhaseInUse())));
}

void accumulate(StepProfile& sum, const StepProfile& p) {
    for (int k = 0; k < p.stageCount; ++k)
        sum.stage(p.stages[k].name) += p.stages[k].ms;
    sum.total += p.total;
}

/// Warms `w` up, then times one step of kDt per benchmark iteration and reports the profile.
void timeSteps(benchmark::State& state, World& w, std::size_t n) {
    for (int k = 0; k < kWarmup; ++k)
        w.step(kDt);
    StepProfile sum;
    for (auto _ : state) {
        w.step(kDt);
        accumulate(sum, w.profile());
    }
    reportProfile(state, sum, w, n);
}

void gas(benchmark::State& state, BroadPhaseKind kind, int threads, std::size_t n) {
    World w = makeGasWorld(n, kind, threads);
    timeSteps(state, w, n);
}

enum class Feature { Gravity, Friction, Walls, Rotation };

/// The gas with one feature off or on. "On" uses a value too small to change the motion
/// (gravity 1e-9 m/s², friction 1e-9) so that the scene, and so the broadphase work, is the
/// same; only the stage (or the friction code path) differs. Walls are on in the gas scene, so
/// "walls:off" removes them. Friction turns discs, so "friction:on" runs the rough contacts;
/// "rotation" compares them (friction 1e-9) for discs that turn ("on") and discs with fixed
/// rotation ("off"), the same code with no spin to give.
void feature(benchmark::State& state, Feature f, bool on, std::size_t n) {
    World w = makeGasWorld(n, BroadPhaseKind::Auto, 1);
    switch (f) {
        case Feature::Gravity:
            if (on) w.setGravity(Vec2(0.0, 1e-9));
            break;
        case Feature::Friction:
            if (on) w.setFriction(1e-9);
            break;
        case Feature::Walls:
            w.setWalls(on);
            break;
        case Feature::Rotation:
            w.setFriction(1e-9);
            if (!on) {
                for (const ParticleId id : w.ids())
                    w.setFixedRotation(id, true);
            }
            break;
    }
    timeSteps(state, w, n);
}

/// Radii log-uniform over `span` (largest 10 m), packing fraction 0.1, otherwise the gas: the
/// scene that decides between grid and quadtree in `auto`.
void spread(benchmark::State& state, BroadPhaseKind kind, double span, std::size_t n) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::normal_distribution<double> vel(0.0, 1.0);
    std::vector<double> radius(n);
    double area = 0.0;
    for (double& r : radius) {
        r = 10.0 * std::pow(span, u(rng)) / span;
        area += 3.141592653589793 * r * r;
    }
    WorldDef def;
    def.width = def.height = std::sqrt(area / kPackingFraction);
    World w(def, {.broadphase = kind});
    w.setThreads(1);
    w.reserve(n);
    for (const double r : radius) {
        w.add({.position = {r + (def.width - 2 * r) * u(rng), r + (def.height - 2 * r) * u(rng)},
               .velocity = {vel(rng), vel(rng)},
               .mass = r * r,
               .radius = r});
    }
    timeSteps(state, w, n);
}

void registerAll() {
    const std::size_t sizes[] = {1000, 3000, 10000, 30000, 100000, 300000, 1000000};
    for (const BroadPhaseKind kind :
         {BroadPhaseKind::Grid, BroadPhaseKind::Quadtree, BroadPhaseKind::AllPairs}) {
        for (const int threads : {1, 2}) {
            for (const std::size_t n : sizes) {
                if (kind == BroadPhaseKind::AllPairs && n > 3000) continue;
                if (kind == BroadPhaseKind::Quadtree && n > 300000) continue;
                const std::string name = "gas/" + std::string(toString(kind)) +
                                         "/threads:" + std::to_string(threads) +
                                         "/n:" + std::to_string(n);
                auto* b = benchmark::RegisterBenchmark(name.c_str(), gas, kind, threads, n);
                b->UseRealTime()->Unit(benchmark::kMillisecond);
                // Worlds this large reorder their storage every kReorderInterval steps; time a
                // whole number of intervals so that the reorder's cost is counted at its rate.
                if (n >= kReorderMinParticles) b->Iterations(kReorderInterval);
            }
        }
    }
    for (const BroadPhaseKind kind :
         {BroadPhaseKind::Grid, BroadPhaseKind::Quadtree, BroadPhaseKind::Auto}) {
        for (const std::size_t n : {10000, 100000}) {
            const std::string name =
                "spread/" + std::string(toString(kind)) + "/span:1000/n:" + std::to_string(n);
            // The grid is slow here by design (that is the point); a few steps suffice.
            benchmark::RegisterBenchmark(name.c_str(), spread, kind, 1000.0, n)
                ->UseRealTime()
                ->Unit(benchmark::kMillisecond)
                ->Iterations(4);
        }
    }
    const std::pair<Feature, const char*> features[] = {{Feature::Gravity, "gravity"},
                                                        {Feature::Friction, "friction"},
                                                        {Feature::Walls, "walls"},
                                                        {Feature::Rotation, "rotation"}};
    for (const auto& [f, fname] : features) {
        for (const bool on : {false, true}) {
            const std::size_t n = 100000;
            const std::string name =
                "feature/" + std::string(fname) + (on ? ":on" : ":off") + "/n:" + std::to_string(n);
            benchmark::RegisterBenchmark(name.c_str(), feature, f, on, n)
                ->UseRealTime()
                ->Unit(benchmark::kMillisecond)
                ->Iterations(2 * kReorderInterval);
        }
    }
}

}  // namespace
}  // namespace psb::bench

int main(int argc, char** argv) {
    psb::bench::registerAll();
    return psb::bench::runBenchmarks(argc, argv);
}
