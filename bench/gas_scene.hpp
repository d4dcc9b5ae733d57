#pragma once
// The gas benchmark scene of the scale issue, shared by every benchmark: N discs of radius 1 m
// and mass 1 kg in a square box at packing fraction 0.1, velocity components drawn from
// N(0, 1) m/s, e = 1, no friction, no gravity, stepped with dt = 0.01 s.

#include <cstdint>
#include <vector>

#include <particle_sandbox/scene.hpp>
#include <particle_sandbox/scene_builders.hpp>
#include <particle_sandbox/world.hpp>

namespace psb::bench {

inline constexpr double kRadius = 1.0;
inline constexpr double kMass = 1.0;
inline constexpr double kPackingFraction = 0.1;
inline constexpr double kDt = 0.01;

struct GasState {
    double side = 0.0;
    std::vector<double> x, y, vx, vy;
};

/// The benchmark's gas as the core's scene builder makes it: positions uniform in the box
/// (overlaps allowed: the first steps separate them) and velocities N(0, 1) per component,
/// from a fixed seed.
inline Scene gasScene(std::size_t n, std::uint64_t seed = 42) {
    return scenes::gas({.count = n,
                        .radius = kRadius,
                        .packing = kPackingFraction,
                        .mass = kMass,
                        .temperature = 1.0,
                        .seed = seed,
                        .overlapping = true});
}

/// The same gas as plain arrays (for Box2D).
inline GasState makeGas(std::size_t n, std::uint64_t seed = 42) {
    const Scene s = gasScene(n, seed);
    GasState g;
    g.side = s.world.width;
    for (const ParticleDef& d : s.particles) {
        g.x.push_back(d.position.x());
        g.y.push_back(d.position.y());
        g.vx.push_back(d.velocity.x());
        g.vy.push_back(d.velocity.y());
    }
    return g;
}

inline World makeGasWorld(std::size_t n, BroadPhaseKind broadphase, int threads) {
    Scene s = gasScene(n);
    s.solver = {.mode = StepMode::Discrete, .broadphase = broadphase};
    World w(s.world, s.solver);
    w.setThreads(threads);
    w.reserve(n);
    for (const ParticleDef& d : s.particles)
        w.add(d);
    return w;
}

}  // namespace psb::bench
