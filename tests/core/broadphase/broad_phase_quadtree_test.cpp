#include <gtest/gtest.h>

#include "broad_phase_scenes.hpp"
#include "broadphase/broad_phase_quadtree.hpp"

namespace psb {
namespace {

ParticleStats statsOf(const ParticleArrays& p) {
    std::vector<ParticleStats> scratch;
    return measureParticles(p, 1, scratch);
}

TEST(Quadtree, DepthStaysBoundedWhenManyCentresCoincide) {
    ParticleArrays p;
    for (int k = 0; k < 1000; ++k)
        test::push(p, 5.0, 5.0, 1.0);
    test::push(p, 100.0, 100.0, 1.0);
    QuadtreeBroadPhase tree;
    tree.build(p, statsOf(p), 1);
    EXPECT_LE(tree.depth(), QuadtreeBroadPhase::kMaxDepth);
    std::vector<ContactPair> pairs;
    tree.findPairs(p, 1, pairs);
    EXPECT_EQ(pairs.size(), 1000u * 999u / 2u);
}

TEST(Quadtree, LeavesHoldAFewParticlesSoTheTreeIsNotOneNode) {
    const ParticleArrays p = test::makeLayout(test::Layout::Uniform, 8000, 2);
    QuadtreeBroadPhase tree;
    tree.build(p, statsOf(p), 1);
    // At most kLeafSize per leaf means at least n / kLeafSize leaves.
    EXPECT_GE(tree.nodeCount(), 8000u / QuadtreeBroadPhase::kLeafSize);
    EXPECT_LE(tree.depth(), 12);
}

TEST(Quadtree, RebuildingForTheSameParticlesAllocatesNoNewNodes) {
    const ParticleArrays p = test::makeLayout(test::Layout::RadiiSpan1000, 5000, 6);
    QuadtreeBroadPhase tree;
    std::vector<ContactPair> pairs;
    tree.build(p, statsOf(p), 1);
    tree.findPairs(p, 1, pairs);
    const std::size_t bytes = tree.memoryBytes();
    for (int k = 0; k < 3; ++k) {
        pairs.clear();
        tree.build(p, statsOf(p), 1);
        tree.findPairs(p, 1, pairs);
    }
    EXPECT_EQ(tree.memoryBytes(), bytes);
}

}  // namespace
}  // namespace psb
