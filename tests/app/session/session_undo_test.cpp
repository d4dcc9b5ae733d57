// Undo, redo and stepping back in time through the session, as the keys and buttons drive it:
// each kind of edit undone to the state before it, and past frames shown bit for bit.

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include <particle_sandbox/presets.hpp>
#include <particle_sandbox/scene.hpp>

#include "session/keys.hpp"
#include "session/same_world.hpp"
#include "session/session.hpp"
#include "session/session_fixture.hpp"
#include "session/test_assets.hpp"

namespace psb::app {
namespace {

constexpr double kFrame = 1.0 / 60.0;

SessionOptions options(bool paused = true) {
    SessionOptions o;
    o.saveTo = std::filesystem::temp_directory_path() / "psb-undo-test-save.json";
    o.seed = 3;
    o.paused = paused;
    o.presets = {testAsset("scenes/03-billiards-break.json")};
    return o;
}

Session session(bool paused = true) {
    return Session(makeWorld(defaultScene()), SceneInfo{.name = "default", .dt = 1.0 / 60.0},
                   options(paused));
}

/// A press at `from`, ten moves to `to` over 0.1 s, a release there: a fling or a launch.
/// Each move is a 60 Hz frame; `shown` collects the worlds they show.
void dragFrames(Session& s, Vec2 from, Vec2 to, double t0, std::vector<World>* shown = nullptr) {
    const Camera& c = s.camera();
    s.apply(cmd::PointerDown{c.worldToScreen(from), t0});
    for (int k = 1; k <= 10; ++k) {
        const double t = t0 + kFrame * k;
        s.apply(cmd::PointerMove{c.worldToScreen(from + (to - from) * (k / 10.0)), t});
        s.update(kFrame, t);
        if (shown) shown->push_back(s.world());
    }
    s.apply(cmd::PointerUp{c.worldToScreen(to), t0 + kFrame * 10});
}

/// Frames at 60 Hz from `now`; returns the clock after them.
double run(Session& s, int frames, double now, std::vector<World>* shown = nullptr) {
    for (int f = 0; f < frames; ++f) {
        now += kFrame;
        s.update(kFrame, now);
        if (shown) shown->push_back(s.world());
    }
    return now;
}

/// Where the Replay slider's handle sits for `t`: 0 at its left end, 1 at its right end.
double handle(const TimelineView& t) {
    const auto [lo, hi] = t.sliderRange();
    return (t.current - lo) / (hi - lo);
}

TEST(SessionUndo, TheReplayHandleStaysAtThePresentThroughAnUndo) {
    // Two seconds run and paused: the present, labelled 2.00 s, at the slider's right end. An
    // edit and its undo clear the record; the state shown is still the present, and the handle
    // stays where the label says it is (it used to jump to the left end, labelled the same).
    Session s = session(false);
    double now = run(s, 120, 0.0);
    s.apply(cmd::TogglePause{});
    EXPECT_DOUBLE_EQ(handle(s.timeline()), 1.0);
    s.apply(cmd::SpawnRandom{});
    now = run(s, 2, now);
    s.apply(cmd::Undo{});
    const TimelineView t = s.timeline();
    EXPECT_DOUBLE_EQ(t.current, s.world().time()) << "the label is the time shown";
    EXPECT_DOUBLE_EQ(handle(t), 1.0) << "the handle is at the present";
    // Back in the recorded past the handle follows the frame shown.
    s.apply(cmd::TogglePause{});
    now = run(s, 60, now);
    s.apply(cmd::TogglePause{});
    s.apply(cmd::SeekBy{-0.5});
    EXPECT_GT(handle(s.timeline()), 0.0);
    EXPECT_LT(handle(s.timeline()), 1.0);
    EXPECT_NEAR(s.timeline().current, s.world().time(), 1e-9);
}

TEST(SessionUndo, UndoesASpawnAndRedoesIt) {
    Session s = session();
    const World before = s.world();
    EXPECT_FALSE(s.canUndo());
    s.apply(cmd::SpawnRandom{});
    const World after = s.world();
    ASSERT_EQ(after.size(), before.size() + 1);
    EXPECT_TRUE(s.canUndo());
    EXPECT_EQ(s.undoLabel(), "spawn particle");
    (void)s.takeNotices();
    s.apply(cmd::Undo{});
    EXPECT_TRUE(said(s.takeNotices(), "Undone: spawn particle"));
    EXPECT_TRUE(identical(s.world(), before));
    EXPECT_FALSE(s.unsavedChanges());
    EXPECT_EQ(s.redoLabel(), "spawn particle");
    s.apply(cmd::Redo{});
    EXPECT_TRUE(identical(s.world(), after));
    EXPECT_TRUE(s.unsavedChanges());
    s.apply(cmd::Redo{});
    EXPECT_TRUE(said(s.takeNotices(), "Nothing to redo"));
}

TEST(SessionUndo, UndoesALaunchAndAFling) {
    Session s = session();
    const World before = s.world();
    dragFrames(s, Vec2(1.0, 6.0), Vec2(2.0, 5.0), 1.0);  // empty space: a launch
    ASSERT_EQ(s.world().size(), before.size() + 1);
    EXPECT_EQ(s.undoLabel(), "launch particle");
    const World launched = s.world();
    const ParticleId yellow = *s.world().pick(Vec2(5.2, 1.6));
    dragFrames(s, Vec2(5.2, 1.6), Vec2(5.2, 2.6), 2.0);  // a particle: a fling
    EXPECT_EQ(s.undoLabel(), "fling particle");
    EXPECT_GT(s.world().get(yellow).velocity.y(), 0.0);
    s.apply(cmd::Undo{});
    EXPECT_TRUE(identical(s.world(), launched));
    EXPECT_FALSE(s.world().isKinematic(yellow));
    s.apply(cmd::Undo{});
    EXPECT_TRUE(identical(s.world(), before));
}

TEST(SessionUndo, UndoesADeletionOfTheHeldParticle) {
    Session s = session();
    const World before = s.world();
    const ParticleId yellow = *s.world().pick(Vec2(5.2, 1.6));
    s.apply(cmd::PointerDown{s.camera().worldToScreen(Vec2(5.2, 1.6)), 1.0});
    s.update(kFrame, 1.0);
    s.apply(cmd::DeleteHeld{});
    s.apply(cmd::PointerUp{s.camera().worldToScreen(Vec2(5.2, 1.6)), 1.1});
    ASSERT_FALSE(s.world().contains(yellow));
    EXPECT_EQ(s.undoLabel(), "delete particle");
    s.apply(cmd::Undo{});
    ASSERT_TRUE(s.world().contains(yellow));
    EXPECT_FALSE(s.world().isKinematic(yellow));  // free again, not stuck in a hand
    EXPECT_EQ(s.world().get(yellow).position, before.get(yellow).position);
    EXPECT_EQ(s.world().size(), before.size());
}

TEST(SessionUndo, DeleteRemovesTheSelectedParticleUndoably) {
    // A teacher clicked a particle and pressed Delete: nothing happened, silently.
    Session s = session();
    const World before = s.world();
    const ParticleId yellow = *s.world().pick(Vec2(5.2, 1.6));
    const Vec2 at = s.camera().worldToScreen(Vec2(5.2, 1.6));
    s.apply(cmd::PointerDown{at, 1.0});
    s.apply(cmd::PointerUp{at, 1.05});  // a click: selects it
    ASSERT_EQ(s.selection().id(), yellow);
    s.apply(cmd::DeleteHeld{});
    EXPECT_FALSE(s.world().contains(yellow));
    EXPECT_EQ(s.world().size(), before.size() - 1);
    EXPECT_FALSE(s.selection().id().has_value());
    EXPECT_EQ(s.undoLabel(), "delete particle");
    s.apply(cmd::Undo{});
    EXPECT_TRUE(identical(s.world(), before));
    EXPECT_EQ(s.selection().id(), yellow);  // selected again, as before the delete
}

TEST(SessionUndo, AGrabDragAndDeleteIsOneEditAndALaunchKeepsItsOwn) {
    Session s = session();
    const World before = s.world();
    const ParticleId yellow = *s.world().pick(Vec2(5.2, 1.6));
    const Camera& c = s.camera();
    s.apply(cmd::PointerDown{c.worldToScreen(Vec2(5.2, 1.6)), 1.0});
    s.apply(cmd::PointerMove{c.worldToScreen(Vec2(5.0, 2.4)), 1.05});
    s.update(kFrame, 1.05);
    s.apply(keys::restitution(s, -1));  // a key while holding: its own entry
    s.apply(cmd::DeleteHeld{});
    s.apply(cmd::PointerUp{c.worldToScreen(Vec2(5.0, 2.4)), 1.1});
    EXPECT_EQ(s.undoHistory().undoCount(), 2u);
    s.apply(cmd::Undo{});  // the particle is back where it was before the grab
    ASSERT_TRUE(s.world().contains(yellow));
    EXPECT_EQ(s.world().get(yellow).position, before.get(yellow).position);
    // Delete pressed during a launch deletes nothing; the launch is still one undoable edit.
    const std::size_t n = s.world().size();
    s.apply(cmd::PointerDown{c.worldToScreen(Vec2(1.0, 6.0)), 2.0});
    s.apply(cmd::PointerMove{c.worldToScreen(Vec2(2.0, 5.0)), 2.1});
    s.apply(cmd::DeleteHeld{});
    s.apply(cmd::PointerUp{c.worldToScreen(Vec2(2.0, 5.0)), 2.2});
    ASSERT_EQ(s.world().size(), n + 1);
    EXPECT_EQ(s.undoLabel(), "launch particle");
    s.apply(cmd::Undo{});
    EXPECT_EQ(s.world().size(), n);
}

TEST(SessionUndo, UndoesAnEditOfTheSelectedParticle) {
    Session s = session();
    const Vec2 yellow(5.2, 1.6);
    s.apply(cmd::PointerDown{s.camera().worldToScreen(yellow), 1.0});
    s.apply(cmd::PointerUp{s.camera().worldToScreen(yellow), 1.05});
    const ParticleId id = *s.selection().id();
    const double mass = s.world().get(id).mass;
    s.apply(cmd::OpenEdit{});
    s.apply(cmd::EditType{"2e1"});
    s.apply(cmd::EditApply{});
    ASSERT_EQ(s.world().get(id).mass, 20.0);
    EXPECT_EQ(s.undoLabel(), "edit particle");
    s.apply(cmd::Undo{});
    EXPECT_EQ(s.world().get(id).mass, mass);
    EXPECT_EQ(s.selection().id(), id);  // the selection comes back with the state
}

TEST(SessionUndo, UndoesAPresetAndAReset) {
    Session s = session();
    const World original = s.world();
    s.apply(cmd::SpawnRandom{});
    s.apply(cmd::OpenPreset{0});
    ASSERT_NE(s.meta().name, "default");
    const World preset = s.world();
    EXPECT_EQ(s.undoLabel(), "open scene");
    s.apply(cmd::Undo{});
    EXPECT_EQ(s.meta().name, "default");
    EXPECT_EQ(s.world().size(), original.size() + 1);
    EXPECT_TRUE(identical(s.loadedWorld(), original));
    EXPECT_TRUE(s.unsavedChanges());  // the spawn is unsaved again
    s.apply(cmd::Restart{});
    EXPECT_TRUE(identical(s.world(), original));
    s.apply(cmd::Undo{});
    EXPECT_EQ(s.world().size(), original.size() + 1);
    s.apply(cmd::Redo{});
    s.apply(cmd::Redo{});  // the preset again (the reset was a new edit: it forgot the redo)
    EXPECT_TRUE(said(s.takeNotices(), "Nothing to redo"));
    EXPECT_TRUE(identical(s.world(), original));
}

TEST(SessionUndo, UndoesPhysicsSettingsAndCoalescesRepeatedPresses) {
    Session s = session();
    const double e = s.world().def().restitution;
    s.update(kFrame, 1.0);
    for (int k = 0; k < 4; ++k)
        s.apply(keys::restitution(s, -1));  // within a second: one entry
    ASSERT_LT(s.world().def().restitution, e - 0.15);
    EXPECT_EQ(s.undoHistory().undoCount(), 1u);
    s.apply(keys::gravity(s));
    s.apply(keys::mode(s));
    EXPECT_EQ(s.undoLabel(), "change mode");
    s.apply(cmd::Undo{});
    EXPECT_EQ(s.world().solver().mode, StepMode::Discrete);
    EXPECT_NE(s.world().def().gravity, Vec2::Zero());
    s.apply(cmd::Undo{});
    EXPECT_EQ(s.world().def().gravity, Vec2::Zero());
    s.apply(cmd::Undo{});
    EXPECT_EQ(s.world().def().restitution, e);
    // Presses more than a second apart are separate entries.
    s.apply(keys::restitution(s, -1));
    s.update(kFrame, 3.0);
    s.apply(keys::restitution(s, -1));
    EXPECT_EQ(s.undoHistory().undoCount(), 2u);
    // The time speed and the new particles' size are undone too.
    s.apply(keys::timeSpeed(s, 2.0));
    s.apply(keys::timeSpeed(s, 2.0));
    s.apply(cmd::ChangeSpawnMass{+1});
    s.apply(cmd::Undo{});
    s.apply(cmd::Undo{});
    EXPECT_EQ(s.timeScale(), 1.0);
}

TEST(SessionUndo, KeepsAHundredStepsAndUndoingAnEditWhileRunningTakesTheClockBack) {
    Session s = session(false);
    double now = run(s, 10, 0.0);
    for (int k = 0; k < 120; ++k) {
        s.apply(keys::gravity(s));
        now = run(s, 1, now);
    }
    const double t = s.world().time();
    int undone = 0;
    while (s.canUndo() && undone < 200) {
        s.apply(cmd::Undo{});
        ++undone;
    }
    EXPECT_EQ(undone, 120);
    EXPECT_LT(s.world().time(), t);
    EXPECT_EQ(s.world().time(), 10 * kFrame);  // the world of the first edit's moment
    EXPECT_EQ(s.world().def().gravity, Vec2::Zero());
}

TEST(SessionUndo, SaysWhenAnUndoOrRedoTakesTheClockBackOrForward) {
    // An edit while paused at 1.00 s, a run to 2.00 s, an undo: the whole state, clock
    // included, goes back to 1.00 s, and the message says so; the redo says where it goes.
    Session s = session(false);
    double now = run(s, 60, 0.0);
    s.apply(cmd::TogglePause{});
    s.apply(cmd::SpawnRandom{});
    s.apply(cmd::TogglePause{});
    now = run(s, 60, now);
    ASSERT_GT(s.world().time(), 1.9);
    (void)s.takeNotices();
    s.apply(cmd::Undo{});
    EXPECT_TRUE(said(s.takeNotices(), "Undone: spawn particle (back to 1.00 s)"));
    EXPECT_NEAR(s.world().time(), 1.0, 1e-9);
    s.apply(cmd::Redo{});
    EXPECT_TRUE(said(s.takeNotices(), "Redone: spawn particle (forward to 2.00 s)"));
    // An undo that leaves the clock where it is says nothing about time.
    s.apply(cmd::TogglePause{});
    s.apply(cmd::SpawnRandom{});
    s.apply(cmd::Undo{});
    const auto notices = s.takeNotices();
    EXPECT_TRUE(said(notices, "Undone: spawn particle"));
    EXPECT_FALSE(said(notices, " to "));
}

class SessionStepBack : public ::testing::TestWithParam<StepMode> {};

/// A running session in `mode` with a 10 s history of the default scene plus spawns.
Session runningIn(StepMode mode) {
    World w = makeWorld(defaultScene());
    SolverSettings solver = w.solver();
    solver.mode = mode;
    w.setSolver(solver);
    w.setThreads(1);
    return Session(std::move(w), SceneInfo{.name = "default", .dt = 1.0 / 60.0}, options(false));
}

TEST_P(SessionStepBack, ShowsEachPastFrameBitForBitAndComesBackToThePresent) {
    Session s = runningIn(GetParam());
    std::vector<World> shown;
    double now = run(s, 40, 0.0, &shown);
    // A fling: the frames of the drag replay the hand's moves.
    dragFrames(s, Vec2(5.2, 1.6), Vec2(4.0, 3.0), now, &shown);
    now = run(s, 20, now + 10 * kFrame, &shown);
    s.apply(cmd::TogglePause{});
    now = run(s, 1, now);
    const World present = s.world();
    for (int k = 1; k <= 45; ++k) {
        s.apply(cmd::StepBack{});
        s.update(kFrame, now += kFrame);
        ASSERT_TRUE(s.timeline().viewingPast);
        ASSERT_TRUE(identical(s.world(), shown[shown.size() - 1 - k], false)) << "frame -" << k;
    }
    EXPECT_NEAR(s.timeline().secondsBack(), 45 * kFrame, 1e-9);
    for (int k = 44; k >= 1; --k) {
        s.apply(cmd::StepForward{});
        ASSERT_TRUE(identical(s.world(), shown[shown.size() - 1 - k], false)) << "frame -" << k;
    }
    s.apply(cmd::StepForward{});
    EXPECT_FALSE(s.timeline().viewingPast);
    EXPECT_TRUE(identical(s.world(), present, false));
    // Scrubbing to a time shows the frame at or before it.
    s.apply(cmd::Seek{shown[10].time() + 0.25 * kFrame});
    EXPECT_TRUE(identical(s.world(), shown[10], false));
    s.apply(cmd::SeekBy{-100.0});  // to the oldest frame held
    EXPECT_EQ(s.world().time(), s.timeline().earliest);
}

TEST_P(SessionStepBack, AnEditInThePastForgetsTheFramesAfterItAndIsUndoable) {
    Session s = runningIn(GetParam());
    std::vector<World> shown;
    double now = run(s, 60, 0.0, &shown);
    s.apply(cmd::TogglePause{});
    for (int k = 0; k < 20; ++k)
        s.apply(cmd::StepBack{});
    const World past = s.world();
    ASSERT_TRUE(identical(past, shown[shown.size() - 21], false));
    s.apply(cmd::SpawnRandom{});
    ASSERT_EQ(s.world().size(), past.size() + 1);
    EXPECT_FALSE(s.timeline().viewingPast);
    now = run(s, 1, now);
    EXPECT_EQ(s.timeline().latest, past.time());  // the old future is gone
    s.apply(cmd::StepForward{});                  // the present: a new step
    now = run(s, 1, now);
    EXPECT_GT(s.world().time(), past.time());
    s.apply(cmd::Undo{});
    EXPECT_TRUE(identical(s.world(), past));
    // Resuming from the past carries on from there.
    s.apply(cmd::TogglePause{});  // running
    now = run(s, 30, now);
    s.apply(cmd::TogglePause{});
    for (int k = 0; k < 5; ++k)
        s.apply(cmd::StepBack{});
    const double t = s.world().time();
    s.apply(cmd::TogglePause{});
    EXPECT_TRUE(said(s.takeNotices(), "the later frames are forgotten"));
    now = run(s, 1, now);
    EXPECT_GT(s.world().time(), t);
    EXPECT_FALSE(s.timeline().viewingPast);
}

TEST_P(SessionStepBack, CoversTenSecondsAndSaysWhereThePastEnds) {
    Session s = runningIn(GetParam());
    double now = run(s, 12 * 60, 0.0);
    s.apply(cmd::TogglePause{});
    const TimelineView v = s.timeline();
    EXPECT_GE(v.latest - v.earliest, 10.0);
    s.apply(cmd::Seek{v.earliest});
    EXPECT_EQ(s.world().time(), v.earliest);
    (void)s.takeNotices();
    s.apply(cmd::StepBack{});
    EXPECT_TRUE(said(s.takeNotices(), "The recorded past starts at"));
    s.apply(cmd::Seek{v.latest});
    EXPECT_FALSE(s.timeline().viewingPast);
    (void)now;
}

INSTANTIATE_TEST_SUITE_P(Modes, SessionStepBack,
                         ::testing::Values(StepMode::Discrete, StepMode::Substep, StepMode::Exact),
                         [](const auto& p) { return std::string(toString(p.param)); });

}  // namespace
}  // namespace psb::app
