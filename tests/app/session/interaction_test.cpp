// Grab, fling, launch and delete, driven with synthetic pointer samples (world metres,
// seconds), no window involved.

#include <gtest/gtest.h>

#include <particle_sandbox/diagnostics.hpp>

#include "session/hand_steps.hpp"
#include "session/interaction.hpp"

namespace psb::app {
namespace {

World boxWorld() {
    return World(WorldDef{});  // 700 m × 700 m, walls on
}

ParticleId addAt(World& w, Vec2 pos, double radius = 10.0, double mass = 2.0) {
    ParticleDef d;
    d.position = pos;
    d.radius = radius;
    d.mass = mass;
    return w.add(d);
}

LaunchSettings launch() {
    LaunchSettings s;
    s.window = 0.1;
    s.minDistance = 1.0;
    return s;
}

/// Moves the pointer in a straight line from `from` at `t0` with velocity `v`, one sample
/// every 10 ms for `steps` samples; returns the time of the last sample.
double drag(Interaction& in, Vec2 from, double t0, Vec2 v, int steps) {
    double t = t0;
    for (int k = 1; k <= steps; ++k) {
        t = t0 + 0.01 * k;
        in.moveTo(from + v * (t - t0), t);
    }
    return t;
}

TEST(Interaction, PressOnAParticleGrabsItAndMakesItKinematic) {
    World w = boxWorld();
    const ParticleId id = addAt(w, {100, 100});
    Interaction in;
    press(in, w, Vec2(105, 100), 0.0);
    EXPECT_EQ(in.mode(), Interaction::Mode::Holding);
    EXPECT_EQ(in.held(), id);
    EXPECT_TRUE(w.isKinematic(id));
}

TEST(Interaction, GrabHitTestUsesTheWholeDiscInWorldUnits) {
    World w = boxWorld();
    const ParticleId id = addAt(w, {100, 100}, 10.0);
    Interaction in;
    // 9.9 m from the centre of a 10 m disc: inside, whatever the zoom.
    press(in, w, Vec2(109.9, 100), 0.0);
    EXPECT_EQ(in.held(), id);
    release(in, w, Vec2(109.9, 100), 0.5, {}, launch(), 1.0);
    press(in, w, Vec2(110.1, 100), 1.0);
    EXPECT_EQ(in.mode(), Interaction::Mode::Launching);
}

TEST(Interaction, GrabTakesTheTopmostOfOverlappingParticles) {
    World w = boxWorld();
    addAt(w, {100, 100});
    const ParticleId top = addAt(w, {105, 100});
    Interaction in;
    press(in, w, Vec2(103, 100), 0.0);
    EXPECT_EQ(in.held(), top);
}

TEST(Interaction, OnlyThePressGrabsSweepingOverOthersCollectsNothing) {
    World w = boxWorld();
    const ParticleId a = addAt(w, {100, 100});
    const ParticleId b = addAt(w, {300, 100});
    Interaction in;
    press(in, w, Vec2(100, 100), 0.0);
    drag(in, Vec2(100, 100), 0.0, Vec2(1000, 0), 20);  // passes over b
    applyHold(in, w, 0.2, launch());
    EXPECT_EQ(in.held(), a);
    EXPECT_FALSE(w.isKinematic(b));
    press(in, w, Vec2(300, 100), 0.25);  // a second press while holding is ignored
    EXPECT_EQ(in.held(), a);
}

TEST(Interaction, HeldParticleKeepsItsGrabOffset) {
    World w = boxWorld();
    const ParticleId id = addAt(w, {100, 100});
    Interaction in;
    press(in, w, Vec2(106, 97), 0.0);  // off centre by (6, -3)
    applyHold(in, w, 0.0, launch());
    EXPECT_NEAR(w.get(id).position.x(), 100.0, 1e-12);  // no jump to the cursor
    EXPECT_NEAR(w.get(id).position.y(), 100.0, 1e-12);
    in.moveTo(Vec2(206, 147), 0.05);
    applyHold(in, w, 0.05, launch());
    EXPECT_NEAR(w.get(id).position.x(), 200.0, 1e-12);
    EXPECT_NEAR(w.get(id).position.y(), 150.0, 1e-12);
}

TEST(Interaction, ReleaseFlingsWithTheVelocityOfTheLast100ms) {
    World w = boxWorld();
    const ParticleId id = addAt(w, {100, 100});
    Interaction in;
    press(in, w, Vec2(100, 100), 0.0);
    // Slow for 0.3 s, then 200 m/s to the right and 50 m/s down for the last 0.1 s.
    double t = drag(in, Vec2(100, 100), 0.0, Vec2(10, 0), 30);
    const Vec2 p = in.pointer();
    t = drag(in, p, t, Vec2(200, 50), 10);
    const ReleaseResult r = release(in, w, in.pointer(), t, {}, launch(), 1.0);
    ASSERT_EQ(r.kind, ReleaseResult::Kind::Flung);
    EXPECT_NEAR(r.velocity.x(), 200.0, 1e-6);
    EXPECT_NEAR(r.velocity.y(), 50.0, 1e-6);
    EXPECT_NEAR(w.get(id).velocity.x(), 200.0, 1e-6);
    EXPECT_FALSE(w.isKinematic(id));
    EXPECT_EQ(in.mode(), Interaction::Mode::Idle);
}

TEST(Interaction, AHandThatStoppedReleasesAtRest) {
    World w = boxWorld();
    const ParticleId id = addAt(w, {100, 100});
    Interaction in;
    press(in, w, Vec2(100, 100), 0.0);
    const double t = drag(in, Vec2(100, 100), 0.0, Vec2(300, 0), 10);
    // Released 0.3 s after the last motion: nothing moved in the last 100 ms.
    release(in, w, in.pointer(), t + 0.3, {}, launch(), 1.0);
    EXPECT_EQ(w.get(id).velocity, Vec2::Zero());
}

TEST(Interaction, AReleaseReportedAFrameAfterSparseMovesFlingsWithTheirSpeed) {
    // A slow page: one move every 50 ms at 300 m/s, and the lift (a finger's, where the last
    // move left it) 80 ms after the last move. Measured up to the lift, the window (1.5 x 50 ms)
    // held only the last move: the fling read as a hand at rest.
    World w = boxWorld();
    const ParticleId id = addAt(w, {100, 100});
    Interaction in;
    press(in, w, Vec2(100, 100), 0.0);
    double t = 0.0;
    for (int k = 1; k <= 4; ++k) {
        t = 0.05 * k;
        in.moveTo(Vec2(100.0 + 300.0 * t, 100.0), t);
    }
    const ReleaseResult r = release(in, w, in.pointer(), t + 0.08, {}, launch(), 1.0);
    ASSERT_EQ(r.kind, ReleaseResult::Kind::Flung);
    EXPECT_NEAR(r.velocity.x(), 300.0, 1e-6);
    EXPECT_NEAR(w.get(id).velocity.x(), 300.0, 1e-6);
}

TEST(Interaction, SparseMovesThenARestLongerThanTheirSpacingReleaseAtRest) {
    World w = boxWorld();
    const ParticleId id = addAt(w, {100, 100});
    Interaction in;
    press(in, w, Vec2(100, 100), 0.0);
    double t = 0.0;
    for (int k = 1; k <= 4; ++k) {
        t = 0.05 * k;
        in.moveTo(Vec2(100.0 + 300.0 * t, 100.0), t);
    }
    // 1.5 x 50 ms is 75 ms, under the 100 ms window: still 100 ms, then let go.
    release(in, w, in.pointer(), t + 0.11, {}, launch(), 1.0);
    EXPECT_EQ(w.get(id).velocity, Vec2::Zero());
}

TEST(Interaction, AMoveBelowTheMinimumDistanceReleasesAtRest) {
    World w = boxWorld();
    const ParticleId id = addAt(w, {100, 100});
    Interaction in;
    press(in, w, Vec2(100, 100), 0.0);
    const double t = drag(in, Vec2(100, 100), 0.0, Vec2(5, 0), 10);  // 0.5 m in 100 ms
    release(in, w, in.pointer(), t, {}, launch(), 1.0);              // minDistance 1 m
    EXPECT_EQ(w.get(id).velocity, Vec2::Zero());
}

TEST(Interaction, OffCentreGrabDoesNotDriftAfterRelease) {
    World w = boxWorld();
    const ParticleId id = addAt(w, {100, 100});
    Interaction in;
    press(in, w, Vec2(108, 104), 0.0);
    release(in, w, Vec2(108, 104), 0.5, {}, launch(), 1.0);
    EXPECT_EQ(w.get(id).velocity, Vec2::Zero());
    w.step(0.01);
    EXPECT_NEAR(w.get(id).position.x(), 100.0, 1e-12);
    EXPECT_NEAR(w.get(id).position.y(), 100.0, 1e-12);
}

TEST(Interaction, HeldParticlePushesOthersAndIsNotPushed) {
    World w = boxWorld();
    const ParticleId held = addAt(w, {100, 100}, 10.0, 1.0);
    const ParticleId other = addAt(w, {125, 100}, 10.0, 1000.0);
    Interaction in;
    press(in, w, Vec2(100, 100), 0.0);
    double t = 0.0;
    for (int k = 1; k <= 10; ++k) {  // move right at 100 m/s into the heavy particle
        t = 0.01 * k;
        in.moveTo(Vec2(100 + 100 * t, 100), t);
        applyHold(in, w, t, launch());
        w.step(0.01);
    }
    applyHold(in, w, t, launch());
    EXPECT_NEAR(w.get(held).position.x(), 110.0, 1e-9);  // exactly where the hand put it
    EXPECT_GT(w.get(other).velocity.x(), 0.0);           // the heavy one was pushed away
}

TEST(Interaction, HeldParticleStaysInTheBox) {
    World w = boxWorld();
    const ParticleId id = addAt(w, {100, 100}, 10.0);
    Interaction in;
    press(in, w, Vec2(100, 100), 0.0);
    in.moveTo(Vec2(-500, 900), 0.1);
    applyHold(in, w, 0.1, launch());
    EXPECT_NEAR(w.get(id).position.x(), 10.0, 1e-12);
    EXPECT_NEAR(w.get(id).position.y(), 690.0, 1e-12);
}

TEST(Interaction, DragOnEmptySpaceLaunchesFromThePressPointWithTheDragVelocity) {
    World w = boxWorld();
    Interaction in;
    SpawnSettings spawn;
    spawn.size = 0.4;  // 4 kg
    press(in, w, Vec2(200, 300), 0.0);
    EXPECT_EQ(in.mode(), Interaction::Mode::Launching);
    const double t = drag(in, Vec2(200, 300), 0.0, Vec2(-120, 80), 15);
    // 0.15 s of drag at (-120, 80) m/s: with a launch time of 0.15 s the velocity is the drag's.
    const ReleaseResult r = release(in, w, in.pointer(), t, spawn, launch(), 0.15);
    ASSERT_EQ(r.kind, ReleaseResult::Kind::Launched);
    ASSERT_EQ(w.size(), 1u);
    const Particle p = w.get(r.id);
    EXPECT_NEAR(p.position.x(), 200.0, 1e-12);
    EXPECT_NEAR(p.position.y(), 300.0, 1e-12);
    EXPECT_NEAR(p.velocity.x(), -120.0, 1e-6);
    EXPECT_NEAR(p.velocity.y(), 80.0, 1e-6);
    EXPECT_DOUBLE_EQ(p.mass, 4.0);
    EXPECT_DOUBLE_EQ(p.radius, 10.0);  // 2.5 m per kg
}

TEST(Interaction, DraggingOutAndStoppingLaunchesWithTheDragVectorNotAtRest) {
    World w = boxWorld();
    Interaction in;
    press(in, w, Vec2(200, 300), 0.0);
    in.moveTo(Vec2(260, 220), 0.05);  // out 100 m, then the hand holds still for half a second
    const ReleaseResult r = release(in, w, Vec2(260, 220), 0.55, {}, launch(), 0.5);
    ASSERT_EQ(r.kind, ReleaseResult::Kind::Launched);
    EXPECT_NEAR(r.velocity.x(), 120.0, 1e-9);  // (60, -80) m / 0.5 s
    EXPECT_NEAR(r.velocity.y(), -160.0, 1e-9);
    EXPECT_FALSE(r.capped);
}

TEST(Interaction, APreviewGivesTheVelocityTheLaunchWillHave) {
    World w = boxWorld();
    Interaction in;
    press(in, w, Vec2(200, 300), 0.0);
    in.moveTo(Vec2(230, 260), 0.05);
    const CappedVelocity preview = in.launchVelocityNow(launch(), 0.25);
    const ReleaseResult r = release(in, w, Vec2(230, 260), 0.9, {}, launch(), 0.25);
    EXPECT_EQ(r.velocity, preview.velocity);
    EXPECT_NEAR(preview.velocity.x(), 120.0, 1e-9);
}

TEST(Interaction, ACappedLaunchSaysSo) {
    World w = boxWorld();
    Interaction in;
    LaunchSettings l = launch();
    l.maxSpeed = 50.0;
    press(in, w, Vec2(100, 100), 0.0);
    in.moveTo(Vec2(400, 500), 0.1);  // 500 m in a launch time of 1 s: 500 m/s
    const ReleaseResult r = release(in, w, Vec2(400, 500), 0.2, {}, l, 1.0);
    ASSERT_EQ(r.kind, ReleaseResult::Kind::Launched);
    EXPECT_TRUE(r.capped);
    EXPECT_NEAR(r.velocity.norm(), 50.0, 1e-9);
    EXPECT_NEAR(r.velocity.x() / r.velocity.y(), 0.75, 1e-12);  // direction kept
}

TEST(Interaction, ALaunchNeverOverlapsAnotherParticle) {
    World w = boxWorld();
    SpawnSettings spawn;  // 10 kg, radius 25 m
    // A press on empty space just beside a particle: the new one would overlap it.
    addAt(w, {300, 300}, 20.0);
    Interaction in;
    press(in, w, Vec2(330, 300), 0.0);
    // A still press longer than a click places a particle at rest.
    const ReleaseResult r = release(in, w, Vec2(330, 300), 0.5, spawn, launch(), 1.0);
    ASSERT_EQ(r.kind, ReleaseResult::Kind::Launched);
    EXPECT_NEAR(maxOverlapBruteForce(w), 0.0, 1e-12);
    // The nearest free spot: touching distance (45 m) plus at most one ring step (12.5 m).
    const double d = (r.position - Vec2(330, 300)).norm();
    EXPECT_LE(d, 45.0 - 30.0 + 12.5 + 1e-9);
}

TEST(Interaction, ALaunchWithNoRoomIsRefusedWithAMessage) {
    WorldDef def;
    def.width = 60.0;
    def.height = 60.0;
    World w(def);
    addAt(w, {30, 30}, 25.0);
    Interaction in;
    press(in, w, Vec2(5, 5), 0.0);  // outside the disc, but the box is full
    const ReleaseResult r = release(in, w, Vec2(5, 5), 0.5, SpawnSettings{}, launch(), 1.0);
    EXPECT_EQ(r.kind, ReleaseResult::Kind::Refused);
    EXPECT_FALSE(r.message.empty());
    EXPECT_EQ(w.size(), 1u);
}

/// A 10 m particle at (100, 100) m moving at (30, -40) m/s.
ParticleId addMoving(World& w) {
    ParticleDef d;
    d.position = {100, 100};
    d.velocity = {30, -40};
    d.radius = 10.0;
    return w.add(d);
}

TEST(Interaction, AClickOnAParticleSelectsItAndKeepsItsVelocity) {
    World w = boxWorld();
    const ParticleId id = addMoving(w);
    Interaction in;
    press(in, w, Vec2(104, 100), 0.0);
    in.moveTo(Vec2(104.5, 100), 0.05);  // 0.5 m: under the 1 m threshold
    const ReleaseResult r = release(in, w, Vec2(104.5, 100), 0.1, {}, launch(), 1.0);
    EXPECT_EQ(r.kind, ReleaseResult::Kind::Clicked);
    EXPECT_EQ(r.id, id);
    EXPECT_EQ(w.get(id).velocity, Vec2(30, -40));
    EXPECT_FALSE(w.isKinematic(id));
    EXPECT_EQ(in.mode(), Interaction::Mode::Idle);
}

TEST(Interaction, AClickOnEmptySpaceLaunchesNothing) {
    World w = boxWorld();
    Interaction in;
    press(in, w, Vec2(200, 200), 0.0);
    const ReleaseResult r = release(in, w, Vec2(200, 200), 0.1, {}, launch(), 1.0);
    EXPECT_EQ(r.kind, ReleaseResult::Kind::Clicked);
    EXPECT_TRUE(r.id.isNull());
    EXPECT_EQ(w.size(), 0u);
}

TEST(Interaction, APressThatMovedPastTheThresholdIsADragNotAClick) {
    // Out 3 m and back to the press point within 0.1 s: the way back does not make it a click.
    World w = boxWorld();
    const ParticleId id = addAt(w, {100, 100});
    Interaction in;
    press(in, w, Vec2(100, 100), 0.0);
    in.moveTo(Vec2(103, 100), 0.03);
    in.moveTo(Vec2(100, 100), 0.06);
    EXPECT_EQ(release(in, w, Vec2(100, 100), 0.1, {}, launch(), 1.0).kind,
              ReleaseResult::Kind::Flung);
    EXPECT_TRUE(w.contains(id));
    press(in, w, Vec2(300, 300), 1.0);
    in.moveTo(Vec2(303, 300), 1.03);
    EXPECT_EQ(release(in, w, Vec2(300, 300), 1.1, {}, launch(), 1.0).kind,
              ReleaseResult::Kind::Launched);
}

TEST(Interaction, AStillPressLongerThanAClickReleasesTheParticleAtRest) {
    World w = boxWorld();
    const ParticleId id = addMoving(w);
    Interaction in;
    press(in, w, Vec2(100, 100), 0.0);
    const double t = Interaction::kClickSeconds + 0.01;
    EXPECT_EQ(release(in, w, Vec2(100, 100), t, {}, launch(), 1.0).kind,
              ReleaseResult::Kind::Flung);
    EXPECT_EQ(w.get(id).velocity, Vec2::Zero());
}

TEST(Interaction, DeleteWhileHeldRemovesOnlyThatParticle) {
    World w = boxWorld();
    const ParticleId a = addAt(w, {100, 100});
    const ParticleId b = addAt(w, {300, 100});
    Interaction in;
    press(in, w, Vec2(300, 100), 0.0);
    const auto gone = deleteHeld(in, w);
    ASSERT_TRUE(gone.has_value());
    EXPECT_EQ(gone->id, b);
    EXPECT_FALSE(w.contains(b));
    EXPECT_TRUE(w.contains(a));
    EXPECT_EQ(in.mode(), Interaction::Mode::Idle);
    // Nothing held: nothing deleted, and the release that follows does nothing.
    EXPECT_FALSE(deleteHeld(in, w).has_value());
    EXPECT_EQ(release(in, w, Vec2(300, 100), 0.1, {}, launch(), 1.0).kind,
              ReleaseResult::Kind::None);
    EXPECT_EQ(w.size(), 1u);
}

TEST(Interaction, DeletionLogLineNamesPositionVelocityAndMassWithUnits) {
    Particle p;
    p.position = {350.0, 120.5};
    p.velocity = {12.3, -4.0};
    p.mass = 10.0;
    EXPECT_EQ(deletionLogLine(p, Axes{}),
              "[I] Deleted particle at [350.00, 120.50] with x velocity 12.30 m/s, y velocity "
              "-4.00 m/s and mass 10.00 kg!");
    // With y up (a 400 m box), as the window shows it.
    EXPECT_EQ(deletionLogLine(p, Axes{true, 400.0}),
              "[I] Deleted particle at [350.00, 279.50] with x velocity 12.30 m/s, y velocity "
              "4.00 m/s and mass 10.00 kg!");
}

TEST(FindFreeSpot, ReturnsTheDesiredPointWhenItIsFree) {
    World w = boxWorld();
    addAt(w, {100, 100}, 10.0);
    const auto s = findFreeSpot(w, Vec2(400, 400), 20.0);
    ASSERT_TRUE(s.has_value());
    EXPECT_EQ(*s, Vec2(400, 400));
}

TEST(FindFreeSpot, ClampsIntoTheBox) {
    World w = boxWorld();
    const auto s = findFreeSpot(w, Vec2(-50, 10), 20.0);
    ASSERT_TRUE(s.has_value());
    EXPECT_EQ(*s, Vec2(20, 20));
}

TEST(FindFreeSpot, KeepsClearOfPegsAndWalls) {
    // A spawn (M) or a launch on a wall once put the new particle inside it, impaled on the
    // wall for good in the exact mode (seen by a new user on the Ramp preset).
    World w = boxWorld();
    w.addObstacle(Obstacle::segment({100, 400}, {600, 400}, 10.0));  // 5 m either side of y = 400
    w.addObstacle(Obstacle::peg({200, 200}, 30.0));
    for (const Vec2& want : {Vec2(300, 400), Vec2(300, 410), Vec2(100, 400), Vec2(200, 200)}) {
        const auto s = findFreeSpot(w, want, 20.0);
        ASSERT_TRUE(s.has_value());
        const double toWall = std::abs(s->y() - 400.0);
        if (s->x() >= 100.0 && s->x() <= 600.0) {
            EXPECT_GE(toWall, 25.0 - 1e-9) << want.transpose();
        }
        EXPECT_GE((*s - Vec2(200, 200)).norm(), 50.0 - 1e-9) << want.transpose();
        EXPECT_LE((*s - want).norm(), 60.0) << "a near free spot, not a far one";
    }
}

TEST(SpawnSettings, NewParticlesAreTheScenesTypicalOneTimesTheSize) {
    SpawnSettings s;
    // An empty 700 m box: the original's 10 kg, 25 m particle, 2.5 m per kg.
    followScene(s, boxWorld());
    EXPECT_DOUBLE_EQ(s.mass(), 10.0);
    EXPECT_DOUBLE_EQ(s.radius(), 25.0);
    s.changeSize(-2);
    EXPECT_DOUBLE_EQ(s.mass(), 8.0);
    EXPECT_DOUBLE_EQ(s.radius(), 20.0);
    // A board of 5 mm, 0.5 g grains (and one big ball): new particles are grains.
    WorldDef def;
    def.width = 0.5;
    def.height = 0.9;
    World board(def);
    for (int k = 0; k < 5; ++k) {
        ParticleDef g;
        g.position = {0.05 + 0.02 * k, 0.1};
        g.radius = 0.005;
        g.mass = 0.0005;
        board.add(g);
    }
    ParticleDef ball;
    ball.position = {0.3, 0.5};
    ball.radius = 0.1;
    ball.mass = 2.0;
    board.add(ball);
    s.size = 1.0;
    followScene(s, board);
    EXPECT_DOUBLE_EQ(s.mass(), 0.0005);
    EXPECT_DOUBLE_EQ(s.radius(), 0.005);
    // An empty small box: the original's particle at the box's scale.
    followScene(s, World(def));
    EXPECT_DOUBLE_EQ(s.mass(), 10.0);
    EXPECT_NEAR(s.radius(), 25.0 * 0.5 / 700.0, 1e-15);
}

TEST(SpawnSettings, SizeStaysInItsRangeAndComesBackExactly) {
    SpawnSettings s;
    for (int k = 0; k < 100; ++k)
        s.changeSize(-1);
    EXPECT_DOUBLE_EQ(s.size, SpawnSettings::kMinSize);
    for (int k = 0; k < 100; ++k)
        s.changeSize(1);
    EXPECT_DOUBLE_EQ(s.size, SpawnSettings::kMaxSize);
    s.size = 1.0;
    for (int k = 0; k < 7; ++k)
        s.changeSize(1);
    for (int k = 0; k < 7; ++k)
        s.changeSize(-1);
    EXPECT_EQ(s.size, 1.0);
}

}  // namespace
}  // namespace psb::app
