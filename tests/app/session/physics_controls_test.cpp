// E / Shift+E restitution steps and G gravity, including the exact mode's refusal.

#include <gtest/gtest.h>

#include "session/physics_controls.hpp"

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

TEST(Gravity, IsEarthsWhateverTheBoxSize) {
    EXPECT_EQ(appGravity(), Vec2(0.0, 9.81));
    // The complaint: G in a 700 m box gave 343 m/s². A box never scales gravity.
    WorldDef d;
    d.width = d.height = 700.0;
    World w(d);
    EXPECT_TRUE(toggleGravity(w, Vec2::Zero()).changed);
    EXPECT_EQ(w.def().gravity, Vec2(0.0, 9.81));
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
    EXPECT_EQ(on.message, "Gravity [1, 2] m/s\u00b2");
}

TEST(Gravity, WithoutASceneGravityTurnsOnAppGravity) {
    World w;
    toggleGravity(w, Vec2::Zero());
    EXPECT_EQ(w.def().gravity, appGravity());
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
    EXPECT_EQ(w.def().gravity, appGravity());
    EXPECT_EQ(w.solver().mode, StepMode::Exact);
    w.step(0.1);
    EXPECT_NEAR(w.get(w.ids()[0]).position.x(), 101.0, 1e-12);
    EXPECT_NEAR(w.get(w.ids()[0]).position.y(), 100.0 + 0.5 * appGravity().y() * 0.01, 1e-9);
}

TEST(GravityText, SaysOffOrTheVector) {
    EXPECT_EQ(gravityText(Vec2::Zero()), "off");
    EXPECT_EQ(gravityText(Vec2(0, 343.35)), "[0, 343.4] m/s\u00b2");
}

}  // namespace
}  // namespace psb::app
