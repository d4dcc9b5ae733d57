// The whole App under SDL's dummy video driver: events in, world and files out. Covers what
// lives in the App itself: click routing, the edit prompt taking the keyboard, R, F12.

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <imgui.h>
#include <imgui_internal.h>
#include <stb_image.h>
#include <unistd.h>

#include <particle_sandbox/presets.hpp>
#include <particle_sandbox/scene.hpp>

#include "app.hpp"
#include "core/test_util.hpp"
#include "temp_dir_test.hpp"
#include "view/mass_shade.hpp"
#include "view/palette.hpp"

namespace psb::app {
namespace {

namespace fs = std::filesystem;

class AppTest : public TempDirTest {
  protected:
    AppTest() : TempDirTest("psb-app") {}

    [[nodiscard]] AppOptions options() const {
        AppOptions o;
        o.renderDriver = "software";
        o.width = o.height = 400;
        o.vsync = false;
        o.startPaused = true;
        o.seed = 3;
        o.saveTo = dir_ / "save.json";
        o.screenshotDir = dir_;
        return o;
    }

    static void key(App& app, SDL_Keycode sym, Uint16 mod = KMOD_NONE) {
        SDL_Event e{};
        e.type = SDL_KEYDOWN;
        e.key.keysym.sym = sym;
        e.key.keysym.scancode = SDL_GetScancodeFromKey(sym);
        e.key.keysym.mod = mod;
        app.processEvent(e);
        e.type = SDL_KEYUP;
        app.processEvent(e);
    }
    /// A letter as the keyboard delivers it: the key, then its text (while text input is on).
    static void typeText(App& app, const char* text) {
        for (const char* c = text; *c != '\0'; ++c) {
            if (*c >= 'a' && *c <= 'z') key(app, static_cast<SDL_Keycode>(*c));
            SDL_Event e{};
            e.type = SDL_TEXTINPUT;
            e.text.text[0] = *c;
            app.processEvent(e);
        }
    }
    static void button(App& app, Uint32 type, Vec2 screen, Uint32 ms) {
        SDL_Event e{};
        e.type = type;
        e.button.button = SDL_BUTTON_LEFT;
        e.button.x = static_cast<Sint32>(std::lround(screen.x()));
        e.button.y = static_cast<Sint32>(std::lround(screen.y()));
        e.button.timestamp = ms;
        app.processEvent(e);
    }
    static void motion(App& app, Vec2 screen, Uint32 ms) {
        SDL_Event e{};
        e.type = SDL_MOUSEMOTION;
        e.motion.x = static_cast<Sint32>(std::lround(screen.x()));
        e.motion.y = static_cast<Sint32>(std::lround(screen.y()));
        e.motion.timestamp = ms;
        app.processEvent(e);
    }
    /// A click at world point `at`: press and release 50 ms later, without moving.
    static void click(App& app, Vec2 at, Uint32 ms) {
        const Vec2 s = app.camera().worldToScreen(at);
        button(app, SDL_MOUSEBUTTONDOWN, s, ms);
        button(app, SDL_MOUSEBUTTONUP, s, ms + 50);
    }
    /// A 100 ms drag of 40 px right from world point `at`.
    static void drag(App& app, Vec2 at, Uint32 ms) {
        const Vec2 s = app.camera().worldToScreen(at);
        button(app, SDL_MOUSEBUTTONDOWN, s, ms);
        for (int k = 1; k <= 10; ++k)
            motion(app, s + Vec2(4.0 * k, 0), ms + 10 * k);
        button(app, SDL_MOUSEBUTTONUP, s + Vec2(40, 0), ms + 100);
    }
    /// The fill the particle at `at` is drawn in: its colour (on the light theme, lightColour's)
    /// in the shade of its mass among the scene's (view/mass_shade.hpp).
    static Color fillAt(const App& app, Vec2 at, Theme theme) {
        const Particle p = app.world().get(idAt(app, at));
        const Color colour = theme == Theme::Light ? lightColour(p.color) : p.color;
        const MassRange masses = massRange(app.world().particles().mass);
        if (!masses.varies()) return colour;
        return massShades(colour, theme).at(masses.place(p.mass));
    }

