// The keys that step a value: E / Shift+E restitution, G gravity and T the mode, each sending
// the panel's Set... command, applied through a session.

#include <gtest/gtest.h>

#include "session/gas_world.hpp"
#include "session/keys.hpp"
#include "session/physics_controls.hpp"
#include "session/session.hpp"

namespace psb::app {
namespace {

/// A session over `world`, paused, saving nowhere it is asked to.
Session sessionOf(World world) {
    SessionOptions o;
    o.paused = true;
    return Session(std::move(world), SceneInfo{.name = "test", .dt = Scene{}.dt}, o);
}

/// The text of the last notice `s` gave since the last call.
std::string lastNotice(Session& s) {
    const auto n = s.takeNotices();
    return n.empty() ? std::string() : n.back().text;
}

TEST(Restitution, StepsByFiveHundredthsWithinZeroAndOne) {
    EXPECT_DOUBLE_EQ(steppedRestitution(1.0, -1), 0.95);
    EXPECT_DOUBLE_EQ(steppedRestitution(0.95, +1), 1.0);
    EXPECT_DOUBLE_EQ(steppedRestitution(1.0, +1), 1.0);
    EXPECT_DOUBLE_EQ(steppedRestitution(0.0, -1), 0.0);
    // A scene's 0.93 snaps to the grid: one step down from 0.95's neighbourhood.
    EXPECT_DOUBLE_EQ(steppedRestitution(0.93, -1), 0.9);
    EXPECT_DOUBLE_EQ(restitutionStep(0.93, -1).value, 0.9);
}

TEST(Restitution, EveryStepIsTheDecimalAFileWouldShow) {
    // A teacher's saved scene read "restitution": 0.7000000000000001 after E presses.
    double e = 1.0;
    for (int k = 20; k > 0; --k) {
        e = steppedRestitution(e, -1);
        EXPECT_EQ(e, (k - 1) / 20.0);  // the double nearest the decimal, which prints as it
    }
    EXPECT_EQ(steppedRestitution(0.65, +1), 0.7);
}

TEST(Restitution, TwentyPressesDownFromOneLandExactlyOnZero) {
    Session s = sessionOf(World{});
    for (int k = 0; k < 20; ++k)
        s.apply(keys::restitution(s, -1));
    EXPECT_EQ(s.world().def().restitution, 0.0);
    EXPECT_EQ(lastNotice(s), "Restitution 0.00");
    const std::uint64_t actions = s.userActions();
    s.apply(keys::restitution(s, -1));  // at zero: nothing changes, nothing is said
    EXPECT_EQ(s.userActions(), actions);
    EXPECT_EQ(lastNotice(s), "");
}

TEST(Gravity, IsEarthsWhateverTheBoxSize) {
    EXPECT_EQ(appGravity(), Vec2(0.0, 9.81));
    // The complaint: G in a 700 m box gave 343 m/s². A box never scales gravity.
    WorldDef d;
    d.width = d.height = 700.0;
    Session s = sessionOf(World(d));
    s.apply(keys::gravity(s));
    EXPECT_EQ(s.world().def().gravity, Vec2(0.0, 9.81));
}

TEST(Gravity, TogglesOffAndBackToTheScenesOwnBitForBit) {
    WorldDef d;
    d.width = d.height = 20.0;
    d.gravity = {1.0 / 3.0, 2.0};  // the scene's own, not straight down
    Session s = sessionOf(World(d));
    (void)s.takeNotices();
    s.apply(keys::gravity(s));
    EXPECT_EQ(lastNotice(s), "Gravity off");
    EXPECT_EQ(s.world().def().gravity, Vec2::Zero());
    s.apply(keys::gravity(s));
    EXPECT_EQ(s.world().def().gravity, d.gravity);
    // Said in the axes the window shows (y up by default): the scene's 2 m/s² down is -2.
    EXPECT_EQ(lastNotice(s), "Gravity [0.3333, -2] m/s\u00b2");
    s.apply(cmd::SetShow{ShowOption::YUp, false});
    s.apply(keys::gravity(s));
    s.apply(keys::gravity(s));
    EXPECT_EQ(lastNotice(s), "Gravity [0.3333, 2] m/s\u00b2");
}

TEST(Gravity, WithoutASceneGravityTurnsOnAppGravity) {
    EXPECT_EQ(gravityOf(gravityToggle(Vec2::Zero(), Vec2::Zero())), appGravity());
    EXPECT_EQ(gravityOf(gravityToggle(appGravity(), Vec2::Zero())), Vec2::Zero());
}

TEST(Gravity, TurnsOnInExactModeAndParticlesFall) {
    SolverSettings solver;
    solver.mode = StepMode::Exact;
    World w(WorldDef{}, solver);
    ParticleDef p;
    p.position = {100, 100};
    p.velocity = {10, 0};
    w.add(p);
    Session s = sessionOf(std::move(w));
    s.apply(keys::gravity(s));
    EXPECT_EQ(s.world().def().gravity, appGravity());
    EXPECT_EQ(s.world().solver().mode, StepMode::Exact);
    World stepped = s.world();
    stepped.step(0.1);
    EXPECT_NEAR(stepped.get(stepped.ids()[0]).position.x(), 101.0, 1e-12);
    EXPECT_NEAR(stepped.get(stepped.ids()[0]).position.y(), 100.0 + 0.5 * appGravity().y() * 0.01,
                1e-9);
}

TEST(GravityText, SaysOffOrTheVector) {
    EXPECT_EQ(gravityText(Vec2::Zero(), Axes{}), "off");
    EXPECT_EQ(gravityText(Vec2(0, 343.35), Axes{}), "[0, 343.4] m/s\u00b2");
    EXPECT_EQ(gravityText(Vec2(0, 9.81), Axes{true, 7.0}), "[0, -9.81] m/s\u00b2") << "y up";
}

TEST(ModeKey, CyclesDiscreteSubstepExact) {
    EXPECT_EQ(nextMode(StepMode::Discrete), StepMode::Substep);
    EXPECT_EQ(nextMode(StepMode::Substep), StepMode::Exact);
    EXPECT_EQ(nextMode(StepMode::Exact), StepMode::Discrete);
}

TEST(ModeKey, WalksTheWholeCycleInAWorldWithoutGravity) {
    Session s = sessionOf(gasWorld());
    (void)s.takeNotices();
    s.apply(keys::mode(s));
    EXPECT_EQ(s.world().solver().mode, StepMode::Substep);
    // One substep would be the discrete mode again.
    EXPECT_EQ(s.world().solver().substeps, kAppSubsteps);
    EXPECT_EQ(lastNotice(s), "Mode: substep x4");
    s.apply(keys::mode(s));
    EXPECT_EQ(s.world().solver().mode, StepMode::Exact);
    EXPECT_EQ(lastNotice(s), "Mode: exact");
    s.apply(keys::mode(s));
    EXPECT_EQ(s.world().solver().mode, StepMode::Discrete);
    EXPECT_EQ(s.lastAction(), "change mode");
}

TEST(ModeKey, KeepsTheScenesOwnSubstepCount) {
    World w = gasWorld();
    SolverSettings solver = w.solver();
    solver.substeps = 7;
    w.setSolver(solver);
    EXPECT_EQ(modeStep(w.solver()).substeps, 7);
    solver.substeps = 100;  // more than the panel's slider reaches
    w.setSolver(solver);
    Session s = sessionOf(std::move(w));
    s.apply(keys::mode(s));
    EXPECT_EQ(s.world().solver().mode, StepMode::Substep);
    EXPECT_EQ(s.world().solver().substeps, 100);
}

TEST(ModeKey, ExactWithGravityAndObstaclesIsReachedAndSteps) {
    World w = gasWorld(Vec2(0.0, 9.81));
    w.addObstacle(Obstacle::peg({0.5 * w.def().width, 0.5 * w.def().height}, 1.0));
    Session s = sessionOf(std::move(w));
    s.apply(keys::mode(s));  // discrete -> substep
    ASSERT_EQ(s.world().solver().mode, StepMode::Substep);
    s.apply(keys::mode(s));
    EXPECT_EQ(s.world().solver().mode, StepMode::Exact);
    s.apply(cmd::SingleStep{});
    s.update(0.0, 0.0);
    EXPECT_GT(s.world().time(), 0.0);
    EXPECT_EQ(s.world().solver().mode, StepMode::Exact);
}

}  // namespace
}  // namespace psb::app
