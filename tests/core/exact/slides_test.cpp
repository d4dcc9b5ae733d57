// The exact mode's slides (Slides): a slide starts only at contact, away from the face's ends,
// for a particle free across both axes; a block slides down a face at g (sin θ − μ cos θ), and
// static friction holds it at rest within the friction angle.

#include <gtest/gtest.h>

#include <cmath>

#include "exact/slides.hpp"
#include "parts.hpp"

namespace psb::exact {
namespace {

constexpr double kG = 9.81;

TEST(ExactSlides, ASlideStartsOnlyAtContactAwayFromTheEndsForAFreeParticle) {
    // A level face from (0, 5) to (10, 5), 0.2 m thick; discs of 0.5 m on it (y points down).
    const ObstacleCells obstacles =
        obstaclesIn({Obstacle::segment({0.0, 5.0}, {10.0, 5.0}, 0.2)}, 10.0, 10.0);
    Slides slides;
    slides.reset(1);
    const Cold freeAxes{};
    Body a = bodyAt(4.0, 4.4, 0.5, 1.5, 0.3, kRestY);
    ASSERT_TRUE(slides.start(0, a, freeAxes, obstacles, 0, 0.0, -1.0));
    EXPECT_TRUE(a.flags & kSliding);
    EXPECT_FALSE(a.flags & kRestY) << "the face carries it now";
    EXPECT_EQ(slides[0].obstacle, 0u);
    EXPECT_EQ(a.vx, 1.5);
    EXPECT_EQ(a.vy, 0.0) << "its velocity into the face is absorbed";

    Body away = bodyAt(4.0, 4.399, 0.5);  // a millimetre off the face
    EXPECT_FALSE(slides.start(0, away, freeAxes, obstacles, 0, 0.0, -1.0));
    Body atEnd = bodyAt(10.0, 4.4, 0.5);  // over the end: the cap's
    EXPECT_FALSE(slides.start(0, atEnd, freeAxes, obstacles, 0, 0.0, -1.0));
    Cold pinned{};
    pinned.pinX = true;
    Body held = bodyAt(4.0, 4.4, 0.5);
    EXPECT_FALSE(slides.start(0, held, pinned, obstacles, 0, 0.0, -1.0));
    EXPECT_FALSE(held.flags & kSliding);
}

TEST(ExactSlides, ABlockSlidesDownAFaceAtGSinThetaLessMuGCosTheta) {
    // A face tilted 30°, down to the right (y points down).
    const double theta = 3.14159265358979323846 / 6.0, ux = std::cos(theta), uy = std::sin(theta);
    const ObstacleCells obstacles =
        obstaclesIn({Obstacle::segment({0.0, 0.0}, {10.0 * ux, 10.0 * uy}, 0.2)}, 20.0, 20.0);
    const Gravity g{0.0, kG, true};
    Slides slides;
    slides.reset(1);
    slides[0].obstacle = 0;
    const double mu = 0.2, at = kG * (std::sin(theta) - mu * std::cos(theta));
    slides.setBlockAcceleration(0, bodyAt(1.0, 0.0, 0.5, 2.0 * ux, 2.0 * uy), obstacles, g, mu);
    EXPECT_NEAR(slides[0].ax, at * ux, 1e-12);
    EXPECT_NEAR(slides[0].ay, at * uy, 1e-12);
    // At rest with μ above tan θ: held.
    slides.setBlockAcceleration(0, bodyAt(1.0, 0.0, 0.5), obstacles, g, 0.6);
    EXPECT_EQ(slides[0].ax, 0.0);
    EXPECT_EQ(slides[0].ay, 0.0);
}

}  // namespace
}  // namespace psb::exact
