// The axes numbers are reported in (axes.hpp): y up counts from the floor, vectors and turning
// flip, each conversion is its own inverse, and zero stays +0 (never "-0" in a table).

#include <gtest/gtest.h>

#include <cmath>

#include <particle_sandbox/axes.hpp>
#include <particle_sandbox/diagnostics.hpp>
#include <particle_sandbox/world.hpp>

namespace psb {
namespace {

TEST(Axes, YDownIsTheWorldsOwn) {
    const Axes down{false, 8.0};
    EXPECT_EQ(down.y(1.5), 1.5);
    EXPECT_EQ(down.up(-2.0), -2.0);
    EXPECT_EQ(down.spin(3.0), 3.0);
    EXPECT_EQ(down.angularMomentum(4.0, 1.0), 4.0);
}

TEST(Axes, YUpCountsFromTheFloorAndFlipsVectorsAndTurning) {
    const Axes up{true, 8.0};
    EXPECT_EQ(up.y(7.5), 0.5) << "a disc of radius 0.5 on the floor of an 8 m box";
    EXPECT_EQ(up.point(Vec2(2.0, 7.5)), Vec2(2.0, 0.5));
    EXPECT_EQ(up.vector(Vec2(1.0, 3.0)), Vec2(1.0, -3.0)) << "falling reads negative";
    EXPECT_EQ(up.spin(2.0), -2.0) << "clockwise on screen reads negative";
    for (const double v : {0.25, 7.0, 3.125, 8.0})
        EXPECT_EQ(up.y(up.y(v)), v);
    EXPECT_NEAR(up.y(up.y(0.1)), 0.1, 1e-15) << "a height comes back to rounding";
    for (const double v : {0.25, -7.0, 1e-300, 8.0}) {
        EXPECT_EQ(up.up(up.up(v)), v);
        EXPECT_EQ(up.spin(up.spin(v)), v);
    }
    EXPECT_FALSE(std::signbit(up.up(0.0))) << "0 shows as 0, not -0";
    EXPECT_FALSE(std::signbit(up.spin(0.0)));
}

TEST(Axes, AngularMomentumAboutTheBottomLeftCornerCounterclockwise) {
    // The world's figure is about the top-left corner, clockwise-positive on screen; with y up
    // the same motion's angular momentum about the bottom-left corner, counted directly.
    WorldDef def;
    def.width = 10.0;
    def.height = 6.0;
    def.gravity = Vec2::Zero();
    World w(def);
    w.add({.position = Vec2(3.0, 2.0),
           .velocity = Vec2(1.5, -0.5),
           .mass = 2.0,
           .radius = 0.4,
           .angularVelocity = 3.0});
    w.add({.position = Vec2(7.0, 4.5), .velocity = Vec2(-1.0, 2.0), .mass = 1.0, .radius = 0.3});
    const Axes up{true, def.height};
    double expected = 0.0, px = 0.0;
    for (const ParticleId id : w.ids()) {
        const Particle p = w.get(id);
        const Vec2 r = up.point(p.position), v = up.vector(p.velocity);
        expected += p.mass * (r.x() * v.y() - r.y() * v.x()) +
                    p.inertiaFactor * p.mass * p.radius * p.radius * up.spin(p.angularVelocity);
        px += p.mass * p.velocity.x();
    }
    EXPECT_NEAR(up.angularMomentum(angularMomentum(w), px), expected, 1e-12);
}

}  // namespace
}  // namespace psb
