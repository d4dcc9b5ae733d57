#pragma once
// The exact mode's dilute-gas benchmark scene, shared by exact_gas_bench and exact_gravity_bench:
// n discs of radius 1 m on a jittered lattice at the given packing fraction in a square box with
// walls, e = 1, velocity components normal with σ = 1 m/s, from a fixed seed.

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>

#include <particle_sandbox/world.hpp>

namespace psb::bench {

/// Side of the box, metres.
inline double exactGasSide(int n, double packing) {
    return std::sqrt(n * std::numbers::pi / packing);
}

/// The gas, with gravity (0, g) (0: none).
inline World exactDiluteGas(int n, double packing, std::uint32_t seed, double g = 0.0) {
    const double r = 1.0;
    const double side = exactGasSide(n, packing);
    WorldDef def;
    def.width = side;
    def.height = side;
    def.restitution = 1.0;
    def.gravity = {0.0, g};
    World w(def, {.mode = StepMode::Exact});
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::normal_distribution<double> speed(0.0, 1.0);
    const int perRow = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(n))));
    const double pitch = side / perRow, slack = pitch - 2.0 * r;
    for (int k = 0; k < n; ++k) {
        const double x = (k % perRow + 0.5) * pitch + (unit(rng) - 0.5) * slack;
        const double y = (k / perRow + 0.5) * pitch + (unit(rng) - 0.5) * slack;
        w.add({.position = {x, y}, .velocity = {speed(rng), speed(rng)}, .radius = r});
    }
    return w;
}

}  // namespace psb::bench
