#include "default_scene.hpp"

#include <cmath>
#include <numbers>
#include <random>

namespace psb::app {

World defaultWorld() {
    SolverSettings solver;
    solver.dt = 1.0 / 120.0;
    World world(WorldDef{}, solver);
    // Masses and radii follow the original's spawn rule (radius = 2.5 m per kg); velocities
    // are in its range of ±300 m/s (±5 pixels per frame at 60 frames per second).
    const struct {
        double x, y, vx, vy, mass;
        Color color;
    } seeds[] = {
        {150, 150, 180, 60, 12, {255, 120, 120}},   {350, 200, -120, 150, 8, {120, 255, 140}},
        {550, 150, -60, -200, 16, {120, 160, 255}}, {200, 450, 240, -90, 6, {255, 220, 110}},
        {480, 480, -150, -30, 20, {230, 130, 255}}, {350, 600, 30, -240, 4, {120, 240, 240}},
    };
    for (const auto& s : seeds) {
        ParticleDef d;
        d.position = {s.x, s.y};
        d.velocity = {s.vx, s.vy};
        d.mass = s.mass;
        d.radius = 2.5 * s.mass;
        d.color = s.color;
        world.add(d);
    }
    return world;
}

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
