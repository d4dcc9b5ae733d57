// g(r)'s counting and normalisation, without a world.

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "observables/pair_distribution.hpp"

namespace psb::observables {
namespace {

TEST(PairDistribution, TheRectanglesPairMeasureIsTheAreaSquaredWhenIntegratedToItsReach) {
    // Over every distance the probability is 1: ∫ 2πr γ̄ = (ab)². The formula holds to
    // min(a, b) only, so check a square's small-r limit instead: 2πr·ab per unit r at r → 0.
    const double a = 3.0, b = 5.0, r = 1e-4;
    EXPECT_NEAR(rectanglePairMeasure(a, b, 0.0, r) / (std::numbers::pi * a * b * r * r), 1.0, 1e-3);
}

TEST(PairDistribution, UniformPointsGiveOneAtEveryDistanceUpToHalfTheBox) {
    // Uniform random points are the ideal gas: g = 1 within the noise of 200 snapshots of 400
    // points (each bin of width 0.25 m holds ~10⁴ pairs: 1 % noise; 4 % allowed).
    const double w = 20.0, h = 10.0;
    PairDistribution pd;
    pd.configure(5.0, 0.25, w, h);
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> ux(0.0, w), uy(0.0, h);
    std::vector<double> counts, x(400), y(400);
    for (int s = 0; s < 200; ++s) {
        for (std::size_t i = 0; i < x.size(); ++i) {
            x[i] = ux(rng);
            y[i] = uy(rng);
        }
        pd.count(x, y, counts);
    }
    const std::vector<double> g = pd.g(counts, 200, x.size(), w, h);
    ASSERT_EQ(g.size(), 20u);
    for (std::size_t k = 1; k < g.size(); ++k)
        EXPECT_NEAR(g[k], 1.0, 0.04) << "bin " << k;
}

TEST(PairDistribution, CountsEveryPairOnceWhateverTheCells) {
    // Cells of the range's size split the box 4 × 4; all-pairs counting must agree.
    PairDistribution pd;
    pd.configure(2.5, 0.1, 10.0, 10.0);
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(0.0, 10.0);
    std::vector<double> x(300), y(300), counts;
    for (std::size_t i = 0; i < x.size(); ++i) {
        x[i] = u(rng);
        y[i] = u(rng);
    }
    pd.count(x, y, counts);
    double brute = 0.0, counted = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
        for (std::size_t j = i + 1; j < x.size(); ++j)
            brute += std::hypot(x[i] - x[j], y[i] - y[j]) < 2.5 ? 1.0 : 0.0;
    }
    for (const double c : counts)
        counted += c;
    EXPECT_EQ(counted, brute);
}

TEST(PairDistribution, InAPeriodicBoxPairsAreCountedBetweenNearestImagesInWrappedCells) {
    // A pair 0.25 m apart across the left edge is 0.25 m apart; and with cells 4 × 4 (range 2.5)
    // or one cell (range 5, half the box) the counts are the brute force's over nearest images.
    PairDistribution edge;
    edge.configure(1.0, 0.1, 10.0, 10.0, true);
    std::vector<double> counts;
    edge.count({0.1, 9.85}, {5.0, 5.0}, counts);
    EXPECT_EQ(counts[2], 1.0);
    std::mt19937_64 rng(4);
    std::uniform_real_distribution<double> u(0.0, 10.0);
    std::vector<double> x(300), y(300);
    for (std::size_t i = 0; i < x.size(); ++i) {
        x[i] = u(rng);
        y[i] = u(rng);
    }
    for (const double range : {2.5, 5.0}) {
        PairDistribution pd;
        pd.configure(range, 0.1, 10.0, 10.0, true);
        std::vector<double> c;
        pd.count(x, y, c);
        double brute = 0.0, counted = 0.0;
        for (std::size_t i = 0; i < x.size(); ++i) {
            for (std::size_t j = i + 1; j < x.size(); ++j) {
                double dx = std::abs(x[i] - x[j]), dy = std::abs(y[i] - y[j]);
                dx = std::min(dx, 10.0 - dx);
                dy = std::min(dy, 10.0 - dy);
                brute += std::hypot(dx, dy) < range ? 1.0 : 0.0;
            }
        }
        for (const double k : c)
            counted += k;
        EXPECT_EQ(counted, brute) << "range " << range;
        // Uniform points: g near 1 out to half the box.
        const std::vector<double> g = pd.g(c, 1, x.size(), 10.0, 10.0);
        EXPECT_TRUE(std::isfinite(g.back())) << "range " << range;
    }
}

TEST(PairDistribution, TheContactValueOfAQuadraticIsItsValueAtContact) {
    PairDistribution pd;
    pd.configure(4.0, 0.02, 10.0, 10.0);
    std::vector<double> g(pd.bins(), 0.0);
    const double sigma = 2.0;
    for (std::size_t k = 0; k < g.size(); ++k) {
        const double u = ((k + 0.5) * 0.02 - sigma) / sigma;
        g[k] = 3.0 - 4.0 * u + 6.0 * u * u;
    }
    EXPECT_NEAR(pd.contactValue(g, sigma), 3.0, 1e-9);
    // Too coarse bins to fit: NaN, not a guess.
    PairDistribution coarse;
    coarse.configure(4.0, 0.2, 10.0, 10.0);
    EXPECT_TRUE(std::isnan(coarse.contactValue(std::vector<double>(coarse.bins(), 1.0), sigma)));
}

}  // namespace
}  // namespace psb::observables
