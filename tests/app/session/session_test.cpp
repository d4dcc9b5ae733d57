// The session without a window: commands in, world, view and notices out. Each defect of the
// issue that lives in the session has a test here that failed before its fix.

#include <gtest/gtest.h>

#include <unistd.h>
#include <algorithm>
#include <filesystem>

#include <particle_sandbox/diagnostics.hpp>
#include <particle_sandbox/error.hpp>
#include <particle_sandbox/presets.hpp>
#include <particle_sandbox/scene.hpp>

#include "core/test_util.hpp"
#include "session/keys.hpp"
#include "session/scene_io.hpp"
#include "session/session.hpp"
#include "session/session_fixture.hpp"
#include "session/test_assets.hpp"
#include "session/units.hpp"

namespace psb::app {
namespace {

namespace fs = std::filesystem;

class SessionTest : public SessionFixture {
  protected:
    SessionTest() : SessionFixture("psb-session", TestWindow{}) {}
};

TEST_F(SessionTest, TheDefaultSceneIsAtHumanScale) {
    const Session s = session();
    const World& w = s.world();
    EXPECT_DOUBLE_EQ(w.def().width, 7.0);  // the original's 700 px at 1 px = 1 cm
    EXPECT_DOUBLE_EQ(w.def().height, 7.0);
    const ParticleArrays& p = w.particles();
    for (std::size_t i = 0; i < p.size(); ++i) {
        EXPECT_GE(p.radius[i], 0.075);
        EXPECT_LE(p.radius[i], 0.5);
        EXPECT_GE(p.mass[i], 3.0);
        EXPECT_LE(p.mass[i], 20.0);
        EXPECT_LE(std::hypot(p.vx[i], p.vy[i]), 5.0);  // a few m/s
    }
    // New particles follow the scene: 10 kg at the median radius, tens of centimetres.
    EXPECT_GT(s.spawn().radius(), 0.1);
    EXPECT_LT(s.spawn().radius(), 0.5);
}

TEST_F(SessionTest, TheBrownianPresetOpensWithItsHeavyDiscsTrailShown) {
    Session s = session();
    ASSERT_EQ(s.view().trails, TrailMode::Off);
    s.apply(cmd::OpenFile{testAsset("scenes/08-brownian-motion.json")});
    EXPECT_EQ(s.view().trails, TrailMode::Selected);
    ASSERT_TRUE(s.selection().id().has_value());
    EXPECT_EQ(s.trailParticle(), *s.selection().id());
    // The heavy disc is the scene's particle 0: the largest of them.
    double largest = 0.0;
    for (const double r : s.world().particles().radius)
        largest = std::max(largest, r);
    EXPECT_EQ(s.world().get(*s.selection().id()).radius, largest);
}

TEST_F(SessionTest, ASecondFingerEndsThePressWithoutAClickOrALaunch) {
    // A pinch begins where the first finger came down on empty space: its press ends
    // (platform/touch.hpp) without clearing the selection or launching a particle.
    Session s = session();
    s.apply(cmd::OpenFile{testAsset("scenes/08-brownian-motion.json")});
    ASSERT_TRUE(s.selection().id().has_value());
    const std::size_t n = s.world().size();
    (void)s.takeNotices();
    const Camera& c = s.camera();
    std::optional<Vec2> empty;
    for (double x = 0.05; x < s.world().def().width && !empty; x += 0.01) {
        for (double y = 0.05; y < s.world().def().height && !empty; y += 0.01) {
            if (!s.world().pick(Vec2(x, y))) empty = Vec2(x, y);
        }
    }
    ASSERT_TRUE(empty.has_value());
    s.apply(cmd::PointerDown{c.worldToScreen(*empty), 1.0});
    s.apply(cmd::PointerUp{c.worldToScreen(*empty), 1.05, true});
    EXPECT_TRUE(s.selection().id().has_value());
    EXPECT_FALSE(said(s.takeNotices(), "Selection cleared"));
    // The first finger moved as far as a launch before the second came: nothing is launched.
    s.apply(cmd::PointerDown{c.worldToScreen(*empty), 2.0});
    s.apply(cmd::PointerMove{c.worldToScreen(*empty) + Vec2(60.0, 0.0), 2.1});
    s.apply(cmd::PointerUp{c.worldToScreen(*empty) + Vec2(60.0, 0.0), 2.15, true});
    EXPECT_EQ(s.world().size(), n);
    EXPECT_TRUE(s.selection().id().has_value());
    // Without a second finger the same click clears the selection, as before.
    s.apply(cmd::PointerDown{c.worldToScreen(*empty), 3.0});
    s.apply(cmd::PointerUp{c.worldToScreen(*empty), 3.05});
    EXPECT_FALSE(s.selection().id().has_value());
}

TEST_F(SessionTest, TheBrownianPresetGivenAtStartUpShowsItsTrailToo) {
    const Scene scene = loadScene(testAsset("scenes/08-brownian-motion.json"));
    Session s(makeWorld(scene), sceneInfo(scene, std::nullopt), options());
    EXPECT_EQ(s.view().trails, TrailMode::Selected);
    ASSERT_TRUE(s.selection().id().has_value());
    EXPECT_EQ(s.world().get(*s.selection().id()).radius, 0.08);
}

TEST_F(SessionTest, GravityIsEarthsInTheDefaultScene) {
    Session s = session();
    s.apply(keys::gravity(s));
    EXPECT_EQ(s.world().def().gravity, Vec2(0.0, 9.81));
}

TEST_F(SessionTest, CommandsAreTheOnlyWayInAndEachSaysWhatItDid) {
    Session s = session();
    (void)s.takeNotices();
    s.apply(keys::show(s, ShowOption::Labels));
    EXPECT_TRUE(s.view().labels);
    s.apply(keys::show(s, ShowOption::Arrows));
    EXPECT_FALSE(s.view().arrows);
    s.apply(keys::timeSpeed(s, 2.0));
    EXPECT_DOUBLE_EQ(s.timeScale(), 2.0);
    s.apply(keys::timeSpeed(s, 1e9));
    EXPECT_DOUBLE_EQ(s.timeScale(), Session::kMaxTimeScale);
    const auto n = s.takeNotices();
    EXPECT_TRUE(said(n, "Labels on"));
    EXPECT_TRUE(said(n, "Arrows off"));
    EXPECT_TRUE(said(n, "Time speed x8"));
    EXPECT_TRUE(s.takeNotices().empty());  // taken once
}

TEST_F(SessionTest, PausedTheWorldStepsOnlyOnASingleStep) {
    Session s = session();
    s.update(1.0, 0.0);
    EXPECT_EQ(s.world().time(), 0.0);
    s.apply(cmd::SingleStep{});
    s.update(0.0, 0.0);
    EXPECT_DOUBLE_EQ(s.world().time(), s.meta().dt);
}

TEST_F(SessionTest, ModeCyclingUnderGravityVisitsEveryMode) {
    Session s = session();
    s.apply(keys::gravity(s));
    std::vector<StepMode> seen;
    for (int k = 0; k < 3; ++k) {
        const StepMode before = s.world().solver().mode;
        s.apply(keys::mode(s));
        EXPECT_NE(s.world().solver().mode, before) << "press " << k;
        seen.push_back(s.world().solver().mode);
    }
    EXPECT_EQ(seen,
              (std::vector<StepMode>{StepMode::Substep, StepMode::Exact, StepMode::Discrete}));
}

TEST_F(SessionTest, HTurnsTheHelpsPagesAndClosesItAfterTheLast) {
    SessionOptions o = options();
    o.layout.helpPages = 2;  // as the view pages the help in a 600 × 600 window
    o.viewportWidth = 600;
    o.viewportHeight = 600;
    Session s(makeWorld(defaultScene()), SceneInfo{.name = "default", .dt = 1.0 / 60.0}, o);
    s.apply(cmd::ToggleHelp{});
    EXPECT_TRUE(s.helpShown());
    EXPECT_EQ(s.helpPage(), 0u);
    s.apply(cmd::ToggleHelp{});
    EXPECT_TRUE(s.helpShown()) << "the second page, not closed";
    EXPECT_EQ(s.helpPage(), 1u);
    s.apply(cmd::ToggleHelp{});
    EXPECT_FALSE(s.helpShown());
    // Opened again it starts at the first page; in a large window one press closes it.
    s.apply(cmd::ToggleHelp{});
    EXPECT_EQ(s.helpPage(), 0u);
    WindowLayout large = o.layout;
    large.helpPages = 1;
    s.apply(cmd::Resize{1000, 1000, large});
    s.apply(cmd::ToggleHelp{});
    EXPECT_FALSE(s.helpShown());
}

TEST_F(SessionTest, EscClosesTheHelpFirstAndAsksBeforeLosingUnsavedChanges) {
    Session s = session();
    s.apply(cmd::ToggleHelp{});
    s.apply(cmd::Back{});
    EXPECT_FALSE(s.helpShown());
    EXPECT_TRUE(s.running());
    s.apply(cmd::SpawnRandom{});  // an unsaved change
    ASSERT_TRUE(s.unsavedChanges());
    s.apply(cmd::Back{});
    EXPECT_TRUE(s.running());
    EXPECT_EQ(s.dialog().kind, Dialog::Kind::Quit);
    EXPECT_TRUE(said(s.takeNotices(), "Unsaved changes"));
    // The dialog holds every other command: a key does nothing, and the window's close button
    // again leaves the question standing.
    const std::size_t n = s.world().size();
    s.apply(cmd::SpawnRandom{});
    s.apply(cmd::Quit{});
    EXPECT_EQ(s.world().size(), n);
    EXPECT_TRUE(s.running());
    EXPECT_EQ(s.dialog().kind, Dialog::Kind::Quit);
    // A second Esc is Cancel, never a quit without saving.
    s.apply(cmd::Back{});
    EXPECT_TRUE(s.running());
    EXPECT_FALSE(s.dialog().open());
    EXPECT_TRUE(said(s.takeNotices(), "Quit cancelled"));
    s.apply(cmd::Back{});
    s.apply(cmd::AnswerQuit{cmd::AnswerQuit::Choice::Discard});
    EXPECT_FALSE(s.running());
    EXPECT_FALSE(fs::exists(dir_ / "save.json"));
}

TEST_F(SessionTest, TheQuitDialogsSaveAsksForANameThenQuitsOnceSaved) {
    Session s = session();
    s.apply(cmd::SpawnRandom{});
    s.apply(cmd::Quit{});
    s.apply(cmd::AnswerQuit{cmd::AnswerQuit::Choice::Save});
    // The scene has no file: Save As, proposing --save-to.
    ASSERT_EQ(s.dialog().kind, Dialog::Kind::SaveAs);
    EXPECT_EQ(s.dialog().proposal, fs::absolute(dir_ / "save.json").lexically_normal());
    EXPECT_TRUE(s.running());
    // A refused name keeps the dialog (and the program) open.
    s.apply(cmd::SaveAs{dir_ / "no-such-dir" / "x.json"});
    EXPECT_TRUE(s.running());
    EXPECT_NE(s.dialog().error.find("Save failed"), std::string::npos) << s.dialog().error;
    s.apply(cmd::SaveAs{s.dialog().proposal});
    EXPECT_FALSE(s.running());
    EXPECT_EQ(loadScene(dir_ / "save.json").particles.size(), s.world().size());
    // Cancel in the Save As dialog cancels the quit.
    Session t = session();
    t.apply(cmd::SpawnRandom{});
    t.apply(cmd::Back{});
    t.apply(cmd::AnswerQuit{cmd::AnswerQuit::Choice::Save});
    t.apply(cmd::Back{});
    EXPECT_TRUE(t.running());
    EXPECT_FALSE(t.dialog().open());
}

TEST_F(SessionTest, EscAsksBeforeQuittingEvenWithNothingUnsaved) {
    // A lesson's run, its recordings and measurements are not saved changes, and Esc is one
    // keystroke: it asks in the quit dialog, whose Enter quits and whose Esc stays.
    Session s = session();
    ASSERT_FALSE(s.unsavedChanges());
    s.apply(cmd::Back{});
    EXPECT_TRUE(s.running());
    ASSERT_EQ(s.dialog().kind, Dialog::Kind::Quit);
    EXPECT_FALSE(s.dialog().unsaved);
    EXPECT_TRUE(said(s.takeNotices(), "Quit Particle Sandbox? Enter quits, Esc stays"));
    // The dialog holds every other command.
    const std::size_t n = s.world().size();
    s.apply(cmd::SpawnRandom{});
    EXPECT_EQ(s.world().size(), n);
    // Esc again stays.
    s.apply(cmd::Back{});
    EXPECT_TRUE(s.running());
    EXPECT_FALSE(s.dialog().open());
    EXPECT_TRUE(said(s.takeNotices(), "Quit cancelled"));
    // Enter (the dialog's Quit) quits.
    s.apply(cmd::Back{});
    s.apply(cmd::AnswerQuit{cmd::AnswerQuit::Choice::Quit});
    EXPECT_FALSE(s.running());
    // With unsaved changes, Quit is not one of the answers: only Save, Discard and Cancel are.
    Session u = session();
    u.apply(cmd::SpawnRandom{});
    u.apply(cmd::Back{});
    ASSERT_TRUE(u.dialog().unsaved);
    u.apply(cmd::AnswerQuit{cmd::AnswerQuit::Choice::Quit});
    EXPECT_TRUE(u.running());
    EXPECT_EQ(u.dialog().kind, Dialog::Kind::Quit);
}

TEST_F(SessionTest, ClosingTheWindowQuitsAtOnceWithNothingToLoseAndAfterASave) {
    Session s = session();
    s.apply(cmd::Quit{});
    EXPECT_FALSE(s.running());
    Session t = session();
    t.apply(cmd::SpawnRandom{});
    saveNow(t);
    EXPECT_FALSE(t.unsavedChanges());
    t.apply(cmd::Quit{});
    EXPECT_FALSE(t.running());
}

TEST_F(SessionTest, ASaveKeepsTheScenesNameAndDescription) {
    Session s = session();
    // A copy: the scene belongs to the file it was opened from, and Save writes it.
    fs::copy_file(testAsset("scenes/05-mass-ratio.json"), dir_ / "mass-ratio.json");
    s.apply(cmd::OpenFile{dir_ / "mass-ratio.json"});
    s.apply(cmd::SpawnRandom{});
    saveNow(s);
    const Scene original = loadScene(testAsset("scenes/05-mass-ratio.json"));
    const Scene saved = loadScene(dir_ / "mass-ratio.json");
    EXPECT_EQ(saved.name, original.name);
    EXPECT_EQ(saved.description, original.description);
    EXPECT_EQ(saved.particles.size(), original.particles.size() + 1);
    // The first scene, given to the session by the app, too.
    SessionOptions o = options();
    o.saveTo = dir_ / "first.json";
    Session first(
        makeWorld(defaultScene()),
        SceneInfo{.name = "default", .description = "A scene described.", .dt = 1.0 / 60.0}, o);
    saveNow(first);
    EXPECT_EQ(loadScene(dir_ / "first.json").description, "A scene described.");
}

TEST_F(SessionTest, APresetOpensPausedAndANewSceneStartsAtTimeSpeedOne) {
    SessionOptions o = options();
    o.paused = false;
    o.presets = testPresets();
    ASSERT_GE(o.presets.size(), 13u);
    Session s(makeWorld(defaultScene()), SceneInfo{.name = "default", .dt = 1.0 / 60.0}, o);
    s.apply(keys::timeSpeed(s, 2.0));
    s.apply(keys::timeSpeed(s, 2.0));
    ASSERT_EQ(s.timeScale(), 4.0);
    (void)s.takeNotices();
    s.apply(cmd::OpenPreset{11});  // the 12th: Shift+2
    const auto n = s.takeNotices();
    EXPECT_TRUE(s.paused());
    EXPECT_EQ(s.timeScale(), 1.0);
    EXPECT_TRUE(said(n, "time speed back to x1 (was x4)"));
    EXPECT_TRUE(said(n, "Preset 12 of 14 (key Shift+2), paused: Space starts it"));
    // Nothing moves until Space.
    const double t = s.world().time();
    s.update(0.5, 1.0);
    EXPECT_EQ(s.world().time(), t);
    s.apply(cmd::TogglePause{});
    s.update(0.1, 1.1);
    EXPECT_GT(s.world().time(), t);
    // R keeps the time speed (the same scene).
    s.apply(keys::timeSpeed(s, 0.5));
    s.apply(cmd::Restart{});
    EXPECT_EQ(s.timeScale(), 0.5);
}

TEST_F(SessionTest, NewParticlesFollowTheScenesScale) {
    Session s = session();
    s.apply(cmd::OpenFile{testAsset("scenes/09-galton-board.json")});
    const Scene board = loadScene(testAsset("scenes/09-galton-board.json"));
    // The board's balls (its dropper's): 5 mm and a few grams, not the default scene's 10 kg.
    ASSERT_EQ(board.droppers.size(), 1u);
    EXPECT_EQ(s.spawn().radius(), board.droppers[0].radius);
    EXPECT_LT(s.spawn().mass(), 0.01);
    const double m = s.spawn().mass();
    s.apply(cmd::ChangeSpawnMass{+1});
    EXPECT_NEAR(s.spawn().mass(), 1.1 * m, 1e-12 * m);
    // A launch makes one of those.
    const Camera& c = s.camera();
    const std::size_t n = s.world().size();
    // Empty space above the top row of pegs, away from the spout.
    s.apply(cmd::PointerDown{c.worldToScreen(Vec2(0.03, 0.04)), 1.0});
    s.apply(cmd::PointerUp{c.worldToScreen(Vec2(0.03, 0.04)), 1.5});
    ASSERT_EQ(s.world().size(), n + 1);
    EXPECT_NEAR(s.world().get(s.world().ids().back()).mass, 1.1 * m, 1e-12 * m);
}

TEST_F(SessionTest, SaveAsProposesAFreeNameAndThenSaveWritesTheFileTheUserNamed) {
    Session s = session();
    saveNow(s);
    s.apply(cmd::SpawnRandom{});
    // The scene now belongs to save.json, which the user named: Ctrl+S writes it again.
    s.apply(cmd::Save{});
    EXPECT_FALSE(s.dialog().open());
    const auto n = s.takeNotices();
    EXPECT_EQ(loadScene(dir_ / "save.json").particles.size(), 7u);
    EXPECT_TRUE(said(n, (dir_ / "save.json").string()));
    EXPECT_TRUE(s.lastSave()->is_absolute());
    // Save As proposes a free name beside --save-to, never the existing file.
    s.apply(cmd::AskSaveAs{});
    ASSERT_EQ(s.dialog().kind, Dialog::Kind::SaveAs);
    EXPECT_EQ(s.dialog().proposal.filename(), "save-2.json");
    EXPECT_TRUE(s.dialog().proposal.is_absolute());
}

TEST_F(SessionTest, ALaunchDraggedOutAndHeldStillHasTheDragsVelocityAsPreviewed) {
    Session s = session();
    const Vec2 from(1.0, 6.0), to(1.6, 5.4);  // empty space, 0.85 m up and right
    const Camera& c = s.camera();
    s.apply(cmd::PointerDown{c.worldToScreen(from), 1.0});
    s.apply(cmd::PointerMove{c.worldToScreen(to), 1.05});
    const CappedVelocity preview = s.launchPreview();
    s.apply(cmd::PointerUp{c.worldToScreen(to), 1.6});  // half a second still: at rest before
    ASSERT_EQ(s.world().size(), 7u);
    const Particle p = s.world().get(s.world().ids().back());
    const Vec2 expected = (to - from) / s.view().arrowSeconds;
    EXPECT_NEAR(p.velocity.x(), expected.x(), 0.02);
    EXPECT_NEAR(p.velocity.y(), expected.y(), 0.02);
    EXPECT_GT(p.velocity.norm(), 1.0);
    EXPECT_EQ(p.velocity, preview.velocity);
}

TEST_F(SessionTest, ACappedLaunchIsShown) {
    Session s = session();
    s.apply(cmd::Zoom{Vec2(400, 400), 1.0 / 40.0});  // far out, so a drag spans many boxes
    (void)s.takeNotices();
    const Vec2 from(-30.0, 3.0), to(40.0, 3.0);
    drag(s, from, to, 1.0);
    const auto n = s.takeNotices();
    EXPECT_TRUE(said(n, "Speed capped at 14 m/s")) << (n.empty() ? "" : n.back().text);
}

TEST_F(SessionTest, TheHudCanShowTheTimeSpeedReached) {
    Session s = session();
    s.apply(cmd::TogglePause{});
    s.apply(keys::timeSpeed(s, 8.0));
    for (int k = 0; k < 60; ++k)
        s.update(0.1, 0.0, 0.0);  // a budget of 0 ms: one step a frame
    // One dt of 1/60 s per 0.1 s of real time: x0.17 reached of x8 asked.
    EXPECT_NEAR(s.reachedTimeScale(), s.meta().dt / 0.1, 0.02);
    EXPECT_LT(s.reachedTimeScale(), s.timeScale());
}

TEST_F(SessionTest, StepsThatKeepUpShowTheSpeedAsked) {
    // Frames of uneven length make some frames step twice and others not at all; the speed
    // reached must not then read as "steps too slow" when nothing was ever dropped.
    Session s = session();
    s.apply(cmd::TogglePause{});
    double now = 0.0;
    for (int k = 0; k < 120; ++k) {
        const double frame = (k % 3 == 0) ? 0.004 : 0.023;
        now += frame;
        s.update(frame, now, 1e9);
    }
    EXPECT_EQ(s.reachedTimeScale(), s.timeScale());
}

TEST_F(SessionTest, AFittedViewLeavesTheMessagesBandAndThePanelColumnFree) {
    Session s = session();
    const auto box = [&] { return s.camera().boxOnScreen(7.0, 7.0); };
    const TestBands& in = window_.bands;
    EXPECT_LE(box().topLeft.y() + box().size.y(), 800.0 - in.bottom);
    EXPECT_GE(box().topLeft.y(), in.top);
    s.apply(keys::show(s, ShowOption::Plots));
    EXPECT_LE(box().topLeft.x() + box().size.x(), 800.0 - in.column);
    s.apply(keys::show(s, ShowOption::Plots));
    EXPECT_GT(box().topLeft.x() + box().size.x(), 800.0 - in.column);  // room back
}

TEST_F(SessionTest, TheInspectorSitsBesideTheBoxWhenTheWindowCanSpareTheWidth) {
    // A window wider than the box needs: the box moves left, keeping its size, so that the
    // inspector (bottom right, when a particle is clicked) does not cover it.
    SessionOptions o = options();
    const auto layoutWith = [this](double inspector) {
        TestBands bands = window_.bands;
        bands.inspector = inspector;
        return testLayout(bands);
    };
    const auto boxAt = [&](double inspector) {
        o.layout = layoutWith(inspector);
        Session s(makeWorld(defaultScene()), SceneInfo{.name = "default", .dt = 1.0 / 60.0}, o);
        s.apply(cmd::Resize{800, 600, o.layout});
        return s.camera().boxOnScreen(7.0, 7.0);
    };
    const auto centred = boxAt(0.0), moved = boxAt(240.0);
    EXPECT_NEAR(moved.size.x(), centred.size.x(), 1e-9);  // no smaller
    EXPECT_LE(moved.topLeft.x() + moved.size.x(), 800.0 - 240.0 + 1e-9);
    // A window with no width to spare keeps the box as big as it was.
    o.layout = layoutWith(240.0);
    Session square(makeWorld(defaultScene()), SceneInfo{.name = "default", .dt = 1.0 / 60.0}, o);
    square.apply(cmd::Resize{600, 900, o.layout});
    o.layout = layoutWith(0.0);
    Session plain(makeWorld(defaultScene()), SceneInfo{.name = "default", .dt = 1.0 / 60.0}, o);
    plain.apply(cmd::Resize{600, 900, o.layout});
    EXPECT_NEAR(square.camera().zoom(), plain.camera().zoom(), 1e-12);
}

TEST_F(SessionTest, AResizeKeepsAFittedViewFitted) {
    Session s = session();
    const double before = s.camera().zoom();
    s.apply(cmd::Resize{1200, 1200, layout()});
    EXPECT_GT(s.camera().zoom(), 1.4 * before);
    const auto b = s.camera().boxOnScreen(7.0, 7.0);
    EXPECT_NEAR(b.topLeft.x() + b.size.x() / 2.0, 600.0, 1.0);
    // A view the user moved keeps its zoom.
    s.apply(cmd::Pan{Vec2(30, 0)});
    const double z = s.camera().zoom();
    s.apply(cmd::Resize{900, 900, layout()});
    EXPECT_DOUBLE_EQ(s.camera().zoom(), z);
}

TEST_F(SessionTest, MFindsRoomInTheGasPreset) {
    const Scene gas = loadScene(testAsset("scenes/04-gas-in-a-box.json"));
    Session s(makeWorld(gas), SceneInfo{.name = "gas", .dt = gas.dt}, options());
    const std::size_t n = s.world().size();
    for (int k = 0; k < 10; ++k)
        s.apply(cmd::SpawnRandom{});
    EXPECT_GE(s.world().size() - n, 8u);
    EXPECT_NEAR(maxOverlapBruteForce(s.world()), 0.0, 1e-12);
}

TEST_F(SessionTest, AParticleDraggedIntoAnotherWhilePausedShowsItsOverlap) {
    for (const StepMode mode : {StepMode::Discrete, StepMode::Exact}) {
        Session s = session();
        while (s.world().solver().mode != mode)
            s.apply(keys::mode(s));
        s.update(0.0, 0.0);
        ASSERT_EQ(s.accuracy().overlap(), 0.0);
        // The yellow disc (5.2, 1.6), r 0.45, dragged onto the orange one (6.0, 3.3), r 0.375.
        const Camera& c = s.camera();
        s.apply(cmd::PointerDown{c.worldToScreen(Vec2(5.2, 1.6)), 1.0});
        s.apply(cmd::PointerMove{c.worldToScreen(Vec2(5.8, 3.0)), 1.2});
        s.update(0.0, 1.2);
        const double truth = maxOverlapBruteForce(s.world());
        EXPECT_GT(truth, 0.3);
        EXPECT_NEAR(s.accuracy().overlap(), truth, 1e-12) << toString(mode);
    }
}

TEST_F(SessionTest, AParticleFlungWhilePausedKeepsItsSpeedForWhenTimeRunsAndSaysSo) {
    // Paused, the yellow disc (5.2, 1.6) dragged 1 m left in 0.1 s and let go moving: it stays
    // where it was let go until time runs (paused), so the message band says that the speed is
    // kept, while dragging and on letting go, and Space sets it moving.
    Session s = session();
    ASSERT_TRUE(s.paused());
    const ParticleId yellow = s.world().pick(Vec2(5.2, 1.6)).value();
    (void)s.takeNotices();
    const Camera& c = s.camera();
    s.apply(cmd::PointerDown{c.worldToScreen(Vec2(5.2, 1.6)), 1.0});
    EXPECT_FALSE(said(s.takeNotices(), "paused")) << "a click that only selects says nothing";
    for (int k = 1; k <= 10; ++k) {
        s.apply(cmd::PointerMove{c.worldToScreen(Vec2(5.2 - 0.1 * k, 1.6)), 1.0 + 0.01 * k});
        s.update(0.0, 1.0 + 0.01 * k);
    }
    const auto dragging = s.takeNotices();
    EXPECT_TRUE(said(dragging, "Paused: let go moving and the particle takes the hand's speed"))
        << (dragging.empty() ? "" : dragging.back().text);
    s.apply(cmd::PointerUp{c.worldToScreen(Vec2(4.2, 1.6)), 1.1});
    const Particle flung = s.world().get(yellow);
    EXPECT_LT(flung.velocity.x(), -5.0);
    const auto released = s.takeNotices();
    EXPECT_TRUE(said(released, "while paused: Space sets it moving"))
        << (released.empty() ? "" : released.back().text);
    s.apply(cmd::TogglePause{});
    s.update(0.1, 1.2);  // the first frame after a pause owes one frame's time
    s.update(0.1, 1.3);
    EXPECT_LT(s.world().get(yellow).position.x(), flung.position.x() - 0.3);
}

TEST_F(SessionTest, AParticleMovedWhilePausedKeepsItsVelocityUnlessFlung) {
    // A student setting up a lesson moved a paused ball and found it at rest ("Let go at
    // rest"). Paused, a particle put down (the hand stopped before letting go) keeps the
    // velocity it had; only a fling (let go moving) gives it the hand's. The mouse and a
    // finger are the same commands, so the desktop and the page agree.
    Session s = session();
    ASSERT_TRUE(s.paused());
    const ParticleId yellow = s.world().pick(Vec2(5.2, 1.6)).value();
    s.apply(cmd::EditParticle{yellow, ParticleField::Vx, "1.5"});
    const Vec2 before = s.world().get(yellow).velocity;
    ASSERT_GT(before.norm(), 1.0);
    (void)s.takeNotices();
    const Camera& c = s.camera();
    s.apply(cmd::PointerDown{c.worldToScreen(Vec2(5.2, 1.6)), 1.0});
    for (int k = 1; k <= 10; ++k)
        s.apply(cmd::PointerMove{c.worldToScreen(Vec2(5.2 - 0.1 * k, 1.6)), 1.0 + 0.01 * k});
    // Held still half a second, then let go where it stood.
    s.apply(cmd::PointerUp{c.worldToScreen(Vec2(4.2, 1.6)), 1.6});
    const Particle moved = s.world().get(yellow);
    EXPECT_NEAR(moved.position.x(), 4.2, 1e-9);
    EXPECT_NEAR((moved.velocity - before).norm(), 0.0, 1e-12) << "the velocity it had is kept";
    const auto said1 = s.takeNotices();
    EXPECT_TRUE(said(
        said1, "Moved while paused: it keeps its speed, " + quantity(before.norm(), "m/s", false)))
        << (said1.empty() ? "" : said1.back().text);
    // Let go moving: a fling, the hand's velocity.
    s.apply(cmd::PointerDown{c.worldToScreen(Vec2(4.2, 1.6)), 2.0});
    for (int k = 1; k <= 10; ++k)
        s.apply(cmd::PointerMove{c.worldToScreen(Vec2(4.2 + 0.1 * k, 1.6)), 2.0 + 0.01 * k});
    s.apply(cmd::PointerUp{c.worldToScreen(Vec2(5.2, 1.6)), 2.1});
    EXPECT_GT(s.world().get(yellow).velocity.x(), 5.0);
    const auto said2 = s.takeNotices();
    EXPECT_TRUE(said(said2, "Flung at")) << (said2.empty() ? "" : said2.back().text);
    EXPECT_FALSE(said(said2, "mm/s")) << "speeds in m/s, as vx and vy beside them";
    // Running, a hand that stopped holds the ball still: it is caught, not moved.
    s.apply(cmd::TogglePause{});
    s.apply(cmd::PointerDown{c.worldToScreen(s.world().get(yellow).position), 3.0});
    s.apply(cmd::PointerUp{c.worldToScreen(s.world().get(yellow).position), 3.6});
    EXPECT_EQ(s.world().get(yellow).velocity.norm(), 0.0);
}

TEST_F(SessionTest, TheEditPromptTakesTheKeyboard) {
    Session s = session();
    const Vec2 yellow(5.2, 1.6);
    s.apply(cmd::PointerDown{s.camera().worldToScreen(yellow), 1.0});
    s.apply(cmd::PointerUp{s.camera().worldToScreen(yellow), 1.05});
    ASSERT_TRUE(s.selection().id().has_value());
    s.apply(cmd::OpenEdit{});
    ASSERT_TRUE(s.prompt().active());
    const std::size_t particles = s.world().size();
    s.apply(cmd::SpawnRandom{});  // a key's command that is not the prompt's: held back
    EXPECT_EQ(s.world().size(), particles);
    s.apply(cmd::Fit{});
    EXPECT_TRUE(s.prompt().active());
    s.apply(cmd::Back{});  // closes the prompt, does not quit
    EXPECT_FALSE(s.prompt().active());
    EXPECT_TRUE(s.running());
}

TEST_F(SessionTest, RestartWithoutAPlayRestoresTheSceneAsLoaded) {
    Session s = session();
    const std::uint64_t loaded = test::stateHash(s.world());
    const std::uint64_t generation = s.sceneGeneration();
    s.apply(cmd::SpawnRandom{});
    s.apply(keys::restitution(s, -1));
    s.apply(cmd::Restart{});
    EXPECT_EQ(test::stateHash(s.world()), loaded);
    EXPECT_NE(s.sceneGeneration(), generation);
    EXPECT_FALSE(s.unsavedChanges());  // exactly the scene as loaded
    // A new title is a change Restart does not undo.
    s.apply(cmd::SetSceneText{"renamed", ""});
    s.apply(cmd::Restart{});
    EXPECT_TRUE(s.unsavedChanges());
}

TEST_F(SessionTest, OnATouchScreenMessagesNameTheButtonsNotTheKeys) {
    SessionOptions o = options();
    o.presets = testPresets();
    Session s(makeWorld(defaultScene()), SceneInfo{.name = "default", .dt = 1.0 / 60.0}, o);
    (void)s.takeNotices();
    s.apply(cmd::SetTouch{true});
    EXPECT_TRUE(s.touch());
    s.apply(cmd::OpenPreset{11});
    const auto n = s.takeNotices();
    EXPECT_TRUE(said(n, "Preset 12 of 14, paused: Play starts it"));
    for (const Notice& notice : n) {
        EXPECT_EQ(notice.text.find("Space"), std::string::npos) << notice.text;
        EXPECT_EQ(notice.text.find("(key "), std::string::npos) << notice.text;
    }
    s.apply(cmd::Stopwatch{cmd::Stopwatch::Action::StartStop});
    EXPECT_TRUE(said(s.takeNotices(), "Stopwatch started: it runs with simulated time (Play)"));
}

TEST_F(SessionTest, OnATouchScreenTheDialogsAndTheEditHintNameTheirButtonsNotKeys) {
    Session s = session();
    s.apply(cmd::SetTouch{true});
    (void)s.takeNotices();
    std::vector<Notice> n;
    const auto take = [&] {
        std::vector<Notice> t = s.takeNotices();
        n.insert(n.end(), t.begin(), t.end());
        return t;
    };
    // Enter edits the selected particle where there is a keyboard; a finger has the panel.
    s.apply(cmd::OpenEdit{});
    EXPECT_TRUE(
        said(take(), "Tap a particle to select it, then edit it in the panel's Selected particle"));
    s.apply(cmd::AskSaveAs{});
    EXPECT_TRUE(said(take(), "Save as: type a file name, then Save or Cancel ("));
    s.apply(cmd::CloseDialog{});
    s.apply(cmd::Back{});  // the quit question, nothing unsaved
    ASSERT_EQ(s.dialog().kind, Dialog::Kind::Quit);
    EXPECT_TRUE(said(take(), "Quit Particle Sandbox? Quit or Stay"));
    for (const Notice& notice : n) {
        for (const char* key : {"Enter", "Esc", "Click"})
            EXPECT_EQ(notice.text.find(key), std::string::npos) << notice.text;
    }
}

}  // namespace
}  // namespace psb::app