    /// A key pressed and let go as xdotool types it: the key, its text (for a character), the
    /// release, no frame in between.
    static void tap(App& app, SDL_Keycode sym, const char* text = nullptr, Uint16 mod = KMOD_NONE) {
        SDL_Event e{};
        e.type = SDL_KEYDOWN;
        e.key.keysym.sym = sym;
        e.key.keysym.scancode = SDL_GetScancodeFromKey(sym);
        e.key.keysym.mod = mod;
        app.processEvent(e);
        if (text != nullptr) {
            SDL_Event t{};
            t.type = SDL_TEXTINPUT;
            std::snprintf(t.text.text, sizeof t.text.text, "%s", text);
            app.processEvent(t);
        }
        e.type = SDL_KEYUP;
        app.processEvent(e);
    }

    /// `text` typed within one frame: each character's key, its text and its release.
    static void typeFast(App& app, const std::string& text) {
        for (const char c : text) {
            const char s[2] = {c, '\0'};
            const SDL_Keycode sym =
                c == ' ' ? SDLK_SPACE : static_cast<SDL_Keycode>(std::tolower(c));
            tap(app, sym, s, std::isupper(static_cast<unsigned char>(c)) ? KMOD_LSHIFT : KMOD_NONE);
        }
    }

    static void frames(App& app, int n) {
        for (int k = 0; k < n; ++k)
            app.frame(0.0);
    }

