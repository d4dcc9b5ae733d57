// Exact (event-driven) mode on a dilute 2-D gas: collisions resolved per second on one core, in
// frames as the app and the runner step it.
//
// The scene: 100 000 (and 10 000) discs of radius 1 m at packing fraction 0.1 in a square box with
// walls, restitution 1, velocity components normally distributed (σ = 1 m/s). Each iteration
// advances the world by 10 simulated seconds (about 10^5 collisions at 10^5 discs); the first
// steps after setup are excluded (they build the cell list and the queue, and let the initial
// lattice relax). Three ways to advance those 10 s:
//   BM_ExactFramesRunner  600 frames of 1/60 s, nothing read between them (particle-sim);
//   BM_ExactFramesApp     600 frames, every particle's position read after each (the app);
//   BM_ExactLongStep      one step of 10 s: the physics alone, what frames are compared with.
//
//   build/bench/exact_gas_bench --benchmark_repetitions=5
//
// Reports collisions/s (the figure; Google Benchmark rates are per CPU second of the
// benchmark thread, so other processes sharing the core do not count; the Time column is wall
// time), events per collision (collisions, wall hits, cell moves, stale predictions) and ns per
// collision.

#include <benchmark/benchmark.h>

#include <particle_sandbox/scene.hpp>
#include <particle_sandbox/scene_builders.hpp>
#include <particle_sandbox/world.hpp>

namespace {

psb::World diluteGas(int n, double packing, std::uint64_t seed) {
    psb::Scene s = psb::scenes::gas(
        {.count = static_cast<std::size_t>(n), .radius = 1.0, .packing = packing, .seed = seed});
    s.solver.mode = psb::StepMode::Exact;
    return psb::makeWorld(s);
}

void report(benchmark::State& state, const psb::World& w) {
    const auto& c = w.counters();
    const double collisions = static_cast<double>(c.collisions);
    state.counters["collisions/s"] = benchmark::Counter(collisions, benchmark::Counter::kIsRate);
    state.counters["events/collision"] = static_cast<double>(c.events) / collisions;
    state.counters["ns/collision"] = benchmark::Counter(
        collisions * 1e-9, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

constexpr double kSimulated = 10.0;  // simulated seconds per iteration
constexpr int kFrames = 600;         // frames of 1/60 s in kSimulated

// How the app and the runner step: one World::step per frame of 1/60 s. `Reader` is what
// happens between frames: nothing (the runner), or reading every particle (the app draws them).
template <typename Reader>
void runFrames(benchmark::State& state, Reader read) {
    const int n = static_cast<int>(state.range(0));
    psb::World w = diluteGas(n, 0.1, 42);
    w.step(20.0);  // build + relax: not timed
    w.resetCounters();
    for (auto _ : state) {
        for (int f = 0; f < kFrames; ++f) {
            w.step(kSimulated / kFrames);
            read(w);
        }
    }
    report(state, w);
}

// The runner: frames nobody reads until the end.
void BM_ExactFramesRunner(benchmark::State& state) {
    runFrames(state, [](const psb::World&) {});
}

// The app: every frame reads every particle's position, as drawing does.
void BM_ExactFramesApp(benchmark::State& state) {
    runFrames(state, [](const psb::World& w) {
        const psb::ParticleArrays& p = w.particles();
        double sum = 0.0;
        for (std::size_t i = 0; i < p.size(); ++i)
            sum += p.x[i] + p.y[i];
        benchmark::DoNotOptimize(sum);
    });
}

// The same simulated time as one long step: the physics alone, for comparison.
void BM_ExactLongStep(benchmark::State& state) {
    const int n = static_cast<int>(state.range(0));
    psb::World w = diluteGas(n, 0.1, 42);
    w.step(20.0);
    w.resetCounters();
    for (auto _ : state) {
        w.step(kSimulated);
    }
    report(state, w);
}

// Mixed sizes, per collision: 4000 discs of radius 1 m at packing 0.2, alone, with one disc of
// radius R (same areal density, so R² kg; state.range(0) = R, 0 for none), or with radii
// log-uniform from 1 to 10 m (range(0) = -10). One step of 20 s per iteration: the cost of the
// neighbour search per collision, apart from the cost of frames (measured above).
void BM_ExactMixedSizes(benchmark::State& state) {
    const auto r = static_cast<double>(state.range(0));
    psb::Scene scene;
    if (r > 0.0) {
        scene = psb::scenes::brownian({.count = 4000, .bigRadius = r, .bigMass = r * r, .seed = 3});
    } else {
        scene = psb::scenes::gas(
            {.count = 4000, .radius = 1.0, .maxRadius = -r, .packing = 0.2, .seed = 3});
    }
    scene.solver.mode = psb::StepMode::Exact;
    psb::World w = psb::makeWorld(scene);
    w.step(5.0);  // build + relax: not timed
    w.resetCounters();
    for (auto _ : state) {
        w.step(2.0 * kSimulated);
    }
    report(state, w);
}

BENCHMARK(BM_ExactMixedSizes)
    ->Arg(0)
    ->Arg(10)
    ->Arg(30)
    ->Arg(-10)
    ->Unit(benchmark::kMillisecond)
    ->MinTime(1.0);

BENCHMARK(BM_ExactFramesRunner)
    ->Arg(10000)
    ->Arg(100000)
    ->Unit(benchmark::kMillisecond)
    ->MinTime(2.0);
BENCHMARK(BM_ExactFramesApp)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK(BM_ExactLongStep)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond)->MinTime(2.0);

}  // namespace

BENCHMARK_MAIN();
