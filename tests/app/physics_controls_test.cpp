// E / Shift+E restitution steps and G gravity, including the exact mode's refusal.

#include <gtest/gtest.h>

#include "physics_controls.hpp"

namespace psb::app {
namespace {

TEST(Restitution, StepsByFiveHundredthsWithinZeroAndOne) {
    EXPECT_DOUBLE_EQ(steppedRestitution(1.0, -1), 0.95);
    EXPECT_DOUBLE_EQ(steppedRestitution(0.95, +1), 1.0);
    EXPECT_DOUBLE_EQ(steppedRestitution(1.0, +1), 1.0);
    EXPECT_DOUBLE_EQ(steppedRestitution(0.0, -1), 0.0);
    // A scene's 0.93 snaps to the grid: one step down from 0.95's neighbourhood.
    EXPECT_DOUBLE_EQ(steppedRestitution(0.93, -1), 0.9);
}

TEST(Restitution, TwentyPressesDownFromOneLandExactlyOnZero) {
    World w;
    for (int k = 0; k < 20; ++k)
        stepRestitution(w, -1);
    EXPECT_EQ(w.def().restitution, 0.0);
    const ControlChange c = stepRestitution(w, -1);
    EXPECT_FALSE(c.changed);
    EXPECT_EQ(c.message, "Restitution 0.00");
}

TEST(Gravity, IsEarthsInABoxOfHumanScale) {
    WorldDef d;
    d.width = 2.54;
    d.height = 1.27;
    EXPECT_EQ(appGravity(d), Vec2(0.0, 9.81));
    d.width = d.height = 20.0;
    EXPECT_EQ(appGravity(d), Vec2(0.0, 9.81));
}

TEST(Gravity, ScalesWithALargerBoxSoAFallAcrossItTakesTwoSeconds) {
    WorldDef d;  // 700 m: the original's window
    const Vec2 g = appGravity(d);
    EXPECT_NEAR(g.y(), 9.81 * 35.0, 1e-9);
    // Falling 700 m from rest: t = sqrt(2 h / g), as across a 20 m box under 9.81 m/s².
    EXPECT_NEAR(std::sqrt(2.0 * 700.0 / g.y()), std::sqrt(2.0 * 20.0 / 9.81), 1e-12);
}

TEST(Gravity, TogglesOffAndBackToTheScenesOwn) {
    WorldDef d;
    d.width = d.height = 20.0;
    d.gravity = {0.0, 9.81};
    World w(d);
    EXPECT_EQ(toggleGravity(w, d.gravity).message, "Gravity off");
    EXPECT_EQ(w.def().gravity, Vec2::Zero());
    const ControlChange on = toggleGravity(w, Vec2(1.0, 2.0));
    EXPECT_TRUE(on.changed);
    EXPECT_EQ(w.def().gravity, Vec2(1.0, 2.0));
    EXPECT_EQ(on.message, "Gravity [1, 2] m/s^2");
}

TEST(Gravity, WithoutASceneGravityTurnsOnAppGravity) {
    World w;
    toggleGravity(w, Vec2::Zero());
    EXPECT_EQ(w.def().gravity, appGravity(w.def()));
}

TEST(Gravity, TurnsOnInExactModeAndParticlesFall) {
    SolverSettings s;
    s.mode = StepMode::Exact;
    World w(WorldDef{}, s);
    ParticleDef p;
    p.position = {100, 100};
    p.velocity = {10, 0};
    w.add(p);
    const ControlChange c = toggleGravity(w, Vec2::Zero());
    EXPECT_TRUE(c.changed);
    EXPECT_EQ(w.def().gravity, appGravity(w.def()));
    EXPECT_EQ(w.solver().mode, StepMode::Exact);
    w.step(0.1);
    EXPECT_NEAR(w.get(w.ids()[0]).position.x(), 101.0, 1e-12);
    EXPECT_NEAR(w.get(w.ids()[0]).position.y(), 100.0 + 0.5 * appGravity(w.def()).y() * 0.01, 1e-9);
}

TEST(GravityText, SaysOffOrTheVector) {
    EXPECT_EQ(gravityText(Vec2::Zero()), "off");
    EXPECT_EQ(gravityText(Vec2(0, 343.35)), "[0, 343.4] m/s^2");
}

}  // namespace
}  // namespace psb::app
