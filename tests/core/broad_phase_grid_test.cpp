#include <gtest/gtest.h>

#include "broad_phase_grid.hpp"
#include "broad_phase_scenes.hpp"

namespace psb {
namespace {

ParticleStats statsOf(const ParticleArrays& p) {
    std::vector<ParticleStats> scratch;
    return measureParticles(p, 1, scratch);
}

TEST(Grid, CellsAreAtLeastTwiceTheSmallRadiusAndAtMostTwoPerParticle) {
    const ParticleArrays p = test::makeLayout(test::Layout::Uniform, 5000, 3);
    GridBroadPhase grid;
    grid.build(p, statsOf(p), 1);
    EXPECT_GE(grid.cellSize(), 2.0 * p.radius[0]);
    EXPECT_LE(grid.cellCount(), 2u * 5000u);
    EXPECT_EQ(grid.largeCount(), 0u);
}

TEST(Grid, AFewLargeDiscsAreKeptOutOfTheCellsSoCellsStaySmall) {
    const ParticleArrays p = test::makeLayout(test::Layout::FewLarge, 4000, 5);
    GridBroadPhase grid;
    grid.build(p, statsOf(p), 1);
    EXPECT_EQ(grid.largeCount(), 20u);  // every 200th particle
    const double small = p.radius[0];
    EXPECT_LT(grid.cellSize(), 4.0 * small) << "the cell size must follow the small discs";
}

TEST(Grid, OrderListsEveryParticleOnceSortedByCell) {
    const ParticleArrays p = test::makeLayout(test::Layout::FewLarge, 3000, 8);
    GridBroadPhase grid;
    grid.build(p, statsOf(p), 1);
    std::vector<std::uint32_t> order = grid.order();
    ASSERT_EQ(order.size(), p.size());
    std::sort(order.begin(), order.end());
    for (std::size_t k = 0; k < order.size(); ++k)
        ASSERT_EQ(order[k], k);
}

TEST(Grid, ParticlesFarOutsideTheRestAreStillFound) {
    ParticleArrays p = test::makeLayout(test::Layout::Uniform, 2000, 4);
    test::push(p, 1e7, 1e7, 1.0);
    test::push(p, 1e7 + 1.5, 1e7, 1.0);  // overlaps the previous one
    GridBroadPhase grid;
    grid.build(p, statsOf(p), 1);
    std::vector<ContactPair> pairs;
    grid.findPairs(p, 1, pairs);
    ASSERT_FALSE(pairs.empty());
    EXPECT_EQ(pairs.back(), (ContactPair{2000, 2001}));
}

}  // namespace
}  // namespace psb
