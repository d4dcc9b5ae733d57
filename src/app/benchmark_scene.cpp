#include "benchmark_scene.hpp"

#include <cmath>
#include <numbers>
#include <random>

namespace psb::app {

World benchmarkWorld(std::size_t count, std::uint32_t seed) {
    constexpr double kRadius = 2.0, kFraction = 0.2;
    const double side = std::sqrt(static_cast<double>(std::max<std::size_t>(count, 1)) *
                                  std::numbers::pi * kRadius * kRadius / kFraction);
    WorldDef def;
    def.width = side;
    def.height = side;
    SolverSettings solver;
    solver.dt = 1.0 / 120.0;
    World world(def, solver);
    const auto perRow = static_cast<std::size_t>(std::ceil(std::sqrt(static_cast<double>(count))));
    const double spacing = side / static_cast<double>(perRow);
    const double jitter = std::max(0.0, (spacing - 2.0 * kRadius) / 2.0 - 0.01);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> j(-jitter, jitter), v(-50.0, 50.0);
    std::uniform_int_distribution<int> ch(100, 255);
    for (std::size_t k = 0; k < count; ++k) {
        ParticleDef d;
        d.position = {(static_cast<double>(k % perRow) + 0.5) * spacing + j(rng),
                      (static_cast<double>(k / perRow) + 0.5) * spacing + j(rng)};
        d.velocity = {v(rng), v(rng)};
        d.mass = 1.0;
        d.radius = kRadius;
        d.color = {static_cast<std::uint8_t>(ch(rng)), static_cast<std::uint8_t>(ch(rng)),
                   static_cast<std::uint8_t>(ch(rng))};
        world.add(d);
    }
    return world;
}

}  // namespace psb::app
