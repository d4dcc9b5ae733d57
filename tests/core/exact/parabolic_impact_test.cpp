// Times of impact under gravity (exact/parabolic_impact.hpp) against brute-force root searches.

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "exact/parabolic_impact.hpp"

namespace psb::exact {
namespace {

/// The first time in [0, horizon] where |p + q t + ½ a t²| falls to sigma, by sampling the
/// distance on a fine grid and bisecting the first interval where it drops through sigma.
double bruteForceContact(double px, double py, double qx, double qy, double ax, double ay,
                         double sigma, double horizon) {
    const auto f = [&](double t) {
        const double x = px + qx * t + 0.5 * ax * t * t, y = py + qy * t + 0.5 * ay * t * t;
        return x * x + y * y - sigma * sigma;
    };
    constexpr int kSamples = 50000;
    double prev = f(0.0);
    if (prev <= 0.0) return 0.0;
    for (int k = 1; k <= kSamples; ++k) {
        const double t = horizon * k / kSamples;
        const double ft = f(t);
        if (ft <= 0.0) {
            double lo = horizon * (k - 1) / kSamples, hi = t;
            for (int it = 0; it < 200; ++it) {
                const double mid = 0.5 * (lo + hi);
                (f(mid) > 0.0 ? lo : hi) = mid;
            }
            return lo;
        }
        prev = ft;
    }
    return kNever;
}

TEST(ParabolicImpact, QuarticFirstRootAgreesWithABruteForceSearch) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    int hits = 0, compared = 0;
    for (int c = 0; c < 1500; ++c) {
        // A disc falling past (or onto) one that does not fall: all shapes of parabola,
        // including ones that rise, turn and come back.
        const double sigma = 0.2 + 0.8 * (u(rng) + 1.0);
        const double px = 4.0 * u(rng), py = 4.0 * u(rng);
        if (px * px + py * py <= sigma * sigma * 1.01) continue;
        const double qx = 3.0 * u(rng), qy = 3.0 * u(rng);
        const double ax = 0.3 * u(rng), ay = 9.81 * (1.0 + u(rng));
        const double horizon = 3.0;
        const double want = bruteForceContact(px, py, qx, qy, ax, ay, sigma, horizon);
        const double got = parabolicPairImpactTime(px, py, qx, qy, ax, ay, sigma, horizon);
        ++compared;
        if (want == kNever) {
            // A graze the grid cannot see is the only allowed disagreement: then the closest
            // approach is within rounding of sigma.
            if (got != kNever) {
                const double x = px + qx * got + 0.5 * ax * got * got;
                const double y = py + qy * got + 0.5 * ay * got * got;
                EXPECT_NEAR(std::hypot(x, y), sigma, 1e-6 * sigma) << "case " << c;
            }
            continue;
        }
        ++hits;
        ASSERT_NE(got, kNever) << "case " << c << " missed a contact at " << want;
        EXPECT_NEAR(got, want, 1e-12 + 1e-12 * want) << "case " << c;
    }
    EXPECT_GT(hits, 120);
    EXPECT_GT(compared, 1200);
}

TEST(ParabolicImpact, ContactTimeIsAtTheSurfaceToRounding) {
    // A ball dropped from rest 1 m above a disc that does not fall: it touches after √(2h/g).
    const double sigma = 1.0, h = 1.0, g = 9.81;
    const double t = parabolicPairImpactTime(0.0, -(sigma + h), 0.0, 0.0, 0.0, g, sigma, kNever);
    EXPECT_NEAR(t, std::sqrt(2.0 * h / g), 1e-15);
}

TEST(ParabolicImpact, ThrownUpPastADiscItComesBackToHit) {
    // Separating now (moving up and away), turned back by gravity: not "never".
    const double t = parabolicPairImpactTime(0.0, -1.5, 0.0, -2.0, 0.0, 9.81, 1.0, kNever);
    ASSERT_NE(t, kNever);
    const double y = -1.5 - 2.0 * t + 0.5 * 9.81 * t * t;
    EXPECT_NEAR(y, -1.0, 1e-12);
    EXPECT_GT(t, 2.0 * 2.0 / 9.81);  // after the apex
}

TEST(ParabolicImpact, TouchingPairThatLeavesIsNotHitNowButWhenItFallsBack) {
    // Just bounced up off the top of a resting disc at 0.5 m/s.
    const double t = parabolicPairImpactTime(0.0, -1.0, 0.0, -0.5, 0.0, 9.81, 1.0, kNever);
    EXPECT_NEAR(t, 2.0 * 0.5 / 9.81, 1e-12);
    // Touching and approaching: now.
    EXPECT_EQ(parabolicPairImpactTime(0.0, -1.0, 0.0, 0.5, 0.0, 9.81, 1.0, kNever), 0.0);
    // Beyond the horizon: never.
    EXPECT_EQ(parabolicPairImpactTime(0.0, -2.0, 0.0, 0.0, 0.0, 9.81, 1.0, 0.1), kNever);
}

TEST(ParabolicImpact, CrossingTimeFollowsTheParabolaAndItsApex) {
    // Falling from rest 1 m above a floor at y = 1 (y down).
    EXPECT_NEAR(crossingTime(0.0, 0.0, 9.81, 1.0, 1.0), std::sqrt(2.0 / 9.81), 1e-15);
    // Thrown up at 1 m/s towards a ceiling 1 m above: the apex (5 cm) is short of it.
    EXPECT_EQ(crossingTime(0.0, -1.0, 9.81, -1.0, -1.0), kNever);
    // ... and 4 cm above: reached on the way up, at the smaller root.
    const double t = crossingTime(0.0, -1.0, 9.81, -0.04, -1.0);
    EXPECT_NEAR(-1.0 * t + 0.5 * 9.81 * t * t, -0.04, 1e-15);
    EXPECT_LT(t, 1.0 / 9.81);
    // Past the floor and moving up, turned back before getting inside: at its turning point.
    EXPECT_NEAR(crossingTime(1.0 + 1e-3, -0.01, 9.81, 1.0, 1.0), 0.01 / 9.81, 1e-15);
    // Past it and pushed out: now; moving away and not turned back: never.
    EXPECT_EQ(crossingTime(1.0, 0.0, 9.81, 1.0, 1.0), 0.0);
    EXPECT_EQ(crossingTime(1.0, -1.0, -9.81, 1.0, 1.0), kNever);
    // Never negative, whatever the input.
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int k = 0; k < 10000; ++k) {
        const double r = crossingTime(u(rng), u(rng), 10.0 * u(rng), u(rng), k % 2 ? 1.0 : -1.0);
        EXPECT_GE(r, 0.0);
    }
}

TEST(ParabolicImpact, SlabExitUnderGravityTakesEitherFace) {
    int face = 0;
    // Thrown up (towards lo) too slowly to reach it: falls back out through hi.
    const double t = slabExitTimeAccelerated(0.5, -1.0, 9.81, 0.0, 1.0, face);
    EXPECT_EQ(face, 1);
    EXPECT_NEAR(0.5 - t + 0.5 * 9.81 * t * t, 1.0, 1e-14);
    // Fast enough: out through lo.
    EXPECT_GT(slabExitTimeAccelerated(0.5, -10.0, 9.81, 0.0, 1.0, face), 0.0);
    EXPECT_EQ(face, -1);
    // At rest without acceleration: never.
    EXPECT_EQ(slabExitTimeAccelerated(0.5, 0.0, 0.0, 0.0, 1.0, face), kNever);
    EXPECT_EQ(face, 0);
}

}  // namespace
}  // namespace psb::exact
