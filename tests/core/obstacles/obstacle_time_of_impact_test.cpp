// Times of impact with fixed obstacles: hand-worked cases, the overlap conventions, and random
// configurations against a brute-force search for the first contact.

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "obstacles/obstacle_geometry.hpp"
#include "obstacles/obstacle_time_of_impact.hpp"

namespace psb::exact {
namespace {

TEST(ObstacleTimeOfImpact, PegHeadOn) {
    // Disc r = 1 at x = 0 moving at 2 m/s toward a peg R = 0.5 at x = 10: gap 8.5 in 4.25 s.
    EXPECT_DOUBLE_EQ(pegImpactTime(0.0, 0.0, 2.0, 0.0, 1.0, 10.0, 0.0, 0.5), 4.25);
    EXPECT_EQ(pegImpactTime(0.0, 0.0, -2.0, 0.0, 1.0, 10.0, 0.0, 0.5), kNever);  // moving away
    EXPECT_EQ(pegImpactTime(0.0, 2.0, 2.0, 0.0, 1.0, 10.0, 0.0, 0.5), kNever);   // passes by
}

TEST(ObstacleTimeOfImpact, SegmentSideFromEitherSide) {
    // Horizontal wall from (0, 0) to (10, 0), half-thickness 0.5; disc r = 1.
    // From above (y = -5) moving down at 1 m/s: touches when y = -1.5, after 3.5 s.
    EXPECT_DOUBLE_EQ(segmentImpactTime(5.0, -5.0, 0.0, 1.0, 1.0, 0.0, 0.0, 10.0, 0.0, 0.5), 3.5);
    // From below moving up at 2 m/s: from y = 5 to y = 1.5 takes 1.75 s.
    EXPECT_DOUBLE_EQ(segmentImpactTime(5.0, 5.0, 0.0, -2.0, 1.0, 0.0, 0.0, 10.0, 0.0, 0.5), 1.75);
    // The endpoints' order does not matter.
    EXPECT_DOUBLE_EQ(segmentImpactTime(5.0, 5.0, 0.0, -2.0, 1.0, 10.0, 0.0, 0.0, 0.0, 0.5), 1.75);
}

TEST(ObstacleTimeOfImpact, SegmentEndCapIsRound) {
    // Moving down along x = 11, one metre past the end (10, 0): the side is missed, the cap at
    // (10, 0) with radius 0.5 is hit when (1)² + y² = 1.5².
    const double t = segmentImpactTime(11.0, -5.0, 0.0, 1.0, 1.0, 0.0, 0.0, 10.0, 0.0, 0.5);
    EXPECT_NEAR(t, 5.0 - std::sqrt(1.5 * 1.5 - 1.0), 1e-14);
    EXPECT_EQ(segmentSideImpactTime(11.0, -5.0, 0.0, 1.0, 1.0, 0.0, 0.0, 10.0, 0.0, 0.5), kNever);
    // Head-on along the segment's own line into its end.
    EXPECT_DOUBLE_EQ(segmentImpactTime(20.0, 0.0, -1.0, 0.0, 1.0, 0.0, 0.0, 10.0, 0.0, 0.5), 8.5);
}

TEST(ObstacleTimeOfImpact, OverlapCollidesNowIfApproachingElseNever) {
    // 1.2 above a wall whose contact distance is 1.5: overlapping.
    EXPECT_EQ(segmentImpactTime(5.0, -1.2, 0.0, 1.0, 1.0, 0.0, 0.0, 10.0, 0.0, 0.5), 0.0);
    EXPECT_EQ(segmentImpactTime(5.0, -1.2, 0.0, -1.0, 1.0, 0.0, 0.0, 10.0, 0.0, 0.5), kNever);
    EXPECT_EQ(pegImpactTime(1.0, 0.0, -1.0, 0.0, 1.0, 0.0, 0.0, 0.5), 0.0);
    EXPECT_EQ(pegImpactTime(1.0, 0.0, 1.0, 0.0, 1.0, 0.0, 0.0, 0.5), kNever);
}

TEST(ObstacleTimeOfImpact, ZeroVelocityIsNever) {
    EXPECT_EQ(segmentImpactTime(5.0, -5.0, 0.0, 0.0, 1.0, 0.0, 0.0, 10.0, 0.0, 0.5), kNever);
    EXPECT_EQ(pegImpactTime(5.0, -5.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.5), kNever);
}

/// Distance from (x, y) to the obstacle's core.
double coreDistance(const Obstacle& o, double x, double y) {
    double qx, qy;
    nearestCorePoint(o, x, y, qx, qy);
    return std::hypot(x - qx, y - qy);
}

/// The first t in [0, horizon] at which the disc touches the obstacle, by sampling the
/// distance on a fine grid of times and bisecting the first sign change; or kNever.
/// `grazing` is set when the closest approach is within a hair of contact (an ambiguous case).
double bruteForceImpact(const Obstacle& o, double px, double py, double vx, double vy, double r,
                        double horizon, bool& grazing) {
    const double sigma = r + o.radius;
    auto gap = [&](double t) { return coreDistance(o, px + t * vx, py + t * vy) - sigma; };
    constexpr int kSamples = 20000;
    double minGap = gap(0.0);
    double prev = 0.0;
    for (int k = 1; k <= kSamples; ++k) {
        const double t = horizon * k / kSamples;
        const double g = gap(t);
        minGap = std::min(minGap, g);
        if (g <= 0.0) {
            double lo = prev, hi = t;
            for (int it = 0; it < 200; ++it) {
                const double mid = 0.5 * (lo + hi);
                (gap(mid) <= 0.0 ? hi : lo) = mid;
            }
            grazing = false;
            return hi;
        }
        prev = t;
    }
    grazing = minGap < 1e-6 * sigma;
    return kNever;
}

TEST(ObstacleTimeOfImpact, MatchesBruteForceOnRandomConfigurations) {
    std::mt19937_64 rng(17);
    std::uniform_real_distribution<double> pos(-10.0, 10.0), vel(-5.0, 5.0), size(0.05, 2.0);
    int hits = 0, misses = 0, sides = 0, caps = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        const bool peg = trial % 3 == 0;
        const Vec2 a(pos(rng), pos(rng));
        const Obstacle o = peg ? Obstacle::peg(a, size(rng))
                               : Obstacle::segment(a, Vec2(pos(rng), pos(rng)), 2.0 * size(rng));
        const double r = size(rng);
        double px = pos(rng) * 2.0, py = pos(rng) * 2.0;
        if (coreDistance(o, px, py) <= r + o.radius) continue;  // starts overlapping
        const double vx = vel(rng), vy = vel(rng);
        const double horizon = 20.0;
        bool grazing = false;
        const double want = bruteForceImpact(o, px, py, vx, vy, r, horizon, grazing);
        if (grazing) continue;
        const double got = obstacleImpactTime(px, py, vx, vy, r, o);
        if (want == kNever) {
            EXPECT_TRUE(got > horizon) << "trial " << trial << " got " << got;
            ++misses;
        } else {
            EXPECT_NEAR(got, want, 1e-9 * horizon) << "trial " << trial;
            ++hits;
            if (!peg) {
                const double side = segmentSideImpactTime(px, py, vx, vy, r, o.a.x(), o.a.y(),
                                                          o.b.x(), o.b.y(), o.radius);
                (side == got ? sides : caps) += 1;
            }
        }
    }
    // The random cases must exercise every part: hits and misses, flat sides and caps.
    EXPECT_GT(hits, 300);
    EXPECT_GT(misses, 300);
    EXPECT_GT(sides, 100);
    EXPECT_GT(caps, 50);
}

TEST(ObstacleTimeOfImpact, ContactPointIsAtTheContactDistance) {
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> pos(-10.0, 10.0), vel(-5.0, 5.0), size(0.05, 2.0);
    int checked = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        const Obstacle o =
            Obstacle::segment(Vec2(pos(rng), pos(rng)), Vec2(pos(rng), pos(rng)), 2.0 * size(rng));
        const double r = size(rng), px = 2.0 * pos(rng), py = 2.0 * pos(rng);
        if (coreDistance(o, px, py) <= r + o.radius) continue;
        const double vx = vel(rng), vy = vel(rng);
        const double t = obstacleImpactTime(px, py, vx, vy, r, o);
        if (t == kNever) continue;
        const double d = coreDistance(o, px + t * vx, py + t * vy);
        EXPECT_NEAR(d, r + o.radius, 1e-10 * (r + o.radius + std::hypot(px, py))) << trial;
        ++checked;
    }
    EXPECT_GT(checked, 200);
}

}  // namespace
}  // namespace psb::exact
