// The exact mode under gravity: what gravity costs a dilute gas, and what a settled pile costs.
//
//   build/bench/exact_gravity_bench --benchmark_repetitions=3
//
// BM_DiluteGasPerCollision/N/G: psb::scenes::gas as exact_gas_bench uses it (N discs of radius 1 m
// at packing 0.1, velocity components normal with σ = 1 m/s, e = 1, walls) with G = 0 no gravity
// and G = 1 a weak gravity, g = σ² / (5 · box side): a scale height of five boxes. Reports ns per
// collision (per CPU second of the benchmark thread), the figure to compare between G = 0 and G
// = 1.
//
// BM_SettledPilePerFrame/N/M: N discs of radius 0.5 m, e = 0.5, μ = 0.3, under 9.81 m/s², at rest
// in a hexagonal pile on the floor; one iteration is one 1/60 s frame, M = 0 discrete, M = 2
// exact (the pile settled first: untimed).

#include <benchmark/benchmark.h>

#include <cmath>

#include <particle_sandbox/scene.hpp>
#include <particle_sandbox/scene_builders.hpp>
#include <particle_sandbox/world.hpp>

namespace {

void BM_DiluteGasPerCollision(benchmark::State& state) {
    const int n = static_cast<int>(state.range(0));
    psb::Scene s = psb::scenes::gas({.count = static_cast<std::size_t>(n), .packing = 0.1});
    s.solver.mode = psb::StepMode::Exact;
    if (state.range(1) != 0) s.world.gravity = {0.0, 1.0 / (5.0 * s.world.width)};
    psb::World w = psb::makeWorld(s);
    w.step(20.0);  // build + relax: not timed
    w.resetCounters();
    for (auto _ : state) {
        w.step(10.0);
    }
    const double collisions = static_cast<double>(w.counters().collisions);
    state.counters["ns/collision"] = benchmark::Counter(
        collisions * 1e-9, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
    state.counters["events/collision"] = static_cast<double>(w.counters().events) / collisions;
}
BENCHMARK(BM_DiluteGasPerCollision)
    ->Args({10000, 0})
    ->Args({10000, 1})
    ->Unit(benchmark::kMillisecond)
    ->MinTime(2.0);

psb::World settledPile(int n, psb::StepMode mode) {
    const double r = 0.5, rowPitch = std::sqrt(3.0) * r;
    const int perRow = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(n)) * 1.2));
    const int rows = (n + perRow - 1) / perRow;
    psb::WorldDef def;
    def.width = 2.0 * r * perRow + r;
    def.height = rows * rowPitch + 20.0;
    def.gravity = {0.0, 9.81};
    def.restitution = 0.5;
    def.friction = 0.3;
    psb::World w(def, {.mode = mode});
    for (int k = 0; k < n; ++k) {
        const int row = k / perRow, col = k % perRow;
        w.add(
            {.position = {r + (row % 2 ? r : 0.0) + 2.0 * r * col, def.height - r - row * rowPitch},
             .radius = r});
    }
    return w;
}

void BM_SettledPilePerFrame(benchmark::State& state) {
    const auto mode = static_cast<psb::StepMode>(state.range(1));
    psb::World w = settledPile(static_cast<int>(state.range(0)), mode);
    for (int k = 0; k < 120; ++k)  // settle: not timed
        w.step(1.0 / 60.0);
    w.resetCounters();
    for (auto _ : state) {
        w.step(1.0 / 60.0);
    }
    state.counters["events/frame"] =
        static_cast<double>(w.counters().events) / static_cast<double>(w.counters().steps);
}
BENCHMARK(BM_SettledPilePerFrame)
    ->Args({10000, static_cast<int>(psb::StepMode::Discrete)})
    ->Args({10000, static_cast<int>(psb::StepMode::Exact)})
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
