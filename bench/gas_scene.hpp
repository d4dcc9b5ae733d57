#pragma once
// The gas benchmark scene of the scale issue, shared by every benchmark: N discs of radius 1 m
// and mass 1 kg in a square box at packing fraction 0.1, velocity components drawn from
// N(0, 1) m/s, e = 1, no friction, no gravity, stepped with dt = 0.01 s.

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include <particle_sandbox/world.hpp>

namespace psb::bench {

inline constexpr double kRadius = 1.0;
inline constexpr double kMass = 1.0;
inline constexpr double kPackingFraction = 0.1;
inline constexpr double kDt = 0.01;

/// Side of the square box holding n discs at the packing fraction, metres.
inline double gasBoxSide(std::size_t n) {
    return std::sqrt(static_cast<double>(n) * 3.141592653589793 * kRadius * kRadius /
                     kPackingFraction);
}

struct GasState {
    double side = 0.0;
    std::vector<double> x, y, vx, vy;
};

/// Positions uniform in the box (overlaps allowed: the first steps separate them) and
/// velocities N(0, 1) per component, from a fixed seed.
inline GasState makeGas(std::size_t n, std::uint64_t seed = 42) {
    GasState g;
    g.side = gasBoxSide(n);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> pos(kRadius, g.side - kRadius);
    std::normal_distribution<double> vel(0.0, 1.0);
    g.x.resize(n);
    g.y.resize(n);
    g.vx.resize(n);
    g.vy.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
        g.x[k] = pos(rng);
        g.y[k] = pos(rng);
        g.vx[k] = vel(rng);
        g.vy[k] = vel(rng);
    }
    return g;
}

inline World makeGasWorld(std::size_t n, BroadPhaseKind broadphase, int threads) {
    const GasState g = makeGas(n);
    WorldDef def;
    def.width = def.height = g.side;
    def.restitution = 1.0;
    def.friction = 0.0;
    def.gravity = Vec2::Zero();
    World w(def, {.mode = StepMode::Discrete, .dt = kDt, .broadphase = broadphase});
    w.setThreads(threads);
    w.reserve(n);
    for (std::size_t k = 0; k < n; ++k) {
        w.add({.position = {g.x[k], g.y[k]},
               .velocity = {g.vx[k], g.vy[k]},
               .mass = kMass,
               .radius = kRadius});
    }
    return w;
}

}  // namespace psb::bench
