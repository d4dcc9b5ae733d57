#include <gtest/gtest.h>

#include "broad_phase_auto.hpp"
#include "broad_phase_scenes.hpp"

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

TEST(AutoBroadPhase, AnExplicitChoiceIsKept) {
    const ParticleArrays p = test::makeLayout(test::Layout::Uniform, 10, 1);
    std::vector<ParticleStats> scratch;
    EXPECT_EQ(chooseBroadPhase(BroadPhaseKind::Quadtree, p, measureParticles(p, 1, scratch)),
              BroadPhaseKind::Quadtree);
}

}  // namespace
}  // namespace psb
