#include <gtest/gtest.h>

#include <particle_sandbox/world.hpp>

#include "broadphase/broad_phase_all_pairs.hpp"

namespace psb {
namespace {

TEST(AllPairs, FindsOverlapsInAscendingOrderAndIgnoresTouching) {
    World w;
    w.add({.position = {10.0, 10.0}, .radius = 1.0});  // 0
    w.add({.position = {12.0, 10.0}, .radius = 1.0});  // 1: touches 0 exactly
    w.add({.position = {11.0, 10.5}, .radius = 1.0});  // 2: overlaps 0 and 1
    w.add({.position = {50.0, 50.0}, .radius = 1.0});  // 3: alone
    std::vector<ContactPair> pairs;
    findPairsAllPairs(w.particles(), pairs);
    ASSERT_EQ(pairs.size(), 2u);
    EXPECT_EQ(pairs[0].i, 0u);
    EXPECT_EQ(pairs[0].j, 2u);
    EXPECT_EQ(pairs[1].i, 1u);
    EXPECT_EQ(pairs[1].j, 2u);
}

}  // namespace
}  // namespace psb
