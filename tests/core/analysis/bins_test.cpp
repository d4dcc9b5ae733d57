// Counting particles in bins, the binomial's expected counts, and the χ² test.

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

#include <particle_sandbox/bins.hpp>
#include <particle_sandbox/chi_square.hpp>
#include <particle_sandbox/error.hpp>

namespace psb {
namespace {

ParticleArrays at(std::initializer_list<std::pair<double, double>> xy) {
    ParticleArrays p;
    for (const auto& [x, y] : xy) {
        p.x.push_back(x);
        p.y.push_back(y);
    }
    return p;
}

TEST(Bins, CountParticlesBelowTheTopByTheSpanOfTheirCentre) {
    const Bins b{.edges = {0.0, 1.0, 2.0, 4.0}, .top = 5.0, .binomial = {}};
    const ParticleArrays p = at({{0.5, 6.0},    // bin 0
                                 {1.0, 6.0},    // on an edge: the bin to its right
                                 {3.9, 9.0},    // bin 2
                                 {4.0, 6.0},    // the last edge: outside
                                 {-0.1, 6.0},   // outside, left
                                 {0.5, 5.0},    // on the top line: not yet in
                                 {0.5, 1.0},    // above
                                 {NAN, 6.0},    // outside
                                 {0.5, NAN}});  // above
    const BinCounts c = countBins(b, p);
    EXPECT_EQ(c.counts, (std::vector<std::size_t>{1, 1, 1}));
    EXPECT_EQ(c.counted(), 3u);
    EXPECT_EQ(c.outside, 3u);
    EXPECT_EQ(c.above, 3u);
}

TEST(Bins, BinomialProbabilitiesArePascalsTriangleOverTwoToTheN) {
    const std::vector<double> p = binomialProbabilities({.trials = 4, .p = 0.5});
    ASSERT_EQ(p.size(), 5u);
    const double want[] = {1, 4, 6, 4, 1};
    for (int k = 0; k < 5; ++k)
        EXPECT_NEAR(p[k], want[k] / 16.0, 1e-15);
    const std::vector<double> q = binomialProbabilities({.trials = 3, .p = 0.2});
    EXPECT_NEAR(q[0], 0.512, 1e-15);
    EXPECT_NEAR(q[3], 0.008, 1e-15);
    EXPECT_EQ(binomialProbabilities({.trials = 2, .p = 1.0}), (std::vector<double>{0, 0, 1}));
}

TEST(Bins, ExpectedCountsScaleWithTheParticlesCounted) {
    Bins b{.edges = {0, 1, 2, 3}, .top = 0.0, .binomial = BinomialExpectation{2, 0.5}};
    EXPECT_EQ(expectedCounts(b, 400), (std::vector<double>{100, 200, 100}));
    b.binomial.reset();
    EXPECT_TRUE(expectedCounts(b, 400).empty());
}

TEST(ChiSquare, CriticalValuesMatchTheTables) {
    // Upper 1 % points of χ² (any statistics table).
    EXPECT_NEAR(chiSquareCritical(1, 0.01), 6.635, 5e-4);
    EXPECT_NEAR(chiSquareCritical(6, 0.01), 16.812, 5e-4);
    EXPECT_NEAR(chiSquareCritical(10, 0.01), 23.209, 5e-4);
    EXPECT_NEAR(chiSquareCritical(6, 0.05), 12.592, 5e-4);
    EXPECT_NEAR(chiSquareUpperTail(6, 16.812), 0.01, 1e-5);
    EXPECT_EQ(chiSquareUpperTail(3, 0.0), 1.0);
    EXPECT_THROW((void)chiSquareCritical(0, 0.01), InvalidArgument);
    EXPECT_THROW((void)chiSquareCritical(3, 1.0), InvalidArgument);
}

TEST(ChiSquare, MergesThinTailsAndCountsTheDegreesOfFreedom) {
    // Binomial(8, 1/2) over 1000 balls: bins 0 and 8 expect 3.9, so each joins its neighbour.
    const Bins b{.edges = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9},
                 .top = 0.0,
                 .binomial = BinomialExpectation{8, 0.5}};
    const std::vector<double> e = expectedCounts(b, 1000);
    std::vector<std::size_t> o(e.size());
    for (std::size_t k = 0; k < e.size(); ++k)
        o[k] = static_cast<std::size_t>(std::lround(e[k]));
    const ChiSquareTest t = chiSquareTest(o, e);
    ASSERT_EQ(t.expected.size(), 7u);
    EXPECT_EQ(t.dof, 6);
    EXPECT_NEAR(t.expected.front(), e[0] + e[1], 1e-12);
    EXPECT_NEAR(t.expected.back(), e[7] + e[8], 1e-12);
    EXPECT_EQ(t.observed.front(), static_cast<double>(o[0] + o[1]));
    EXPECT_NEAR(t.critical, 16.812, 5e-4);
    EXPECT_LT(t.statistic, 0.1);  // rounding only
    EXPECT_TRUE(t.passes());
    EXPECT_GT(t.pValue, 0.99);
}

TEST(ChiSquare, AFlatPileFailsAgainstTheBinomial) {
    const Bins b{.edges = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9},
                 .top = 0.0,
                 .binomial = BinomialExpectation{8, 0.5}};
    const std::vector<std::size_t> flat(9, 100);
    const ChiSquareTest t = chiSquareTest(flat, expectedCounts(b, 900));
    EXPECT_GT(t.statistic, t.critical);
    EXPECT_FALSE(t.passes());
    EXPECT_LT(t.pValue, 1e-10);
}

TEST(ChiSquare, TooFewExpectedLeavesNoTest) {
    const ChiSquareTest t = chiSquareTest({1, 2}, {1.5, 1.5});
    EXPECT_EQ(t.dof, 0);
    EXPECT_FALSE(t.valid());
    EXPECT_FALSE(t.passes());
    EXPECT_THROW((void)chiSquareTest({1}, {1.0, 2.0}), InvalidArgument);
}

TEST(ChiSquare, AClassThatCannotHappenButDidIsInfinitelyFar) {
    const ChiSquareTest t = chiSquareTest({0, 10, 10}, {0.0, 10.0, 10.0}, 0.01, 0.0);
    EXPECT_EQ(t.statistic, 0.0);
    const ChiSquareTest u = chiSquareTest({3, 10, 10}, {0.0, 10.0, 10.0}, 0.01, 0.0);
    EXPECT_TRUE(std::isinf(u.statistic));
    EXPECT_FALSE(u.passes());
}

}  // namespace
}  // namespace psb
