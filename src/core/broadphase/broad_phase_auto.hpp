#pragma once
// The `auto` broadphase rule, from the particle count and the spread of radii.
//
//   n < kAllPairsBelow                        → all-pairs (no build cost; n² is still tiny)
//   L² > kLargePairsPerParticle · n, where L  → quadtree  (or all-pairs below
//   is the number of "large" particles                     kAllPairsBelowForQuadtree)
//   otherwise                                 → grid
//
// "Large" is the grid's own definition: radius above twice the mean radius. The grid keeps
// large particles out of its cells and tests them against each other directly, about L²/2
// tests per step, which is nothing for a few large discs among many small ones and dominates
// when radii spread widely. The quadtree has no size limit (its node bounds cover the discs).
// Thresholds from measurements on the development machine (docs/performance.md): the grid
// beats all-pairs from about 32 particles and is about 4× faster than the quadtree on a gas of
// equal discs; with radii log-uniform over 1000× at packing fraction 0.1 (bench `spread/...`)
// the quadtree step is 2× faster than the grid's at 10^4 particles and 20× at 10^5.

#include <particle_sandbox/particle_arrays.hpp>
#include <particle_sandbox/solver_settings.hpp>

#include "broadphase/particle_stats.hpp"

namespace psb {

inline constexpr std::size_t kAllPairsBelow = 32;
inline constexpr std::size_t kAllPairsBelowForQuadtree = 128;
inline constexpr std::size_t kLargePairsPerParticle = 16;

/// Resolves `requested` for the particles `p` described by `stats`: returns it unchanged unless
/// it is Auto.
[[nodiscard]] BroadPhaseKind chooseBroadPhase(BroadPhaseKind requested, const ParticleArrays& p,
                                              const ParticleStats& stats);

}  // namespace psb
