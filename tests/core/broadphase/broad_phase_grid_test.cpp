#include <gtest/gtest.h>

#include <random>

#include "broad_phase_scenes.hpp"
#include "broadphase/broad_phase_all_pairs.hpp"
#include "broadphase/broad_phase_grid.hpp"

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
    std::vector<std::uint32_t> order(grid.order().begin(), grid.order().end());
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

/// What the move stage does with cellsForMove(): each particle's cell under the last plan.
bool writeCellsAsMoveDoes(GridBroadPhase& grid, const ParticleArrays& p) {
    const auto cells = grid.cellsForMove(p.size());
    if (!cells) return false;
    for (std::size_t i = 0; i < p.size(); ++i)
        cells->cellOf[i] = cells->map.cellOf(p.x[i], p.y[i]);
    return true;
}

std::vector<ContactPair> allPairs(const ParticleArrays& p) {
    std::vector<ContactPair> pairs;
    findPairsAllPairs(p, pairs);
    return pairs;
}

TEST(Grid, KeepsItsPlanWhileTheParticlesStayInsideItAndStillFindsEveryPair) {
    ParticleArrays p = test::makeLayout(test::Layout::Uniform, 4000, 11);
    GridBroadPhase grid;
    grid.build(p, statsOf(p), 1);
    const double cell = grid.cellSize();
    // A small drift, as in one step of a gas: some particles change cells, none leaves.
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> d(-0.3, 0.3);
    for (std::size_t i = 0; i < p.size(); ++i) {
        p.x[i] += d(rng);
        p.y[i] += d(rng);
    }
    ASSERT_TRUE(writeCellsAsMoveDoes(grid, p));
    grid.build(p, statsOf(p), 1, true);
    EXPECT_TRUE(grid.keptPlan());
    EXPECT_EQ(grid.cellSize(), cell);
    std::vector<ContactPair> pairs;
    grid.findPairs(p, 1, pairs);
    EXPECT_EQ(pairs, allPairs(p));
    EXPECT_GT(pairs.size(), 100u);
}

TEST(Grid, PlansAfreshWhenParticlesSpreadOutOrRadiiGrow) {
    ParticleArrays p = test::makeLayout(test::Layout::Uniform, 4000, 12);
    GridBroadPhase grid;
    grid.build(p, statsOf(p), 1);
    // Spread to three times the extent: the old grid would clamp most of them into its edges.
    for (std::size_t i = 0; i < p.size(); ++i) {
        p.x[i] *= 3.0;
        p.y[i] *= 3.0;
    }
    ASSERT_TRUE(writeCellsAsMoveDoes(grid, p));
    grid.build(p, statsOf(p), 1, true);
    EXPECT_FALSE(grid.keptPlan());
    std::vector<ContactPair> pairs;
    grid.findPairs(p, 1, pairs);
    EXPECT_EQ(pairs, allPairs(p));

    // Every radius past half the cell: the kept cells would miss pairs.
    const double cell = grid.cellSize();
    for (double& r : p.radius)
        r = 0.6 * cell;
    ASSERT_TRUE(writeCellsAsMoveDoes(grid, p));
    grid.build(p, statsOf(p), 1, true);
    EXPECT_FALSE(grid.keptPlan());
    EXPECT_GE(grid.cellSize(), 1.2 * cell);
    pairs.clear();
    grid.findPairs(p, 1, pairs);
    EXPECT_EQ(pairs, allPairs(p));
}

// Rows of a thousand particles, far longer than the query's bands: those slots are tested
// where the particles are, and every pair is still found.
TEST(Grid, AThinStripWithRowsLongerThanABandStillFindsEveryPair) {
    ParticleArrays p;
    std::mt19937_64 rng(14);
    std::uniform_real_distribution<double> ux(0.0, 1500.0), uy(0.0, 3.0);
    for (int k = 0; k < 3000; ++k)
        test::push(p, ux(rng), uy(rng), 0.5);
    GridBroadPhase grid;
    grid.build(p, statsOf(p), 1);
    // Cells under 1.5 m in a 3 m strip: at most three rows, so about a thousand slots a row.
    ASSERT_LT(grid.cellSize(), 1.5);
    std::vector<ContactPair> pairs;
    grid.findPairs(p, 1, pairs);
    EXPECT_EQ(pairs, allPairs(p));
    EXPECT_GT(pairs.size(), 500u);
}

TEST(Grid, OffersNoCellsToMoveWhenItsPlanSetLargeParticlesApart) {
    const ParticleArrays p = test::makeLayout(test::Layout::FewLarge, 3000, 13);
    GridBroadPhase grid;
    EXPECT_FALSE(grid.cellsForMove(p.size()).has_value()) << "no plan yet";
    grid.build(p, statsOf(p), 1);
    EXPECT_FALSE(grid.cellsForMove(p.size()).has_value());
}

}  // namespace
}  // namespace psb
