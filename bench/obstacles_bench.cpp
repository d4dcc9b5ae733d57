// The cost of fixed obstacles in the discrete step: the gas benchmark scene (gas_scene.hpp) with
// and without 10^3 obstacles, per particle-step.
//
// Names: obstacles/<count>/n:<N>. The obstacles are half pegs of radius 1 m and half segments
// 6 m long and 0.4 m thick, at random in the box (from a fixed seed): about 1 % of the box's
// area, so that particles meet an obstacle about as often as a wall. The gas starts without
// obstacles overlapping it excluded: the first steps push overlapping particles out, and the
// warm-up steps are not timed. Counters: items_per_second = particle-steps per second;
// obstacles_us = mean microseconds per step in the obstacles stage; obstacle_hits_per_step.
//
//   build/release/bench/obstacles_bench --benchmark_repetitions=5
//       --benchmark_enable_random_interleaving=true          (one command line)
//
// The bound: obstacles/1000/n:10000 at most 1.5 times the time per particle-step of
// obstacles/0/n:10000.
//
// Frames: obstacles_frames/<count>/n:<N>/<mode>, the same scenes stepped as the app and
// particle-sim step them: each iteration is 60 frames of 1/60 s, one World::step(1/60) each
// (in `substep` mode 4 substeps per frame), storage reorders included; warm-up not timed.
// items_per_second = particle-frames per second (CPU time).
//
// The exact mode: obstacles_exact/<count>/n:<N>, a dilute gas (packing 0.1, radius 1 m, e = 1,
// no overlaps, as exact_gas_bench) with the same obstacles, particles that would overlap one
// left out of both variants (so both have the same particles). Each iteration runs 60 frames of
// 1/60 s, nothing read between them (as particle-sim steps); warm-up not timed. Counters:
// ns_per_collision = CPU time per collision of any kind (pair, wall or obstacle: each is one
// velocity change resolved), events_per_collision, obstacle_share (obstacle collisions / all).
// The bound: obstacles_exact/1000/n:10000 at most 1.5 times the ns_per_collision of
// obstacles_exact/0/n:10000.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <random>
#include <string>

#include <particle_sandbox/scene_builders.hpp>

#include "gas_scene.hpp"
#include "run_benchmarks.hpp"

namespace psb::bench {
namespace {

Obstacles randomObstacles(std::size_t count, double side, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> pos(10.0, side - 10.0), angle(0.0, 6.283185307179586);
    Obstacles out;
    for (std::size_t k = 0; k < count; ++k) {
        const Vec2 a(pos(rng), pos(rng));
        if (k % 2 == 0) {
            out.push_back(Obstacle::peg(a, 1.0));
        } else {
            const double t = angle(rng);
            out.push_back(Obstacle::segment(a, a + 6.0 * Vec2(std::cos(t), std::sin(t)), 0.4));
        }
    }
    return out;
}

void obstacles(benchmark::State& state, std::size_t count, std::size_t n) {
    World w = makeGasWorld(n, BroadPhaseKind::Auto, 1);
    w.setObstacles(randomObstacles(count, w.def().width, 11));
    for (int k = 0; k < 20; ++k)
        w.step(kDt);
    w.resetCounters();
    double stageMs = 0.0;
    for (auto _ : state) {
        w.step(kDt);
        stageMs += w.profile().ms("obstacles");
    }
    const double steps = static_cast<double>(state.iterations());
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(n));
    state.counters["obstacles_us"] = 1e3 * stageMs / steps;
    state.counters["obstacle_hits_per_step"] =
        static_cast<double>(w.counters().obstacleCollisions) / steps;
}

void obstacleFrames(benchmark::State& state, std::size_t count, std::size_t n, StepMode mode) {
    World w = makeGasWorld(n, BroadPhaseKind::Auto, 1);
    const double frame = 1.0 / 60.0;
    w.setSolver({.mode = mode, .substeps = mode == StepMode::Substep ? 4 : 1});
    w.setObstacles(randomObstacles(count, w.def().width, 11));
    for (int f = 0; f < 60; ++f)
        w.step(frame);
    w.resetCounters();
    for (auto _ : state) {
        for (int f = 0; f < 60; ++f)
            w.step(frame);
    }
    const double frames = 60.0 * static_cast<double>(state.iterations());
    state.SetItemsProcessed(state.iterations() * 60 * static_cast<std::int64_t>(n));
    state.counters["obstacle_hits_per_frame"] =
        static_cast<double>(w.counters().obstacleCollisions) / frames;
}

/// Distance from (x, y) to the obstacle's surface (negative inside).
double surfaceDistance(const Obstacle& o, const Vec2& p) {
    const Vec2 e = o.b - o.a;
    const double len2 = e.squaredNorm();
    const double t = len2 > 0.0 ? std::clamp((p - o.a).dot(e) / len2, 0.0, 1.0) : 0.0;
    return (p - (o.a + t * e)).norm() - o.radius;
}

void obstaclesExact(benchmark::State& state, std::size_t count, std::size_t n) {
    Scene s = scenes::gas({.count = n, .radius = 1.0, .packing = 0.1, .seed = 42});
    s.solver.mode = StepMode::Exact;
    const Obstacles all = randomObstacles(1000, s.world.width, 11);
    std::erase_if(s.particles, [&](const ParticleDef& p) {
        for (const Obstacle& o : all)
            if (surfaceDistance(o, p.position) <= p.radius) return true;
        return false;
    });
    World w = makeWorld(s);
    w.setObstacles(Obstacles(all.begin(), all.begin() + static_cast<std::ptrdiff_t>(count)));
    w.step(5.0);  // build + relax: not timed
    w.resetCounters();
    for (auto _ : state) {
        for (int f = 0; f < 60; ++f)
            w.step(1.0 / 60.0);
    }
    const StepCounters& c = w.counters();
    const double collisions =
        static_cast<double>(c.collisions + c.wallCollisions + c.obstacleCollisions);
    state.counters["ns_per_collision"] = benchmark::Counter(
        collisions * 1e-9, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
    state.counters["events_per_collision"] = static_cast<double>(c.events) / collisions;
    state.counters["obstacle_share"] = static_cast<double>(c.obstacleCollisions) / collisions;
}

void registerAll() {
    for (const std::size_t n : {10000, 100000}) {
        for (const std::size_t count : {0, 1000}) {
            const std::string name =
                "obstacles/" + std::to_string(count) + "/n:" + std::to_string(n);
            benchmark::RegisterBenchmark(name.c_str(), obstacles, count, n)
                ->UseRealTime()
                ->Unit(benchmark::kMillisecond);
        }
    }
    for (const StepMode mode : {StepMode::Discrete, StepMode::Substep}) {
        for (const std::size_t count : {0, 1000}) {
            const std::string name = "obstacles_frames/" + std::to_string(count) + "/n:10000/" +
                                     (mode == StepMode::Discrete ? "discrete" : "substep");
            benchmark::RegisterBenchmark(name.c_str(), obstacleFrames, count, std::size_t{10000},
                                         mode)
                ->Unit(benchmark::kMillisecond);
        }
    }
    for (const std::size_t count : {0, 1000}) {
        const std::string name = "obstacles_exact/" + std::to_string(count) + "/n:10000";
        benchmark::RegisterBenchmark(name.c_str(), obstaclesExact, count, std::size_t{10000})
            ->Unit(benchmark::kMillisecond);
    }
}

}  // namespace
}  // namespace psb::bench

int main(int argc, char** argv) {
    psb::bench::registerAll();
    return psb::bench::runBenchmarks(argc, argv);
}
