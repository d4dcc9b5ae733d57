#pragma once
// The `auto` broadphase rule.
//
//   fewer than kAllPairsBelow particles           → all-pairs (no build cost; n² is tiny)
//   more than 1 in kLargeFraction particles large  → quadtree (radii spread widely)
//   otherwise                                      → grid
//
// "Large" is the grid's own definition: radius above twice the mean radius. The grid keeps
// large particles out of its cells and tests them one by one, which is cheap for a few large
// discs among many small ones and expensive when many are large; the quadtree has no size
// limit at all (its node bounds cover the discs), so it takes the widely spread cases.
// The thresholds were set from the benchmarks in docs/performance.md.

#include <particle_sandbox/particle_arrays.hpp>
#include <particle_sandbox/solver_settings.hpp>

#include "particle_stats.hpp"

namespace psb {

inline constexpr std::size_t kAllPairsBelow = 64;
inline constexpr std::size_t kLargeFraction = 32;

/// Resolves `requested` for the particles `p` described by `stats`: returns it unchanged unless
/// it is Auto.
[[nodiscard]] BroadPhaseKind chooseBroadPhase(BroadPhaseKind requested, const ParticleArrays& p,
                                              const ParticleStats& stats);

}  // namespace psb
