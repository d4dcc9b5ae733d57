// The session's value commands (session_values.cpp): what the control panel's controls send.
// Each sets its value, refuses a bad one with a message and no change, and counts as one user
// action, a slider's whole drag included.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

#include <particle_sandbox/presets.hpp>
#include <particle_sandbox/scene.hpp>

#include "session/gas_gauges.hpp"
#include "session/gas_world.hpp"
#include "session/scene_io.hpp"
#include "session/session.hpp"
#include "session/session_fixture.hpp"
#include "session/test_assets.hpp"

namespace psb::app {
namespace {

namespace fs = std::filesystem;

class SessionValues : public SessionFixture {
  protected:
    // The side column as the view makes it beside the open control panel in a 1000-pixel
    // window: two fifths of the 690 pixels left, and the margin.
    SessionValues()
        : SessionFixture("psb-session-values", TestWindow{1000,
                                                          800,
                                                          {.top = 60.0,
                                                           .bottom = 44.0,
                                                           .column = 276.0 + 8.0,
                                                           .controls = 310.0,
                                                           .controlsFolded = 34.0},
                                                          true}) {}

    /// A left-button drag in world metres, 5 moves over 100 ms.
    static void drag(Session& s, Vec2 from, Vec2 to, double t0) {
        psb::app::drag(s, from, to, t0, 5, 0.02);
    }
    /// A free spot in the default scene's 7 m box.
    [[nodiscard]] static Vec2 emptySpot(const Session& s) {
        for (double y = 0.5; y < 6.5; y += 0.25) {
            for (double x = 0.5; x < 6.5; x += 0.25) {
                if (!s.world().pick(Vec2(x, y)) &&
                    findFreeSpot(s.world(), Vec2(x, y), 0.6) == std::optional<Vec2>(Vec2(x, y))) {
                    return {x, y};
                }
            }
        }
        return {3.5, 3.5};
    }
};

TEST_F(SessionValues, ASliderDragIsOneUserActionAndANewDragAnother) {
    Session s = session();
    const auto before = s.userActions();
    s.apply(cmd::SetRestitution{0.9, false});
    for (int k = 1; k <= 50; ++k)
        s.apply(cmd::SetRestitution{0.9 - 0.01 * k, true});
    EXPECT_DOUBLE_EQ(s.world().def().restitution, 0.4);
    EXPECT_EQ(s.userActions(), before + 1);
    EXPECT_EQ(s.lastAction(), "set restitution");
    EXPECT_TRUE(s.unsavedChanges());
    s.apply(cmd::SetRestitution{0.7, false});
    EXPECT_EQ(s.userActions(), before + 2);
    // A continuing command of another control is a new action.
    s.apply(cmd::SetFriction{0.2, true});
    EXPECT_EQ(s.userActions(), before + 3);
    EXPECT_EQ(s.lastAction(), "set friction");
}

TEST_F(SessionValues, RestitutionAndFrictionOutOfRangeAreRefusedAndChangeNothing) {
    Session s = session();
    for (const double bad : {-0.1, 1.5, std::numeric_limits<double>::quiet_NaN()}) {
        s.apply(cmd::SetRestitution{bad});
        EXPECT_TRUE(said(s.takeNotices(), "Restitution must be between 0 and 1")) << bad;
        EXPECT_DOUBLE_EQ(s.world().def().restitution, 1.0);
    }
    s.apply(cmd::SetFriction{-1.0});
    EXPECT_TRUE(said(s.takeNotices(), "Friction must be a number >= 0"));
    s.apply(cmd::SetFriction{0.35});
    EXPECT_DOUBLE_EQ(s.world().def().friction, 0.35);
    EXPECT_FALSE(s.unsavedChanges() && s.userActions() == 0);
}

TEST_F(SessionValues, GravityOnWithItsValueOffAndBadValuesRefused) {
    Session s = session();
    s.apply(cmd::SetGravity{true, 9.81});
    EXPECT_EQ(s.world().def().gravity, Vec2(0.0, 9.81));
    EXPECT_TRUE(said(s.takeNotices(), "Gravity [0, -9.81] m/s\u00b2")) << "down, y counting up";
    s.apply(cmd::SetGravity{true, 1.62, true});
    EXPECT_EQ(s.world().def().gravity, Vec2(0.0, 1.62));
    for (const double bad : {0.0, -9.81, 1e9, std::numeric_limits<double>::infinity()}) {
        s.apply(cmd::SetGravity{true, bad});
        EXPECT_TRUE(said(s.takeNotices(), "Gravity must be above 0")) << bad;
        EXPECT_EQ(s.world().def().gravity, Vec2(0.0, 1.62));
    }
    s.apply(cmd::SetGravity{false});
    EXPECT_EQ(s.world().def().gravity, Vec2::Zero());
}

TEST_F(SessionValues, WallsOnAndOff) {
    Session s = session();
    s.apply(cmd::SetWalls{false});
    EXPECT_FALSE(s.world().def().walls);
    EXPECT_TRUE(said(s.takeNotices(), "Walls off"));
    s.apply(cmd::SetWalls{true});
    EXPECT_TRUE(s.world().def().walls);
}

// Heat and Cool scale every free particle's speed: the temperature goes with its square; a
// factor out of range, or one that would make a particle absurdly fast, changes nothing.
TEST_F(SessionValues, HeatAndCoolScaleEverySpeedUndoably) {
    Session s = session();
    const World before = s.world();
    double energy = 0.0;
    for (const ParticleId id : before.ids())
        energy += 0.5 * before.get(id).mass * before.get(id).velocity.squaredNorm();
    ASSERT_GT(energy, 0.0);
    s.apply(cmd::ScaleSpeeds{1.1});
    double heated = 0.0;
    for (const ParticleId id : s.world().ids()) {
        EXPECT_EQ(s.world().get(id).velocity, 1.1 * before.get(id).velocity);
        heated += 0.5 * s.world().get(id).mass * s.world().get(id).velocity.squaredNorm();
    }
    EXPECT_NEAR(heated / energy, 1.21, 1e-12);
    EXPECT_TRUE(said(s.takeNotices(), "Heated: every speed x1.1, the temperature"));
    EXPECT_EQ(s.undoLabel(), "heat");
    s.apply(cmd::Undo{});
    for (const ParticleId id : s.world().ids())
        EXPECT_EQ(s.world().get(id).velocity, before.get(id).velocity);
    for (const double bad : {0.0, -1.0, 11.0, std::nan(""), HUGE_VAL}) {
        s.apply(cmd::ScaleSpeeds{bad});
        EXPECT_TRUE(said(s.takeNotices(), "Speeds can be scaled")) << bad;
    }
    s.apply(cmd::ScaleSpeeds{10.0});
    s.apply(cmd::ScaleSpeeds{10.0});
    s.apply(cmd::ScaleSpeeds{10.0});
    s.apply(cmd::ScaleSpeeds{10.0});  // 10^4 times the speeds: over 1000 box sizes a second
    EXPECT_TRUE(said(s.takeNotices(), "Not heated: the fastest particle would move at"));
    s.apply(cmd::ScaleSpeeds{1.0 / 1.1});
    EXPECT_TRUE(said(s.takeNotices(), "Cooled"));
}

TEST_F(SessionValues, SqueezeMovesTheParticlesWithTheBoxKeepsTheirSpeedsAndUndoes) {
    Session s = session();
    s.setWorld(gasWorld(), SceneInfo{.name = "gas", .dt = Scene{}.dt});
    (void)s.takeNotices();
    const World before = s.world();
    const double side = std::sqrt(0.9);
    s.apply(cmd::ResizeBox{700.0 * side, 700.0 * side});
    EXPECT_TRUE(said(s.takeNotices(), "the area x0.9, the particles moved with it"));
    EXPECT_DOUBLE_EQ(s.world().def().width, 700.0 * side);
    // 40 discs far apart: no pushing, each centre scaled with the box.
    for (const ParticleId id : before.ids()) {
        const Particle a = before.get(id), b = s.world().get(id);
        EXPECT_EQ(b.velocity, a.velocity);
        EXPECT_NEAR(b.position.x(),
                    std::clamp(a.position.x() * side, a.radius, 700.0 * side - a.radius), 1e-9);
    }
    // The same temperature in less room: the ideal gas's pressure up by the areas' ratio.
    const auto ideal = [](const World& w) {
        World measured = w;
        GasGauges g;
        g.sample(measured);  // opens the core's window: kT and A′ as it measures them
        return g.reading(measured).idealPressure;
    };
    const double reach = [](double l) { return (l - 16.0) * (l - 16.0); }(700.0);
    const double squeezed = [](double l) { return (l - 16.0) * (l - 16.0); }(700.0 * side);
    EXPECT_NEAR(ideal(s.world()) / ideal(before), reach / squeezed, 1e-9);
    EXPECT_EQ(s.undoLabel(), "squeeze the box");
    s.apply(cmd::Undo{});
    EXPECT_DOUBLE_EQ(s.world().def().width, 700.0);
    EXPECT_EQ(s.world().get(before.ids()[5]).position, before.get(before.ids()[5]).position);
    // Too far: the discs would overlap, or one would not fit; nothing changes.
    s.apply(cmd::ResizeBox{100.0, 100.0});
    EXPECT_TRUE(said(s.takeNotices(), "Not resized: the particles would overlap by up to"));
    s.apply(cmd::ResizeBox{10.0, 700.0});
    EXPECT_TRUE(said(s.takeNotices(), "across) would not fit"));
    EXPECT_DOUBLE_EQ(s.world().def().width, 700.0);
    for (const double bad : {0.0, -5.0, 1e7, std::nan(""), HUGE_VAL}) {
        s.apply(cmd::ResizeBox{bad, 700.0});
        EXPECT_TRUE(said(s.takeNotices(), "The box must be 0.01 m to 1e+06 m")) << bad;
    }
    // A box with obstacles keeps its size.
    World pegs = gasWorld();
    pegs.addObstacle(Obstacle::peg(Vec2(650.0, 650.0), 5.0));
    s.setWorld(std::move(pegs), SceneInfo{.name = "pegs", .dt = Scene{}.dt});
    (void)s.takeNotices();
    s.apply(cmd::ResizeBox{600.0, 600.0});
    EXPECT_TRUE(said(s.takeNotices(), "Not resized: this scene's walls, pegs and spouts"));
    EXPECT_DOUBLE_EQ(s.world().def().width, 700.0);
}

TEST_F(SessionValues, TheArrowScaleStaysWhereTheUserSetItUntilASceneOpens) {
    // Left alone, the scale the scene chose stays as the motion speeds up (heat the default
    // scene 100 x): arrow lengths stay comparable over time.
    Session alone = session();
    const double chosen = alone.view().arrowSeconds;
    alone.apply(cmd::ScaleSpeeds{10.0});
    alone.apply(cmd::ScaleSpeeds{10.0});
    alone.apply(cmd::TogglePause{});
    alone.update(0.1, 0.1);
    EXPECT_EQ(alone.view().arrowSeconds, chosen);

    // Set by the user, it stays through the same speed-up.
    Session s = session();
    s.apply(cmd::SetArrowScale{1.0, false});
    EXPECT_TRUE(said(s.takeNotices(), "Arrows: 1 s of motion, kept until a scene opens"));
    EXPECT_TRUE(s.view().arrowScaleSet);
    s.apply(cmd::ScaleSpeeds{10.0});
    s.apply(cmd::ScaleSpeeds{10.0});
    s.apply(cmd::TogglePause{});
    s.update(0.1, 0.1);
    EXPECT_DOUBLE_EQ(s.view().arrowSeconds, 1.0);

    // Bad values are refused and change nothing.
    for (const double bad : {0.0, -1.0, 0.001, 6.0, std::nan(""), HUGE_VAL}) {
        s.apply(cmd::SetArrowScale{bad, false});
        EXPECT_TRUE(said(s.takeNotices(), "The arrow scale must be")) << bad;
        EXPECT_DOUBLE_EQ(s.view().arrowSeconds, 1.0) << bad;
    }

    // A new scene chooses its own scale again.
    s.setWorld(World(s.world().def()), SceneInfo{.name = "empty", .dt = Scene{}.dt});
    EXPECT_FALSE(s.view().arrowScaleSet);
    EXPECT_DOUBLE_EQ(s.view().arrowSeconds, 1.0 / 3.0);
}

TEST_F(SessionValues, TheUiScaleIsSetWithinItsRangeAndBadValuesAreRefused) {
    Session s = session();
    EXPECT_TRUE(s.view().uiScaleAutomatic);
    EXPECT_EQ(s.view().uiScale, 1.0);
    s.apply(cmd::SetUiScale{2.0, false});
    EXPECT_TRUE(said(s.takeNotices(), "UI scale 200 % (Ctrl+0: automatic)"));
    EXPECT_EQ(s.view().uiScale, 2.0);
    EXPECT_FALSE(s.view().uiScaleAutomatic);
    for (const double bad : {0.0, 0.74, 3.01, -1.0, std::nan(""), HUGE_VAL}) {
        s.apply(cmd::SetUiScale{bad, false});
        EXPECT_TRUE(said(s.takeNotices(), "The UI scale must be 75 % to 300 %")) << bad;
        EXPECT_EQ(s.view().uiScale, 2.0) << bad;
    }
    s.apply(cmd::SetUiScale{1.5, true});
    EXPECT_TRUE(said(s.takeNotices(), "UI scale 150 % (automatic: by the window's height"));
    EXPECT_TRUE(s.view().uiScaleAutomatic);
    // A view setting, not an edit: nothing to undo, and a new scene keeps it.
    EXPECT_FALSE(s.canUndo());
    s.setWorld(World(s.world().def()), SceneInfo{.name = "empty", .dt = Scene{}.dt});
    EXPECT_EQ(s.view().uiScale, 1.5);
}

TEST_F(SessionValues, TheThemeSwitchesAndIsNoEdit) {
    Session s = session();
    EXPECT_EQ(s.view().theme, Theme::Dark);
    s.apply(cmd::SetTheme{Theme::Light});
    EXPECT_TRUE(said(s.takeNotices(), "Theme: light"));
    EXPECT_EQ(s.view().theme, Theme::Light);
    EXPECT_FALSE(s.canUndo());
    s.apply(cmd::SetTheme{Theme::Light});
    EXPECT_TRUE(s.takeNotices().empty()) << "no news";
    s.apply(cmd::SetTheme{Theme::Dark});
    EXPECT_EQ(s.view().theme, Theme::Dark);
}

TEST_F(SessionValues, OnATouchScreenTheScaleAndThemeMessagesNameNoKey) {
    // A laptop's touch screen: the panel's slider, Auto and Light, not Ctrl+0 and Ctrl+T.
    Session s = session();
    s.apply(cmd::SetTouch{true});
    (void)s.takeNotices();
    s.apply(cmd::SetUiScale{2.0, false});
    EXPECT_TRUE(said(s.takeNotices(), "UI scale 200 % (Show: Auto makes it automatic)"));
    s.apply(cmd::SetUiScale{1.5, true});
    std::vector<Notice> n = s.takeNotices();
    EXPECT_TRUE(said(n, "UI scale 150 % (automatic: by the window's height)"));
    s.apply(cmd::SetTheme{Theme::Light});
    s.apply(cmd::SetTheme{Theme::Dark});
    const std::vector<Notice> themes = s.takeNotices();
    EXPECT_TRUE(said(themes, "Theme: light (high contrast, for projectors)"));
    n.insert(n.end(), themes.begin(), themes.end());
    for (const Notice& notice : n)
        EXPECT_EQ(notice.text.find("Ctrl+"), std::string::npos) << notice.text;
}

TEST(UiScale, StepsThroughTheListAndTheAutomaticRuleFollowsTheHeight) {
    EXPECT_EQ(steppedUiScale(1.0, +1), 1.1);
    EXPECT_EQ(steppedUiScale(1.0, -1), 0.9);
    EXPECT_EQ(steppedUiScale(1.0, +5), 2.0);
    EXPECT_EQ(steppedUiScale(3.0, +1), 3.0);
    EXPECT_EQ(steppedUiScale(0.75, -1), 0.75);
    EXPECT_EQ(steppedUiScale(1.3, +1), 1.5) << "from between two steps, the next one";
    EXPECT_EQ(steppedUiScale(1.3, -1), 1.25);
    EXPECT_EQ(automaticUiScale(800), 1.0) << "the window the program opens";
    EXPECT_EQ(automaticUiScale(899), 1.0);
    EXPECT_EQ(automaticUiScale(900), 1.25);
    EXPECT_EQ(automaticUiScale(1080), 1.5) << "a 1920x1080 projector, full screen";
    EXPECT_EQ(automaticUiScale(1440), 2.0);
    EXPECT_EQ(automaticUiScale(2160), 3.0);
    EXPECT_EQ(automaticUiScale(5000), 3.0);
    EXPECT_EQ(automaticUiScale(std::nan("")), 1.0);
}

TEST(UiScale, AWindowAllowsNoScaleThatPutsThePanelPastItsEdge) {
    // A phone held upright (390 CSS pixels) at 150 %: the panel's sheet, 310 points wide, ran
    // 465 pixels off its right edge with its close button. No scale may leave the window less
    // than the panel's least width (kPanelLeastPoints), at any width from 320 up.
    EXPECT_EQ(mostUiScale(390.0), 1.6);
    EXPECT_EQ(mostUiScale(320.0), 1.3);
    EXPECT_EQ(mostUiScale(1024.0), 3.0) << "a tablet allows every scale";
    EXPECT_EQ(mostUiScale(100.0), kMinUiScale) << "never below the least scale";
    EXPECT_EQ(mostUiScale(std::nan("")), kMaxUiScale) << "no window yet";
    for (double width = 320.0; width <= 2000.0; width += 1.0)
        for (const double chosen : kUiScaleSteps) {
            ViewOptions v;
            v.uiScale = chosen;
            v.uiScaleMost = mostUiScale(width);
            EXPECT_GE(width / v.uiScaleInUse(), kPanelLeastPoints - 1e-9)
                << width << " points at " << chosen;
        }
}

TEST_F(SessionValues, AScaleAboveWhatTheWindowAllowsIsKeptAndUsedAtTheMostItAllows) {
    // The scale is remembered (settings) as chosen; a narrow window uses less, and says so
    // where it is chosen.
    Session s = session();
    (void)s.takeNotices();
    s.apply(cmd::FitUiScale{mostUiScale(390.0)});
    EXPECT_TRUE(s.takeNotices().empty()) << "a window's size is no news";
    s.apply(cmd::SetUiScale{1.5, false});
    EXPECT_EQ(s.view().uiScaleInUse(), 1.5) << "150 % fits 390 pixels: 260 points";
    s.apply(cmd::SetUiScale{2.0, false});
    EXPECT_TRUE(said(s.takeNotices(),
                     "UI scale 200 %, shown at 160 %, the most this window's "
                     "width allows"));
    EXPECT_EQ(s.view().uiScale, 2.0) << "the choice is kept";
    EXPECT_EQ(s.view().uiScaleInUse(), 1.6);
    s.apply(cmd::FitUiScale{mostUiScale(1024.0)});  // turned sideways, or a wider window
    EXPECT_EQ(s.view().uiScaleInUse(), 2.0);
    for (const double bad : {0.0, 3.5, std::nan("")}) {
        s.apply(cmd::FitUiScale{bad});
        EXPECT_EQ(s.view().uiScaleInUse(), 2.0) << bad;
    }
}

TEST_F(SessionValues, ModeWithSubstepsAndExactAlsoWhereThereAreObstacles) {
    Session s = session();
    s.apply(cmd::SetMode{StepMode::Substep, 8});
    EXPECT_EQ(s.world().solver().mode, StepMode::Substep);
    EXPECT_EQ(s.world().solver().substeps, 8);
    s.apply(cmd::SetMode{StepMode::Substep, 1});  // one substep would be the discrete mode
    EXPECT_EQ(s.world().solver().substeps, 2);
    s.apply(cmd::SetMode{StepMode::Exact});
    EXPECT_EQ(s.world().solver().mode, StepMode::Exact);

    World pegs(s.world().def());
    pegs.addObstacle(Obstacle::peg(Vec2(3.5, 3.5), 0.2));
    s.setWorld(std::move(pegs), SceneInfo{.name = "pegs", .dt = Scene{}.dt});
    (void)s.takeNotices();
    s.apply(cmd::SetMode{StepMode::Exact});
    EXPECT_EQ(s.world().solver().mode, StepMode::Exact);
}

TEST_F(SessionValues, EachShowOptionIsSetAndSaysWhatItSwitched) {
    Session s = session();
    const ShowOption all[] = {ShowOption::Arrows, ShowOption::Labels, ShowOption::Momentum,
                              ShowOption::Plots,  ShowOption::Speeds, ShowOption::Profile,
                              ShowOption::Bins};
    for (const ShowOption o : all) {
        (void)s.takeNotices();
        const bool was = s.view().shown(o);
        s.apply(cmd::SetShow{o, !was});
        EXPECT_EQ(s.view().shown(o), !was);
        EXPECT_TRUE(said(s.takeNotices(), showMessage(o, !was))) << showMessage(o, !was);
        s.apply(cmd::SetShow{o, !was});  // already so: nothing changes, nothing is said
        EXPECT_TRUE(s.takeNotices().empty());
    }
    EXPECT_TRUE(s.profileShown() == s.view().profile);
    EXPECT_EQ(showMessage(ShowOption::Speeds, true), "Speed distribution on");
}

TEST_F(SessionValues, TimeSpeedIsSetWithinItsLimits) {
    Session s = session();
    s.apply(cmd::SetTimeScale{0.25});
    EXPECT_DOUBLE_EQ(s.timeScale(), 0.25);
    s.apply(cmd::SetTimeScale{1000.0});
    EXPECT_DOUBLE_EQ(s.timeScale(), Session::kMaxTimeScale);
    s.apply(cmd::SetTimeScale{0.0});
    EXPECT_DOUBLE_EQ(s.timeScale(), Session::kMinTimeScale);
    s.apply(cmd::SetTimeScale{std::numeric_limits<double>::quiet_NaN()});
    EXPECT_DOUBLE_EQ(s.timeScale(), Session::kMinTimeScale);
}

TEST_F(SessionValues, TheLaunchToolLaunchesEvenFromAParticle) {
    Session s = session();
    s.apply(cmd::SetTool{cmd::Tool::Launch});
    const Particle p = s.world().get(s.world().ids().front());
    const std::size_t n = s.world().size();
    drag(s, p.position, p.position + Vec2(1.0, 0.0), 1.0);
    EXPECT_EQ(s.world().size(), n + 1);
    EXPECT_EQ(s.world().get(p.id).position, p.position);  // not grabbed
    EXPECT_EQ(s.lastAction(), "launch particle");
}

TEST_F(SessionValues, TheSelectToolSelectsAndNeverMovesAnything) {
    Session s = session();
    s.apply(cmd::SetTool{cmd::Tool::Select});
    const Particle p = s.world().get(s.world().ids().back());
    const std::size_t n = s.world().size();
    drag(s, p.position, p.position + Vec2(1.0, 1.0), 1.0);
    EXPECT_EQ(s.world().size(), n);
    EXPECT_EQ(s.world().get(p.id).position, p.position);
    s.apply(cmd::PointerDown{s.camera().worldToScreen(p.position), 2.0});
    s.apply(cmd::PointerUp{s.camera().worldToScreen(p.position), 2.05});
    ASSERT_TRUE(s.selection().id());
    EXPECT_EQ(*s.selection().id(), p.id);
    EXPECT_FALSE(s.unsavedChanges());
}

TEST_F(SessionValues, ThePanToolMovesTheView) {
    Session s = session();
    s.apply(cmd::SetTool{cmd::Tool::Pan});
    const Vec2 before = s.camera().worldToScreen(Vec2::Zero());
    const std::size_t n = s.world().size();
    // Screen points: the view moves under the hand.
    const Vec2 from = s.camera().worldToScreen(emptySpot(s));
    s.apply(cmd::PointerDown{from, 1.0});
    for (int k = 1; k <= 5; ++k)
        s.apply(cmd::PointerMove{from + Vec2(20.0 * k, 0.0), 1.0 + 0.02 * k});
    s.apply(cmd::PointerUp{from + Vec2(100.0, 0.0), 1.1});
    const Vec2 after = s.camera().worldToScreen(Vec2::Zero());
    EXPECT_NEAR(after.x() - before.x(), 100.0, 1e-9);
    EXPECT_EQ(s.world().size(), n);
}

TEST_F(SessionValues, ALaunchUsesTheChosenMassRadiusAndColour) {
    Session s = session();
    s.apply(cmd::SetLaunchBody{2.5, 0.2, Color{10, 20, 30}});
    EXPECT_DOUBLE_EQ(s.spawn().mass(), 2.5);
    EXPECT_DOUBLE_EQ(s.spawn().radius(), 0.2);
    const Vec2 at = emptySpot(s);
    drag(s, at, at + Vec2(0.5, 0.0), 1.0);
    const Particle p = s.world().get(s.world().ids().back());
    EXPECT_DOUBLE_EQ(p.mass, 2.5);
    EXPECT_DOUBLE_EQ(p.radius, 0.2);
    EXPECT_EQ(p.color, (Color{10, 20, 30}));
    // Radius 0 follows the mass again; bad values are refused.
    s.apply(cmd::SetLaunchBody{4.0, 0.0, std::nullopt});
    EXPECT_DOUBLE_EQ(s.spawn().radius(), s.spawn().typicalRadius * 4.0 / s.spawn().typicalMass);
    s.apply(cmd::SetLaunchBody{-1.0, 0.1, std::nullopt});
    EXPECT_TRUE(said(s.takeNotices(), "Launch mass must be between"));
    s.apply(cmd::SetLaunchBody{1.0, 100.0, std::nullopt});
    EXPECT_TRUE(said(s.takeNotices(), "Launch radius must be above 0 and at most half the box"));
    EXPECT_DOUBLE_EQ(s.spawn().mass(), 4.0);
}

TEST_F(SessionValues, EditingOneFieldAppliesItOrRefusesWithTheReason) {
    Session s = session();
    const ParticleId id = s.world().ids().front();
    s.apply(cmd::Select{id});
    s.apply(cmd::EditParticle{id, ParticleField::Vx, "1.5"});
    EXPECT_DOUBLE_EQ(s.world().get(id).velocity.x(), 1.5);
    EXPECT_EQ(s.lastAction(), "edit particle");
    EXPECT_TRUE(s.editRefusal().empty());
    const Particle before = s.world().get(id);
    s.apply(cmd::EditParticle{id, ParticleField::X, "100"});
    EXPECT_NE(s.editRefusal().find("x: 100 m is outside the box"), std::string::npos)
        << s.editRefusal();
    s.apply(cmd::EditParticle{id, ParticleField::Mass, "heavy"});
    EXPECT_NE(s.editRefusal().find("mass: 'heavy' is not a number"), std::string::npos);
    s.apply(cmd::EditParticle{id, ParticleField::Radius, "-1"});
    EXPECT_NE(s.editRefusal().find("radius: must be > 0"), std::string::npos);
    const Particle after = s.world().get(id);
    EXPECT_EQ(after.position, before.position);
    EXPECT_EQ(after.mass, before.mass);
    EXPECT_EQ(after.radius, before.radius);
    // Onto another particle: refused, naming it.
    const Particle other = s.world().get(s.world().ids().back());
    s.apply(cmd::EditParticle{id, ParticleField::X, std::to_string(other.position.x())});
    s.apply(
        cmd::EditParticle{id, ParticleField::Y, std::to_string(s.axes().y(other.position.y()))});
    EXPECT_NE(s.editRefusal().find("would overlap the particle at"), std::string::npos)
        << s.editRefusal();
}

TEST_F(SessionValues, YUpShowsAndTakesHeightsFromTheFloorAndUpwardVelocities) {
    Session s = session();
    ASSERT_TRUE(s.view().yUp) << "on by default";
    const double h = s.world().def().height;
    const ParticleId id = s.world().ids().front();
    s.apply(cmd::EditParticle{id, ParticleField::Y, "0.75"});
    ASSERT_TRUE(s.editRefusal().empty()) << s.editRefusal();
    EXPECT_DOUBLE_EQ(s.world().get(id).position.y(), h - 0.75) << "0.75 m above the floor";
    s.apply(cmd::EditParticle{id, ParticleField::Vy, "2"});
    EXPECT_DOUBLE_EQ(s.world().get(id).velocity.y(), -2.0) << "upward: up the screen";
    EXPECT_TRUE(said(s.takeNotices(), "velocity [")) << "the edit is reported";
    // The axes the panel and the exports read: y and vy as typed.
    EXPECT_DOUBLE_EQ(s.axes().y(s.world().get(id).position.y()), 0.75);
    EXPECT_DOUBLE_EQ(s.axes().up(s.world().get(id).velocity.y()), 2.0);
    const std::string table = s.tableText(cmd::DataTable::Values, csv::Separator::Tab);
    EXPECT_NE(table.find("y_up_m"), std::string::npos) << table;
    // Off: y counts down from the top edge, as the scene files do.
    s.apply(cmd::SetShow{cmd::ShowOption::YUp, false});
    EXPECT_FALSE(s.view().yUp);
    s.apply(cmd::EditParticle{id, ParticleField::Y, "0.75"});
    EXPECT_DOUBLE_EQ(s.world().get(id).position.y(), 0.75);
    s.apply(cmd::EditParticle{id, ParticleField::Vy, "2"});
    EXPECT_DOUBLE_EQ(s.world().get(id).velocity.y(), 2.0);
    EXPECT_EQ(s.tableText(cmd::DataTable::Values, csv::Separator::Tab).find("y_up_m"),
              std::string::npos);
}

TEST_F(SessionValues, SelectFromATableAndClear) {
    Session s = session();
    const ParticleId id = s.world().ids().back();
    s.apply(cmd::Select{id});
    ASSERT_TRUE(s.selected());
    EXPECT_EQ(s.selected()->id, id);
    s.apply(cmd::Select{kNullParticle});
    EXPECT_FALSE(s.selected());
}

TEST_F(SessionValues, ShowOptionsAreSetAndTheSideColumnRefitsTheBox) {
    Session s = session();
    s.apply(cmd::SetShow{cmd::ShowOption::Labels, true});
    EXPECT_TRUE(s.view().labels);
    s.apply(cmd::SetShow{cmd::ShowOption::Arrows, false});
    EXPECT_FALSE(s.view().arrows);
    const double w = s.world().def().width;
    const double rightBefore = s.camera().worldToScreen(Vec2(w, 0.0)).x();
    s.apply(cmd::SetShow{cmd::ShowOption::Plots, true});
    EXPECT_TRUE(s.view().plots);
    const double rightAfter = s.camera().worldToScreen(Vec2(w, 0.0)).x();
    EXPECT_LE(rightAfter, 1000.0 - window_.bands.column + 1e-9);
    EXPECT_LT(rightAfter, rightBefore);
    s.apply(cmd::SetTrails{2});
    EXPECT_EQ(s.view().trails, TrailMode::All);
}

TEST_F(SessionValues, TheBoxIsFittedBesideTheControlPanelOpenOrFolded) {
    Session s = session();
    EXPECT_TRUE(s.controlsShown());
    EXPECT_GE(s.camera().worldToScreen(Vec2::Zero()).x(), 310.0);
    s.apply(cmd::ToggleControls{});
    EXPECT_FALSE(s.controlsShown());
    const double x = s.camera().worldToScreen(Vec2::Zero()).x();
    EXPECT_GE(x, 34.0);
    EXPECT_LT(x, 310.0);
}

TEST_F(SessionValues, AWindowTooNarrowForTheBoxBesideTheOpenPanelFoldsItAndSaysSo) {
    // 800 pixels wide, then 400 x 300: the open panel (310 pixels) would leave the box 90.
    Session s = session();
    ASSERT_TRUE(s.controlsShown());
    (void)s.takeNotices();
    WindowLayout narrow = layout();
    narrow.controlsFit = false;
    s.apply(cmd::Resize{400, 300, narrow});
    EXPECT_FALSE(s.controlsShown());
    EXPECT_TRUE(said(s.takeNotices(), "control panel folded"));
    EXPECT_LT(s.camera().worldToScreen(Vec2::Zero()).x(), 310.0);
    // C opens it all the same, over the box, and says so; a wider window keeps it open.
    s.apply(cmd::ToggleControls{});
    EXPECT_TRUE(s.controlsShown());
    EXPECT_TRUE(said(s.takeNotices(), "covers the box"));
    s.apply(cmd::Resize{900, 800, layout()});
    EXPECT_TRUE(s.controlsShown());
}

TEST_F(SessionValues, ABiggerUiScaleInTheSameWindowKeepsThePanelOpenOverTheBox) {
    // The scale's slider is on the panel: the layout the new scale gives (the panel wider than
    // the box leaves room for) comes with the window's own size, and the panel stays open.
    Session s = session();
    ASSERT_TRUE(s.controlsShown());
    (void)s.takeNotices();
    WindowLayout wide = layout();
    wide.controlsFit = false;
    s.apply(cmd::Resize{s.camera().viewportWidth(), s.camera().viewportHeight(), wide});
    EXPECT_TRUE(s.controlsShown()) << "the panel folded under the finger that scaled it";
    EXPECT_TRUE(said(s.takeNotices(), "covers the box at this scale"));
    s.apply(cmd::ToggleControls{});
    EXPECT_FALSE(s.controlsShown()) << "<< folds it";
}

TEST_F(SessionValues, SaveAsWritesThePathAsksBeforeReplacingAFileAndRemembersIt) {
    Session s = session();
    s.apply(cmd::SaveAs{dir_ / "lesson"});
    ASSERT_TRUE(s.lastSave());
    EXPECT_EQ(*s.lastSave(), fs::absolute(dir_ / "lesson.json").lexically_normal());
    EXPECT_TRUE(fs::exists(dir_ / "lesson.json"));
    EXPECT_EQ(loadScene(dir_ / "lesson.json").particles.size(), s.world().size());
    // An existing file is never replaced without asking: the dialog asks, and writes only when
    // the user says Replace.
    s.apply(cmd::SpawnRandom{});
    s.apply(cmd::SaveAs{dir_ / "lesson.json"});
    ASSERT_EQ(s.dialog().kind, Dialog::Kind::SaveAs);
    EXPECT_EQ(s.dialog().replace, fs::absolute(dir_ / "lesson.json").lexically_normal());
    EXPECT_EQ(loadScene(dir_ / "lesson.json").particles.size(), s.world().size() - 1);
    s.apply(cmd::SaveAs{s.dialog().replace, true});
    EXPECT_FALSE(s.dialog().open());
    EXPECT_EQ(loadScene(dir_ / "lesson.json").particles.size(), s.world().size());
    s.apply(cmd::SaveAs{dir_ / "lesson-2.json"});
    ASSERT_EQ(s.recentFiles().size(), 2u);
    EXPECT_EQ(s.recentFiles().front().filename(), "lesson-2.json");
    s.apply(cmd::SaveAs{""});
    EXPECT_TRUE(said(s.takeNotices(), "type a file name first"));
    EXPECT_TRUE(s.fileError().empty());
    s.apply(cmd::SaveAs{dir_ / "no-such-dir" / "x.json"});
    EXPECT_TRUE(said(s.takeNotices(), "Save failed"));
    // The panel shows the failure, not the save before it.
    EXPECT_EQ(s.fileError().rfind("Save failed: ", 0), 0u) << s.fileError();
    s.apply(cmd::OpenFile{dir_ / "no-such-scene.json"});
    EXPECT_EQ(s.fileError().rfind("Cannot open scene: ", 0), 0u) << s.fileError();
    s.apply(cmd::SaveAs{dir_ / "again.json"});
    EXPECT_TRUE(s.fileError().empty());
}

TEST_F(SessionValues, TheSavedLineBelongsToTheSceneSavedAndGoesWhenAnotherOpens) {
    // The Scene section says "Saved to FILE" for the scene shown: after a preset, a new scene
    // or another file it would name a file the scene on screen was never written to.
    Session s = session();
    s.apply(cmd::SaveAs{dir_ / "collision"});
    ASSERT_TRUE(s.lastSave());
    s.apply(cmd::OpenPreset{3});
    EXPECT_FALSE(s.lastSave()) << "the gas was never saved";
    s.apply(cmd::SaveAs{dir_ / "gas"});
    ASSERT_TRUE(s.lastSave());
    s.apply(cmd::NewScene{});
    EXPECT_FALSE(s.lastSave());
    s.apply(cmd::SaveAs{dir_ / "empty"});
    s.apply(cmd::OpenFile{dir_ / "collision.json"});
    EXPECT_FALSE(s.lastSave()) << "opened, not saved";
    EXPECT_EQ(s.sceneFile().path, fs::absolute(dir_ / "collision.json").lexically_normal());
    EXPECT_EQ(s.recentFiles().front().filename(), "collision.json");
}

TEST_F(SessionValues, SaveAsDropsTrailingDotsAndRefusesANameWithoutAStem) {
    Session s = session();
    s.apply(cmd::SaveAs{dir_ / "a."});
    ASSERT_TRUE(s.lastSave());
    EXPECT_EQ(s.lastSave()->filename(), "a.json");
    EXPECT_FALSE(fs::exists(dir_ / "a."));
    s.apply(cmd::SaveAs{dir_ / ".json"});
    EXPECT_TRUE(said(s.takeNotices(), "hidden file"));
    // The panel's status line says why, not "Saved to a.json" from the save before.
    EXPECT_NE(s.fileError().find("hidden file"), std::string::npos) << s.fileError();
    EXPECT_FALSE(fs::exists(dir_ / ".json"));
    EXPECT_FALSE(fs::exists(dir_ / ".json.json"));
    s.apply(cmd::SaveAs{dir_ / "..."});
    EXPECT_TRUE(said(s.takeNotices(), "is not a file name"));
    s.apply(cmd::SaveAs{dir_ / "sub" / ""});
    EXPECT_TRUE(said(s.takeNotices(), "the path ends in a folder"));
    EXPECT_EQ(s.lastSave()->filename(), "a.json");  // the refused names saved nothing
}

TEST_F(SessionValues, AnotherSceneForgetsTheLastOnesOverlap) {
    Session s = session();
    // Two particles pressed into each other, measured by a frame.
    WorldDef def = s.world().def();
    World pressed(def);
    ParticleDef a;
    a.position = {3.0, 3.0};
    a.radius = 0.5;
    pressed.add(a);
    a.position = {3.5, 3.0};
    pressed.add(a);
    s.setWorld(std::move(pressed), SceneInfo{.name = "pressed", .dt = Scene{}.dt});
    s.update(0.0, 0.0);
    ASSERT_GT(s.accuracy().overlap(), 0.4);
    s.setWorld(World(def), SceneInfo{.name = "empty", .dt = Scene{}.dt});
    EXPECT_EQ(s.accuracy().overlap(), 0.0);
}

TEST_F(SessionValues, EveryPresetIsListedWithANameAndAOneLineSummary) {
    Session s = session();
    ASSERT_EQ(s.presets().size(), testPresets().size());
    ASSERT_GE(s.presets().size(), 13u);
    for (const SceneListing& p : s.presets()) {
        EXPECT_FALSE(p.name.empty()) << p.file;
        EXPECT_FALSE(p.summary.empty()) << p.file;
        EXPECT_EQ(p.summary.find('\n'), std::string::npos) << p.file;
        EXPECT_LE(p.summary.size(), p.description.size()) << p.file;
    }
    EXPECT_EQ(s.presets()[1].name, "Newton's cradle");
}

TEST_F(SessionValues, PanelCommandsStillWorkWhileTheEditPromptIsOpen) {
    Session s = session();
    s.apply(cmd::Select{s.world().ids().front()});
    s.apply(cmd::OpenEdit{});
    ASSERT_TRUE(s.prompt().active());
    s.apply(cmd::SetRestitution{0.5});
    EXPECT_DOUBLE_EQ(s.world().def().restitution, 0.5);
}

}  // namespace
}  // namespace psb::app
