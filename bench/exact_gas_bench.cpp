// Exact (event-driven) mode on a dilute 2-D gas: collisions resolved per second on one core.
//
// The scene: 100 000 (and 10 000) discs of radius 1 m at packing fraction 0.1 in a square box with
// walls, restitution 1, velocity components normally distributed (σ = 1 m/s). Each iteration
// advances the world by 10 simulated seconds (about 10^5 collisions); the first steps after setup
// are excluded (they build the cell list and the queue, and let the initial lattice relax).
//
//   build/bench/exact_gas_bench --benchmark_repetitions=5
//
// Reports collisions/s (the figure; Google Benchmark rates are per CPU second of the
// benchmark thread, so other processes sharing the core do not count; the Time column is wall
// time), events per collision (collisions, wall hits, cell moves, stale predictions) and ns per
// collision.

#include <benchmark/benchmark.h>

#include <particle_sandbox/world.hpp>

#include "exact_gas_scene.hpp"

namespace {

void BM_ExactDiluteGas(benchmark::State& state) {
    const int n = static_cast<int>(state.range(0));
    psb::World w = psb::bench::exactDiluteGas(n, 0.1, 42);
    w.step(20.0);  // build + relax: not timed
    w.resetCounters();
    for (auto _ : state) {
        w.step(10.0);
    }
    const auto& c = w.counters();
    const double collisions = static_cast<double>(c.collisions);
    state.counters["collisions/s"] = benchmark::Counter(collisions, benchmark::Counter::kIsRate);
    state.counters["events/collision"] = static_cast<double>(c.events) / collisions;
    state.counters["ns/collision"] = benchmark::Counter(
        collisions * 1e-9, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_ExactDiluteGas)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond)->MinTime(2.0);

}  // namespace

BENCHMARK_MAIN();
