// Times of impact of the exact mode: the stable root, the invalid-state rules, walls, cells.

#include <gtest/gtest.h>

#include <cmath>

#include "exact/time_of_impact.hpp"

namespace psb::exact {
namespace {

TEST(ExactTimeOfImpact, HeadOnPairTouchesWhenTheGapCloses) {
    // Centres 10 apart, radii sum 2, closing at 4 m/s: gap 8 closes in 2 s.
    EXPECT_DOUBLE_EQ(pairImpactTime(10.0, 0.0, -4.0, 0.0, 2.0), 2.0);
}

TEST(ExactTimeOfImpact, GlancingPairTouchesAtTheGeometricInstant) {
    // Relative path along y = 1.2 towards the origin: contact when x² + 1.2² = 2².
    const double t = pairImpactTime(10.0, 1.2, -1.0, 0.0, 2.0);
    EXPECT_NEAR(t, 10.0 - std::sqrt(4.0 - 1.44), 1e-14);
}

TEST(ExactTimeOfImpact, MissesSeparatingAndRestingPairsAreNever) {
    EXPECT_EQ(pairImpactTime(10.0, 2.5, -1.0, 0.0, 2.0), kNever);  // passes 2.5 > 2 away
    EXPECT_EQ(pairImpactTime(10.0, 0.0, 1.0, 0.0, 2.0), kNever);   // separating
    EXPECT_EQ(pairImpactTime(10.0, 0.0, 0.0, 0.0, 2.0), kNever);   // at rest
}

TEST(ExactTimeOfImpact, OverlappingPairCollidesNowIfApproachingOtherwiseNever) {
    EXPECT_EQ(pairImpactTime(1.5, 0.0, -1.0, 0.0, 2.0), 0.0);
    EXPECT_EQ(pairImpactTime(1.5, 0.0, 1.0, 0.0, 2.0), kNever);
    EXPECT_EQ(pairImpactTime(1.5, 0.0, 0.0, 1.0, 2.0), kNever);  // sliding past: not approaching
    EXPECT_EQ(pairImpactTime(2.0, 0.0, -1.0, 0.0, 2.0), 0.0);    // exactly touching
}

TEST(ExactTimeOfImpact, TouchingPairWithRoundingLevelApproachIsNotApproaching) {
    // What a perfectly inelastic collision leaves: touching, relative normal speed ~1e-17.
    EXPECT_EQ(pairImpactTime(2.0, 0.0, -1e-17, 0.3, 2.0), kNever);
    EXPECT_EQ(pairImpactTime(2.0, 0.0, -1e-9, 0.0, 2.0), 0.0);  // slow but clearly approaching
}

TEST(ExactTimeOfImpact, StableRootKeepsItsDigitsWhereTheTextbookFormLosesThem) {
    // Far apart and slow: b² >> a·c, so (−b − √(b² − ac)) / a cancels catastrophically.
    const double dx = 1e8, dvx = -1e-3, sigma = 1.0;
    const double want = (dx - sigma) / 1e-3;  // head-on: exact answer
    const double stable = pairImpactTime(dx, 0.0, dvx, 0.0, sigma);
    EXPECT_LE(std::abs(stable - want) / want, 1e-15);
    // A glancing far approach: offset 0.5, so contact when the gap along x is √(1 − 0.25).
    const long double ref = (1e7L - std::sqrt(0.75L)) / 1e-4L;
    const double got = pairImpactTime(1e7, 0.5, -1e-4, 0.0, 1.0);
    EXPECT_LE(std::abs(static_cast<long double>(got) - ref) / ref, 1e-15L);
}

TEST(ExactTimeOfImpact, NeverReturnsANegativeTime) {
    for (double gap : {-1e-3, -1e-12, 0.0, 1e-15, 1e-3}) {
        for (double v : {-5.0, -1e-9, 0.0, 1e-9, 5.0}) {
            const double t = pairImpactTime(2.0 + gap, 0.0, v, 0.0, 2.0);
            EXPECT_GE(t, 0.0) << gap << " " << v;
            EXPECT_GE(wallImpactTime(9.0 + gap, v, 9.0, 1.0), 0.0);
            EXPECT_GE(wallImpactTime(1.0 - gap, v, 1.0, -1.0), 0.0);
        }
    }
}

TEST(ExactTimeOfImpact, WallIsHitOnlyWhenMovingTowardsIt) {
    EXPECT_DOUBLE_EQ(wallImpactTime(5.0, 2.0, 9.0, 1.0), 2.0);
    EXPECT_DOUBLE_EQ(wallImpactTime(5.0, -2.0, 1.0, -1.0), 2.0);
    EXPECT_EQ(wallImpactTime(5.0, -2.0, 9.0, 1.0), kNever);
    EXPECT_EQ(wallImpactTime(9.5, 2.0, 9.0, 1.0), 0.0);      // past it, moving out: now
    EXPECT_EQ(wallImpactTime(9.5, -2.0, 9.0, 1.0), kNever);  // past it, moving in: left alone
}

TEST(ExactTimeOfImpact, SlabExitPicksTheFaceAheadAndNeverGoesBackInTime) {
    int face = 0;
    EXPECT_DOUBLE_EQ(slabExitTime(2.0, 1.0, 0.0, 4.0, face), 2.0);
    EXPECT_EQ(face, 1);
    EXPECT_DOUBLE_EQ(slabExitTime(1.0, -0.5, 0.0, 4.0, face), 2.0);
    EXPECT_EQ(face, -1);
    EXPECT_EQ(slabExitTime(4.0 + 1e-15, 1.0, 0.0, 4.0, face), 0.0);
    EXPECT_EQ(slabExitTime(2.0, 0.0, 0.0, 4.0, face), kNever);
    EXPECT_EQ(face, 0);
}

}  // namespace
}  // namespace psb::exact
