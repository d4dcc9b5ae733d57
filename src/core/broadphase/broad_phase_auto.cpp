#include "broadphase/broad_phase_auto.hpp"

namespace psb {

BroadPhaseKind chooseBroadPhase(BroadPhaseKind requested, const ParticleArrays& p,
                                const ParticleStats& stats) {
    if (requested != BroadPhaseKind::Auto) return requested;
    const std::size_t n = p.size();
    if (n < kAllPairsBelow) return BroadPhaseKind::AllPairs;
    const double largeAbove = 2.0 * stats.meanRadius;
    if (stats.maxRadius <= largeAbove) return BroadPhaseKind::Grid;
    std::size_t large = 0;
    for (const double r : p.radius)
        large += r > largeAbove;
    if (large * large <= kLargePairsPerParticle * n) return BroadPhaseKind::Grid;
    return n < kAllPairsBelowForQuadtree ? BroadPhaseKind::AllPairs : BroadPhaseKind::Quadtree;
}

}  // namespace psb
