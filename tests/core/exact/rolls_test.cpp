// The exact mode's rolls (Rolls): a disc that slips on the floor is given the slip's
// deceleration and the instant its slip ends, and rolls from there at v = v0·q / (1 + q).

#include <gtest/gtest.h>

#include <particle_sandbox/particle_arrays.hpp>

#include "exact/rolls.hpp"
#include "parts.hpp"

namespace psb::exact {
namespace {

constexpr double kG = 9.81;

// One disc (k = 1/2, q = 2) of 0.5 m in a world that keeps rotation, not turning.
ParticleArrays oneDisc() {
    ParticleArrays p;
    p.x = {1.0};
    p.y = {9.5};
    p.vx = {2.0};
    p.vy = {0.0};
    p.invMass = {1.0};
    p.radius = {0.5};
    p.mass = {1.0};
    p.id = {ParticleId{}};
    p.rotation = true;
    p.angle = {0.0};
    p.omega = {0.0};
    p.inertiaFactor = {0.5};
    p.fixedRotation = {0};
    return p;
}

TEST(ExactRolls, ADiscSlippingOnTheFloorRollsWhenItsSlipEnds) {
    const double mu = 0.3, v0 = 2.0, q = 2.0;
    Rolls rolls;
    rolls.reset(oneDisc(), mu);
    ASSERT_TRUE(rolls.rough());
    ASSERT_TRUE(rolls.turns(0));
    Slides slides;
    slides.reset(1);
    const ObstacleCells none = obstaclesIn({}, 10.0, 10.0);
    const Gravity g{0.0, kG, true};
    const Cold c{};
    Body a = bodyAt(1.0, 9.5, 0.5, v0, 0.0, kRestY);  // on the floor
    rolls.set(0, a, c, slides, none, g, mu);
    EXPECT_TRUE(a.flags & kRolling);
    // Slipping forward: the centre decelerates at μ g, the slip s = v − ω r at μ g (1 + q).
    EXPECT_NEAR(slides[0].ax, -mu * kG, 1e-12);
    EXPECT_EQ(slides[0].ay, 0.0);
    const double tStar = v0 / (mu * kG * (1.0 + q));
    EXPECT_NEAR(slides[0].slipEnds, tStar, 1e-12);
    // At the instant: rolling, at v0·q / (1 + q), without acceleration on a level floor.
    a.vx = v0 - mu * kG * tStar;
    a.t = tStar;
    EXPECT_FALSE(rolls.endSlip(0, a, c, slides, none, g, mu, tStar));
    EXPECT_NEAR(a.vx, v0 * q / (1.0 + q), 1e-12);
    EXPECT_EQ(slides[0].ax, 0.0);
    EXPECT_EQ(slides[0].slipEnds, kNever) << "rolling makes no events";
    EXPECT_NEAR(rolls.spinAt(0, 0.5, tStar).omega, a.vx / 0.5, 1e-12);
}

}  // namespace
}  // namespace psb::exact