    static ParticleId idAt(const App& app, Vec2 at) {
        const auto id = app.world().pick(at);
        EXPECT_TRUE(id.has_value());
        return id.value_or(kNullParticle);
    }
};

// The built-in scene: the 18 kg particle at (5.2, 1.6) m, radius 45 cm; (1.0, 6.2) is empty.
const Vec2 kYellow(5.2, 1.6), kEmpty(1.0, 6.2);

TEST_F(AppTest, AClickSelectsAndAClickOnEmptySpaceDeselects) {
    App app(options());
    EXPECT_FALSE(app.selected().has_value());
    const ParticleId id = idAt(app, kYellow);
    const Vec2 v = app.world().get(id).velocity;
    click(app, kYellow, 1000);
    ASSERT_TRUE(app.selected().has_value());
    EXPECT_EQ(*app.selected(), id);
    EXPECT_EQ(app.world().get(id).velocity, v);  // inspecting does not stop it
    EXPECT_EQ(app.world().size(), 6u);
    click(app, kEmpty, 2000);
    EXPECT_FALSE(app.selected().has_value());
    EXPECT_EQ(app.world().size(), 6u);  // a click launches nothing
}

TEST_F(AppTest, DragsStillLaunchAndFling) {
    App app(options());
    click(app, kYellow, 1000);
    drag(app, kEmpty, 2000);
    EXPECT_EQ(app.world().size(), 7u);
    EXPECT_TRUE(app.selected().has_value());  // a drag does not change the selection
    const ParticleId id = idAt(app, Vec2(2.5, 2.6));
    drag(app, Vec2(2.5, 2.6), 3000);
    EXPECT_GT(app.world().get(id).velocity.x(), 1.0);
}

TEST_F(AppTest, DeletingTheSelectedParticleClearsTheSelection) {
    App app(options());
    click(app, kYellow, 1000);
    ASSERT_TRUE(app.selected().has_value());
    button(app, SDL_MOUSEBUTTONDOWN, app.camera().worldToScreen(kYellow), 2000);
    key(app, SDLK_DELETE);
    button(app, SDL_MOUSEBUTTONUP, app.camera().worldToScreen(kYellow), 2500);
    EXPECT_EQ(app.world().size(), 5u);
    EXPECT_FALSE(app.selected().has_value());
}

TEST_F(AppTest, TheEditPromptTakesLettersAndEscWithoutTogglingOrQuitting) {
    App app(options());
    click(app, kYellow, 1000);
    key(app, SDLK_RETURN);
    ASSERT_TRUE(app.editing());
    const WorldDef before = app.world().def();
    typeText(app, "eg");  // would lower restitution and turn gravity on
    key(app, SDLK_r);     // would reset the scene
    EXPECT_EQ(app.world().def().restitution, before.restitution);
    EXPECT_EQ(app.world().def().gravity, before.gravity);
    key(app, SDLK_F12);  // no text: still a screenshot
    app.frame(0.0);
    EXPECT_TRUE(app.lastScreenshot().has_value());
    key(app, SDLK_ESCAPE);
    EXPECT_FALSE(app.editing());
    EXPECT_TRUE(app.running());
    EXPECT_DOUBLE_EQ(app.world().get(*app.selected()).mass, 18.0);  // cancelled
    key(app, SDLK_ESCAPE);  // nothing open: asks whether to quit
    EXPECT_TRUE(app.running());
    app.frame(0.0);
    key(app, SDLK_RETURN);  // Quit
    EXPECT_FALSE(app.running());
}

TEST_F(AppTest, EnterAppliesAnEditAndARefusedOneChangesNothing) {
    App app(options());
    click(app, kYellow, 1000);
    const ParticleId id = *app.selected();
    key(app, SDLK_RETURN);
    typeText(app, "25");
    key(app, SDLK_TAB);
    key(app, SDLK_TAB);
    typeText(app, "-7");  // vx
    key(app, SDLK_RETURN);
    EXPECT_FALSE(app.editing());
    EXPECT_DOUBLE_EQ(app.world().get(id).mass, 25.0);
    EXPECT_DOUBLE_EQ(app.world().get(id).velocity.x(), -7.0);

    key(app, SDLK_RETURN);
    key(app, SDLK_TAB);
    typeText(app, "-1");  // radius
    const std::uint64_t before = test::stateHash(app.world());
    key(app, SDLK_RETURN);
    EXPECT_TRUE(app.editing());  // open, to correct the value
    EXPECT_EQ(test::stateHash(app.world()), before);
    EXPECT_DOUBLE_EQ(app.world().get(id).radius, 0.45);
}

TEST_F(AppTest, ERestitutionAndGGravityInEveryMode) {
    App app(options());
    key(app, SDLK_e);
    EXPECT_DOUBLE_EQ(app.world().def().restitution, 0.95);
    key(app, SDLK_e, KMOD_LSHIFT);
    key(app, SDLK_e, KMOD_LSHIFT);
    EXPECT_DOUBLE_EQ(app.world().def().restitution, 1.0);
    key(app, SDLK_g);
    EXPECT_EQ(app.world().def().gravity, Vec2(0.0, 9.81));  // Earth's, never scaled by the box
    key(app, SDLK_t);                                       // substep
    ASSERT_EQ(app.world().solver().mode, StepMode::Substep);
    key(app, SDLK_t);  // exact, with gravity on
    EXPECT_EQ(app.world().solver().mode, StepMode::Exact);
    key(app, SDLK_g);  // off
    EXPECT_EQ(app.world().def().gravity, Vec2::Zero());
    key(app, SDLK_g);  // on again, in the exact mode
    EXPECT_EQ(app.world().def().gravity, Vec2(0.0, 9.81));
    EXPECT_EQ(app.world().solver().mode, StepMode::Exact);
    key(app, SDLK_SPACE);
    app.frame(0.1);  // it still steps
    EXPECT_GT(app.world().time(), 0.0);
}

TEST_F(AppTest, RRestoresTheWorldAsLoadedAfterStepsSpawnsDeletionsAndEdits) {
    App app(options());
    const std::uint64_t loaded = test::stateHash(app.world());
    const SolverSettings solver = app.world().solver();

    key(app, SDLK_SPACE);
    app.frame(0.2);  // twelve steps
    key(app, SDLK_SPACE);
    key(app, SDLK_m);         // spawn
    drag(app, kEmpty, 1000);  // launch
    const Vec2 at = app.world().get(app.world().ids()[3]).position;
    click(app, at, 2000);
    key(app, SDLK_RETURN);
    typeText(app, "30");
    key(app, SDLK_RETURN);
    const Vec2 other = app.world().get(app.world().ids()[0]).position;
    button(app, SDL_MOUSEBUTTONDOWN, app.camera().worldToScreen(other), 3000);
    key(app, SDLK_DELETE);
    button(app, SDL_MOUSEBUTTONUP, app.camera().worldToScreen(other), 3500);
    key(app, SDLK_e);
    key(app, SDLK_g);
    key(app, SDLK_t);
    ASSERT_NE(test::stateHash(app.world()), loaded);

    key(app, SDLK_r);
    EXPECT_EQ(test::stateHash(app.world()), loaded);
    EXPECT_EQ(app.world().size(), 6u);
    EXPECT_EQ(app.world().time(), 0.0);
    EXPECT_EQ(app.world().def().restitution, 1.0);
    EXPECT_EQ(app.world().def().gravity, Vec2::Zero());
    EXPECT_EQ(app.world().solver().mode, solver.mode);
    EXPECT_FALSE(app.selected().has_value());
}

TEST_F(AppTest, RRestoresTheSceneAsLoadedEvenIfItsFileChanged) {
    const fs::path file = dir_ / "scene.json";
    Scene s = defaultScene();
    s.particles.resize(2);
    saveScene(s, file);
    AppOptions o = options();
    o.scene = file;
    App app(o);
    const std::uint64_t loaded = test::stateHash(app.world());
    s.particles.resize(1);  // the file changes under the running app
    saveScene(s, file);
    key(app, SDLK_m);
    key(app, SDLK_r);
    EXPECT_EQ(app.world().size(), 2u);
    EXPECT_EQ(test::stateHash(app.world()), loaded);
}

TEST_F(AppTest, ASceneNamedOnTheCommandLineOpensPausedAndCtrlSWritesItsFile) {
    const fs::path file = dir_ / "lesson.json";
    Scene s = defaultScene();
    s.particles.resize(2);
    saveScene(s, file);
    AppOptions o = options();
    o.startPaused = false;
    o.scene = file;
    App app(o);
    EXPECT_TRUE(app.session().paused());
    app.frame(0.2);
    EXPECT_EQ(app.world().time(), 0.0);
    key(app, SDLK_m);
    EXPECT_TRUE(app.session().unsavedChanges());
    // The user opened a file they may write: Ctrl+S writes it, no dialog.
    key(app, SDLK_s, KMOD_LCTRL);
    EXPECT_FALSE(app.session().dialog().open());
    EXPECT_FALSE(app.session().unsavedChanges());
    EXPECT_EQ(loadScene(file).particles.size(), 3u);
    // Ctrl+Shift+S asks for a name; Esc cancels it and writes nothing.
    key(app, SDLK_s, KMOD_LCTRL | KMOD_LSHIFT);
    EXPECT_EQ(app.session().dialog().kind, Dialog::Kind::SaveAs);
    key(app, SDLK_ESCAPE);
    EXPECT_FALSE(app.session().dialog().open());
    EXPECT_TRUE(app.session().running());
}

TEST_F(AppTest, TextAndKeysTypedWithinAFrameReachTheFieldsInTheOrderTyped) {
    // New scene, "10", Tab, "4" typed quicker than a frame (xdotool type): the keys reached
    // ImGui a change a frame while the characters went in at once, and the width read 104.
    AppOptions o = options();
    o.width = o.height = 800;
    App app(o);
    app.frame(0.0);
    key(app, SDLK_n, KMOD_LCTRL);
    frames(app, 3);
    ASSERT_EQ(app.session().dialog().kind, Dialog::Kind::NewScene);
    typeFast(app, "10");
    tap(app, SDLK_TAB);
    typeFast(app, "4");
    tap(app, SDLK_TAB);
    typeFast(app, "0");
    frames(app, 12);
    tap(app, SDLK_RETURN);
    frames(app, 3);
    EXPECT_FALSE(app.session().dialog().open());
    EXPECT_DOUBLE_EQ(app.world().def().width, 10.0);
    EXPECT_DOUBLE_EQ(app.world().def().height, 4.0);
    EXPECT_EQ(app.world().def().gravity, Vec2::Zero());
}

TEST_F(AppTest, TabGivesThePanelTheKeysAndEscGivesThemBack) {
    AppOptions o = options();
    o.width = o.height = 800;  // the panel open
    App app(o);
    app.frame(0.0);
    ASSERT_TRUE(app.session().controlsShown());
    EXPECT_FALSE(app.panelHasKeyboard());
    key(app, SDLK_a);
    EXPECT_FALSE(app.session().view().arrows) << "A is the sandbox's while the panel has no keys";
    key(app, SDLK_TAB);
    app.frame(0.0);
    EXPECT_TRUE(app.panelHasKeyboard());
    const Vec2 centre = app.camera().screenToWorld(Vec2(400, 400));
    key(app, SDLK_a);
    key(app, SDLK_LEFT);
    app.frame(0.0);
    EXPECT_FALSE(app.session().view().arrows) << "A went to the panel";
    EXPECT_TRUE(app.camera().screenToWorld(Vec2(400, 400)).isApprox(centre))
        << "Left moved through the panel, not the view";
    key(app, SDLK_ESCAPE);
    app.frame(0.0);
    EXPECT_FALSE(app.panelHasKeyboard());
    EXPECT_TRUE(app.running()) << "that Esc was the panel's: no quit";
    key(app, SDLK_a);
    EXPECT_TRUE(app.session().view().arrows) << "the keys are the sandbox's again";
    // While the edit prompt is open Tab is its own (next field), never the panel's.
    click(app, kYellow, 1000);
    key(app, SDLK_RETURN);
    ASSERT_TRUE(app.editing());
    key(app, SDLK_TAB);
    app.frame(0.0);
    EXPECT_FALSE(app.panelHasKeyboard());
}

TEST_F(AppTest, TabReachesPlayAndSpaceStartsTimeAndSpaceAgainStopsIt) {
    AppOptions o = options();
    o.width = o.height = 800;  // the panel open
    App app(o);
    app.frame(0.0);
    // Each key pressed and let go before the next frame, as a quick hand or xdotool does: ImGui
    // 1.86 reads the keys at the frame, and lost such a tap (a second Space did nothing).
    const auto press = [&app](SDL_Keycode sym) {
        key(app, sym);
        app.frame(0.0);
        app.frame(0.0);
    };
    const auto cursorOn = [&app](const char* name) {
        const PanelItem* i = app.panel().item(name);
        return i != nullptr && GImGui != nullptr && GImGui->NavId == i->id;
    };
    // Tab walks the panel's controls, buttons included: the fold button, the Time section, Play.
    for (int k = 0; k < 3 && !cursorOn("Play/Pause"); ++k) {
        press(SDLK_TAB);
        ASSERT_TRUE(app.panelHasKeyboard());
    }
    ASSERT_TRUE(cursorOn("Play/Pause")) << "three Tabs reach Play";
    ASSERT_TRUE(app.session().paused());
    press(SDLK_SPACE);
    EXPECT_FALSE(app.session().paused()) << "Space on Play starts time";
    EXPECT_TRUE(cursorOn("Play/Pause")) << "the cursor stays on the button, now Pause";
    EXPECT_TRUE(app.panelHasKeyboard());
    press(SDLK_SPACE);
    EXPECT_TRUE(app.session().paused()) << "Space on Pause stops it";
    EXPECT_TRUE(cursorOn("Play/Pause"));
    press(SDLK_TAB);
    EXPECT_TRUE(cursorOn("Step")) << "Tab goes on from the cursor, not back to the top";
}

TEST_F(AppTest, TheUiScaleAndThemeAreKeptInTheSettingsFileAndReadAtTheNextStart) {
    AppOptions o = options();
    o.width = o.height = 800;
    o.settingsFile = dir_ / "config" / "particle-sandbox" / "settings.json";
    int hudAtOne = 0;
    {
        App app(o);
        app.frame(0.0);
        hudAtOne = app.lastFrame().layout.hud.h;
        EXPECT_EQ(app.session().view().uiScale, 1.0);
        EXPECT_FALSE(std::filesystem::exists(*o.settingsFile)) << "nothing changed yet";
        key(app, SDLK_t, KMOD_LCTRL);
        for (int k = 0; k < 5; ++k)  // 110, 125, 150, 175, 200 %
            key(app, SDLK_EQUALS, KMOD_LCTRL);
        app.frame(0.0);
        EXPECT_EQ(app.session().view().uiScale, 2.0);
        EXPECT_EQ(app.session().view().theme, Theme::Light);
        EXPECT_GT(app.lastFrame().layout.hud.h, 1.8 * hudAtOne) << "the HUD's text is bigger";
        ASSERT_TRUE(std::filesystem::exists(*o.settingsFile));
    }
    App again(o);
    again.frame(0.0);
    EXPECT_EQ(again.session().view().uiScale, 2.0);
    EXPECT_FALSE(again.session().view().uiScaleAutomatic);
    EXPECT_EQ(again.session().view().theme, Theme::Light);
    EXPECT_GT(again.lastFrame().layout.hud.h, 1.8 * hudAtOne);
    // Ctrl+0: automatic again (100 % for an 800-point window), and the file says so.
    key(again, SDLK_0, KMOD_LCTRL);
    again.frame(0.0);
    EXPECT_TRUE(again.session().view().uiScaleAutomatic);
    EXPECT_EQ(again.session().view().uiScale, 1.0);
    EXPECT_EQ(again.lastFrame().layout.hud.h, hudAtOne);
    std::ifstream in(*o.settingsFile);
    const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    EXPECT_NE(text.find("\"scale\": \"auto\""), std::string::npos) << text;
}

TEST_F(AppTest, ABrokenSettingsFileIsReportedAndIgnored) {
    AppOptions o = options();
    o.settingsFile = dir_ / "settings.json";
    std::ofstream(*o.settingsFile) << "{\"ui\": {\"theme\": ";
    App app(o);
    app.frame(0.0);
    EXPECT_EQ(app.session().view().theme, Theme::Dark);
    const auto shown = app.messages();
    EXPECT_TRUE(std::any_of(shown.begin(), shown.end(), [&](const std::string& m) {
        return m.find(o.settingsFile->string()) != std::string::npos &&
               m.find("not JSON") != std::string::npos;
    })) << "the message names the file and what is wrong";
}

TEST_F(AppTest, TheLightThemeDrawsALightWindow) {
    App app(options());
    key(app, SDLK_t, KMOD_LCTRL);
    key(app, SDLK_F12);
    app.frame(0.0);
    ASSERT_TRUE(app.lastScreenshot().has_value());
    int w = 0, h = 0, n = 0;
    unsigned char* px = stbi_load(app.lastScreenshot()->c_str(), &w, &h, &n, 3);
    ASSERT_NE(px, nullptr) << stbi_failure_reason();
    const Vec2 c = app.camera().worldToScreen(kEmpty);
    const std::size_t i = 3 * (static_cast<std::size_t>(std::lround(c.y())) * w +
                               static_cast<std::size_t>(std::lround(c.x())));
    EXPECT_EQ(px[i], 255);
    EXPECT_EQ(px[i + 1], 255);
    EXPECT_EQ(px[i + 2], 255);
    // The yellow particle becomes Okabe–Ito's orange, seen on white, in the shade of its
    // 18 kg among the scene's masses.
    const Vec2 y = app.camera().worldToScreen(kYellow);
    const std::size_t j = 3 * (static_cast<std::size_t>(std::lround(y.y())) * w +
                               static_cast<std::size_t>(std::lround(y.x())));
    const Color fill = fillAt(app, kYellow, Theme::Light);
    EXPECT_EQ(lightColour(app.world().get(idAt(app, kYellow)).color), (Color{230, 159, 0}));
    EXPECT_NEAR(px[j], fill.r, 8);
    EXPECT_NEAR(px[j + 1], fill.g, 8);
    EXPECT_NEAR(px[j + 2], fill.b, 8);
    stbi_image_free(px);
}

TEST_F(AppTest, F12WritesTheWindowAsAPng) {
    App app(options());
    key(app, SDLK_F12);
    app.frame(0.0);
    ASSERT_TRUE(app.lastScreenshot().has_value());
    EXPECT_EQ(app.lastScreenshot()->parent_path(), dir_);
    int w = 0, h = 0, n = 0;
    unsigned char* px = stbi_load(app.lastScreenshot()->c_str(), &w, &h, &n, 3);
    ASSERT_NE(px, nullptr) << stbi_failure_reason();
    EXPECT_EQ(w, app.camera().viewportWidth());
    EXPECT_EQ(h, app.camera().viewportHeight());
    // The yellow particle's centre is drawn in its colour (255, 210, 110) in the shade of its
    // mass among the scene's.
    const Vec2 c = app.camera().worldToScreen(kYellow);
    const std::size_t i = 3 * (static_cast<std::size_t>(std::lround(c.y())) * w +
                               static_cast<std::size_t>(std::lround(c.x())));
    const Color fill = fillAt(app, kYellow, Theme::Dark);
    EXPECT_NEAR(px[i], fill.r, 8);
    EXPECT_NEAR(px[i + 1], fill.g, 8);
    EXPECT_NEAR(px[i + 2], fill.b, 8);
    stbi_image_free(px);
}

TEST_F(AppTest, CtrlRRecordsTheBoxsSideOfTheWindowAndCtrlRAgainSavesIt) {
    if (const auto why = videoFormatProblem(VideoFormat::Mp4)) GTEST_SKIP() << *why;
    App app(options());
    key(app, SDLK_r, KMOD_LCTRL);
    app.frame(0.0);
    // The mark says so on the screen; the panel's button too.
    ASSERT_TRUE(app.lastFrame().recordingMark.has_value());
    EXPECT_NE(app.lastFrame().recordingMark->label.find("REC 0:00 MP4"), std::string::npos);
    const auto said = [&](const std::string& text) {
        for (const std::string& m : app.messages())
            if (m.find(text) != std::string::npos) return true;
        return false;
    };
    EXPECT_TRUE(said("Recording video (MP4, ")) << ::testing::PrintToString(app.messages());
    // That message is for the one at the screen: drawn after the video takes the frame.
    EXPECT_TRUE(app.lastFrame().overlays.messagesAfterCapture);
    for (int i = 0; i < 20; ++i) {
        SDL_Delay(20);  // real time: a frame every 20 ms fills about one 60 Hz slot in each
        app.frame(0.02);
    }
    key(app, SDLK_r, KMOD_LCTRL);
    app.frame(0.0);
    EXPECT_FALSE(app.lastFrame().recordingMark.has_value());
    EXPECT_FALSE(app.lastFrame().overlays.messagesAfterCapture);
    EXPECT_TRUE(said("Saved video " + dir_.string())) << ::testing::PrintToString(app.messages());
    std::vector<fs::path> videos;
    for (const auto& e : fs::directory_iterator(dir_))
        if (e.path().extension() == ".mp4") videos.push_back(e.path());
    ASSERT_EQ(videos.size(), 1u);
    // Plain R still restarts: no second video.
    key(app, SDLK_r);
    app.frame(0.0);
    EXPECT_FALSE(app.lastFrame().recordingMark.has_value());
}

TEST_F(AppTest, AfterAFingerTheVideosMessageAndMarkNameThePanelsButtonNotCtrlR) {
    // A laptop's touch screen: the panel's Record video starts it (here Ctrl+R, the same
    // command), and what is said names the button that stops it.
    if (const auto why = videoFormatProblem(VideoFormat::Mp4)) GTEST_SKIP() << *why;
    App app(options());
    SDL_Event finger{};
    finger.type = SDL_FINGERDOWN;
    finger.tfinger.x = finger.tfinger.y = 0.9f;
    app.processEvent(finger);
    finger.type = SDL_FINGERUP;
    app.processEvent(finger);
    app.frame(0.0);
    ASSERT_TRUE(app.session().touch());
    key(app, SDLK_r, KMOD_LCTRL);
    app.frame(0.0);
    ASSERT_TRUE(app.lastFrame().recordingMark.has_value());
    EXPECT_EQ(app.lastFrame().recordingMark->label, "REC 0:00 MP4 - Video: Stop video");
    const std::vector<std::string> said = app.messages();
    EXPECT_TRUE(std::any_of(said.begin(), said.end(), [](const std::string& m) {
        return m.starts_with("Recording video (MP4, ") && m.ends_with(": Video: Stop video");
    })) << ::testing::PrintToString(said);
    for (const std::string& m : said)
        EXPECT_EQ(m.find("Ctrl+R"), std::string::npos) << m;
    key(app, SDLK_r, KMOD_LCTRL);
    app.frame(0.0);
}

TEST_F(AppTest, AVideoStillRecordingIsCompletedWhenTheAppCloses) {
    if (const auto why = videoFormatProblem(VideoFormat::Gif)) GTEST_SKIP() << *why;
    AppOptions o = options();
    o.record = VideoFormat::Gif;
    {
        App app(o);
        for (int i = 0; i < 5; ++i) {
            SDL_Delay(40);
            app.frame(0.04);
        }
    }
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(dir_))
        files.push_back(e.path());
    ASSERT_EQ(files.size(), 1u);
    EXPECT_EQ(files[0].extension(), ".gif");  // complete: no part file left
    EXPECT_GT(fs::file_size(files[0]), 100u);
}

}  // namespace
}  // namespace psb::app
