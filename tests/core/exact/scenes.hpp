#pragma once
// Scenes shared by the exact-mode tests.

#include <cmath>
#include <cstdint>
#include <random>

#include <particle_sandbox/world.hpp>

namespace psb::test {

/// A box of `n` discs at random, non-overlapping positions (jittered lattice), random masses
/// in [1, 5] kg, radii in [rMin, rMax], velocity components uniform in [-1, 1] m/s.
inline World exactGas(int n, double boxSide, double rMin, double rMax, double restitution,
                      std::uint32_t seed, bool walls = true) {
    WorldDef def;
    def.width = boxSide;
    def.height = boxSide;
    def.walls = walls;
    def.restitution = restitution;
    World w(def, {.mode = StepMode::Exact});
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const int perRow = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(n))));
    const double pitch = boxSide / perRow;
    const double slack = pitch - 2.0 * rMax;  // room to jitter without overlapping
    for (int k = 0; k < n; ++k) {
        const double cx = (k % perRow + 0.5) * pitch, cy = (k / perRow + 0.5) * pitch;
        const double jx = slack > 0 ? (unit(rng) - 0.5) * slack : 0.0;
        const double jy = slack > 0 ? (unit(rng) - 0.5) * slack : 0.0;
        w.add({.position = {cx + jx, cy + jy},
               .velocity = {2.0 * unit(rng) - 1.0, 2.0 * unit(rng) - 1.0},
               .mass = 1.0 + 4.0 * unit(rng),
               .radius = rMin + (rMax - rMin) * unit(rng)});
    }
    return w;
}

}  // namespace psb::test
