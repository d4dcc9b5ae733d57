#include <gtest/gtest.h>

#include "broad_phase_scenes.hpp"
#include "broadphase/broad_phase_auto.hpp"

namespace psb {
namespace {

BroadPhaseKind autoFor(const ParticleArrays& p) {
    std::vector<ParticleStats> scratch;
    return chooseBroadPhase(BroadPhaseKind::Auto, p, measureParticles(p, 1, scratch));
}

TEST(AutoBroadPhase, FewParticlesUseAllPairs) {
    EXPECT_EQ(autoFor(test::makeLayout(test::Layout::Uniform, kAllPairsBelow - 1, 1)),
              BroadPhaseKind::AllPairs);
}

TEST(AutoBroadPhase, ManyEqualDiscsUseTheGrid) {
    EXPECT_EQ(autoFor(test::makeLayout(test::Layout::Uniform, 5000, 1)), BroadPhaseKind::Grid);
}

TEST(AutoBroadPhase, AFewLargeDiscsAmongManySmallStillUseTheGrid) {
    EXPECT_EQ(autoFor(test::makeLayout(test::Layout::FewLarge, 5000, 1)), BroadPhaseKind::Grid);
}

TEST(AutoBroadPhase, RadiiSpreadOverDecadesUseTheQuadtree) {
    EXPECT_EQ(autoFor(test::makeLayout(test::Layout::RadiiSpan1000, 5000, 1)),
              BroadPhaseKind::Quadtree);
}

/// n particles of which `large` have radius 1 m and the rest 1 cm, on a line.
ParticleArrays bimodal(std::size_t n, std::size_t large) {
    ParticleArrays p;
    for (std::size_t k = 0; k < n; ++k)
        test::push(p, 3.0 * k, 0.0, k < large ? 1.0 : 0.01);
    return p;
}

TEST(AutoBroadPhase, ManyLargeDiscsUseTheQuadtreeButAFewOnlyTheGrid) {
    // 45 % large: L² = 2025 n >> 16 n.
    EXPECT_EQ(autoFor(bimodal(10000, 4500)), BroadPhaseKind::Quadtree);
    // L² = 160000 = 16 n: still the grid.
    EXPECT_EQ(autoFor(bimodal(10000, 400)), BroadPhaseKind::Grid);
}

TEST(AutoBroadPhase, FewParticlesWithSpreadRadiiUseAllPairs) {
    EXPECT_EQ(autoFor(bimodal(100, 45)), BroadPhaseKind::AllPairs);
}

TEST(AutoBroadPhase, AnExplicitChoiceIsKept) {
    const ParticleArrays p = test::makeLayout(test::Layout::Uniform, 10, 1);
    std::vector<ParticleStats> scratch;
    EXPECT_EQ(chooseBroadPhase(BroadPhaseKind::Quadtree, p, measureParticles(p, 1, scratch)),
              BroadPhaseKind::Quadtree);
}

}  // namespace
}  // namespace psb
