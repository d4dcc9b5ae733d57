#pragma once
// Bounds and radius statistics of the particles, measured once per step and shared by the
// broadphase choice and the grid's plan.

#include <cstddef>
#include <vector>

#include <particle_sandbox/particle_arrays.hpp>

namespace psb {

struct ParticleStats {
    std::size_t count = 0;
    double minX = 0.0, minY = 0.0, maxX = 0.0, maxY = 0.0;  ///< bounds of the centres, metres
    double meanRadius = 0.0;                                ///< metres
    double minRadius = 0.0;                                 ///< metres
    double maxRadius = 0.0;                                 ///< metres
    double maxAbsCoordinate = 0.0;  ///< largest |coordinate| of a centre, metres (for rounding)
};

/// Measures `p` with up to `threads` threads. `blockScratch` holds per-block partial results
/// between calls (so that measuring allocates nothing in steady state). The result does not
/// depend on `threads`.
[[nodiscard]] ParticleStats measureParticles(const ParticleArrays& p, int threads,
                                             std::vector<ParticleStats>& blockScratch);

/// The partial result of particles [begin, end) (end > begin), for combineBlocks.
void measureBlock(const ParticleArrays& p, std::size_t begin, std::size_t end, ParticleStats& out);
/// Combines the per-block results of parallel::forBlocks over n particles, in block order.
[[nodiscard]] ParticleStats combineBlocks(const std::vector<ParticleStats>& blocks, std::size_t n);

}  // namespace psb
