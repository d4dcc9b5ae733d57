// The key map and the mouse: SDL events to commands, without a window.

#include <gtest/gtest.h>

#include "platform/input.hpp"
#include "platform/sdl_context.hpp"

namespace psb::app {
namespace {

SDL_KeyboardEvent keyEvent(SDL_Keycode sym, Uint16 mod = KMOD_NONE, Uint8 repeat = 0) {
    SDL_KeyboardEvent k{};
    k.type = SDL_KEYDOWN;
    k.keysym.sym = sym;
    k.keysym.mod = mod;
    k.repeat = repeat;
    return k;
}

template <class T>
bool is(const std::vector<Command>& c) {
    return c.size() == 1 && std::holds_alternative<T>(c.front());
}

TEST(Input, CtrlPlusMinusAndZeroStepTheUiScaleAndCtrlTSwitchesTheTheme) {
    KeyState now;
    now.view.uiScale = 1.5;
    for (const SDL_Keycode plus : {SDLK_EQUALS, SDLK_PLUS, SDLK_KP_PLUS}) {
        const auto c = commandsForKey(keyEvent(plus, KMOD_LCTRL), now);
        ASSERT_TRUE(is<cmd::SetUiScale>(c));
        EXPECT_EQ(std::get<cmd::SetUiScale>(c.front()).scale, 1.75);
        EXPECT_FALSE(std::get<cmd::SetUiScale>(c.front()).automatic);
    }
    for (const SDL_Keycode minus : {SDLK_MINUS, SDLK_KP_MINUS}) {
        const auto c = commandsForKey(keyEvent(minus, KMOD_RCTRL), now);
        ASSERT_TRUE(is<cmd::SetUiScale>(c));
        EXPECT_EQ(std::get<cmd::SetUiScale>(c.front()).scale, 1.25);
    }
    const auto zero = commandsForKey(keyEvent(SDLK_0, KMOD_LCTRL), now);
    ASSERT_TRUE(is<cmd::SetUiScale>(zero)) << "Ctrl+0 is not preset 10";
    EXPECT_TRUE(std::get<cmd::SetUiScale>(zero.front()).automatic);
    EXPECT_TRUE(is<cmd::OpenPreset>(commandsForKey(keyEvent(SDLK_0), now))) << "plain 0 still is";
    EXPECT_TRUE(commandsForKey(keyEvent(SDLK_EQUALS), now).empty());
    const auto theme = commandsForKey(keyEvent(SDLK_t, KMOD_LCTRL), now);
    ASSERT_TRUE(is<cmd::SetTheme>(theme));
    EXPECT_EQ(std::get<cmd::SetTheme>(theme.front()).theme, Theme::Light);
    now.view.theme = Theme::Light;
    EXPECT_EQ(
        std::get<cmd::SetTheme>(commandsForKey(keyEvent(SDLK_t, KMOD_LCTRL), now).front()).theme,
        Theme::Dark);
    EXPECT_TRUE(is<cmd::SetMode>(commandsForKey(keyEvent(SDLK_t), now))) << "plain T: the mode";
    // The edit prompt has the keyboard: none of them reach the view.
    now.editing = true;
    EXPECT_TRUE(commandsForKey(keyEvent(SDLK_EQUALS, KMOD_LCTRL), now).empty());
}

TEST(Input, EveryKeyOfTheHelpMapsToItsCommand) {
    const auto labels = commandsForKey(keyEvent(SDLK_s), KeyState{});
    ASSERT_TRUE(is<cmd::SetShow>(labels));
    EXPECT_EQ(std::get<cmd::SetShow>(labels.front()).option, ShowOption::Labels);
    EXPECT_TRUE(std::get<cmd::SetShow>(labels.front()).on);  // off at first: S turns them on
    EXPECT_TRUE(is<cmd::Save>(commandsForKey(keyEvent(SDLK_s, KMOD_LCTRL), KeyState{})));
    KeyState now;
    now.restitution = 0.9;
    now.solver.mode = StepMode::Substep;
    now.solver.substeps = 6;
    now.timeScale = 2.0;
    const auto t = commandsForKey(keyEvent(SDLK_t), now);
    ASSERT_TRUE(is<cmd::SetMode>(t));
    EXPECT_EQ(std::get<cmd::SetMode>(t.front()).mode, StepMode::Exact);
    EXPECT_EQ(std::get<cmd::SetMode>(t.front()).substeps, 6);
    EXPECT_TRUE(is<cmd::Back>(commandsForKey(keyEvent(SDLK_ESCAPE), KeyState{})));
    EXPECT_TRUE(is<cmd::DeleteHeld>(commandsForKey(keyEvent(SDLK_DELETE), KeyState{})));
    EXPECT_TRUE(is<cmd::SpawnRandom>(commandsForKey(keyEvent(SDLK_m), KeyState{})));
    const auto e = commandsForKey(keyEvent(SDLK_e, KMOD_LSHIFT), now);
    ASSERT_TRUE(is<cmd::SetRestitution>(e));
    EXPECT_DOUBLE_EQ(std::get<cmd::SetRestitution>(e.front()).value, 0.95);
    const auto g = commandsForKey(keyEvent(SDLK_g), now);
    ASSERT_TRUE(is<cmd::SetGravity>(g));
    EXPECT_TRUE(std::get<cmd::SetGravity>(g.front()).on);
    const auto faster = commandsForKey(keyEvent(SDLK_PERIOD), now);
    ASSERT_TRUE(is<cmd::SetTimeScale>(faster));
    EXPECT_EQ(std::get<cmd::SetTimeScale>(faster.front()).value, 4.0);
    const auto preset = commandsForKey(keyEvent(SDLK_3), KeyState{});
    ASSERT_TRUE(is<cmd::OpenPreset>(preset));
    EXPECT_EQ(std::get<cmd::OpenPreset>(preset.front()).index, 2);
}

TEST(Input, XStartsRecordingAndStopsIt) {
    const auto start = commandsForKey(keyEvent(SDLK_x), KeyState{});
    ASSERT_TRUE(is<cmd::SetRecording>(start));
    EXPECT_TRUE(std::get<cmd::SetRecording>(start.front()).on);
    EXPECT_EQ(std::get<cmd::SetRecording>(start.front()).every, 0) << "the last choice";
    KeyState recording;
    recording.recording = true;
    const auto stop = commandsForKey(keyEvent(SDLK_x), recording);
    ASSERT_TRUE(is<cmd::SetRecording>(stop));
    EXPECT_FALSE(std::get<cmd::SetRecording>(stop.front()).on);
}

TEST(Input, CtrlRTogglesTheVideoAndPlainRRestarts) {
    const auto video = commandsForKey(keyEvent(SDLK_r, KMOD_LCTRL), KeyState{});
    ASSERT_TRUE(is<cmd::ToggleVideo>(video));
    // The key records with the last settings the panel chose: it carries none of its own.
    EXPECT_FALSE(std::get<cmd::ToggleVideo>(video.front()).settings.has_value());
    EXPECT_TRUE(is<cmd::Restart>(commandsForKey(keyEvent(SDLK_r), KeyState{})));
}

TEST(Input, WAndBChooseTheWallAndPegToolsAsAToggle) {
    const auto w = commandsForKey(keyEvent(SDLK_w), KeyState{});
    ASSERT_TRUE(is<cmd::SetTool>(w));
    EXPECT_EQ(std::get<cmd::SetTool>(w.front()).tool, cmd::Tool::Wall);
    EXPECT_TRUE(std::get<cmd::SetTool>(w.front()).toggle);
    const auto b = commandsForKey(keyEvent(SDLK_b), KeyState{});
    ASSERT_TRUE(is<cmd::SetTool>(b));
    EXPECT_EQ(std::get<cmd::SetTool>(b.front()).tool, cmd::Tool::Peg);
    EXPECT_TRUE(commandsForKey(keyEvent(SDLK_w), KeyState{.editing = true})
                    .empty());  // typed into the prompt
    EXPECT_TRUE(commandsForKey(keyEvent(SDLK_w, KMOD_NONE, 1), KeyState{}).empty());  // no repeat
}

TEST(Input, EveryPresetUpTo19HasAKeyAndTheKeyItsName) {
    // 1-9 the first nine, 0 the tenth, Shift+1-9 the 11th to the 19th: the 14 presets each
    // have one, and the message that opens one names the key that does.
    const auto index = [](SDL_Keycode sym, Uint16 mod) {
        const auto c = commandsForKey(keyEvent(sym, mod), KeyState{});
        EXPECT_TRUE(is<cmd::OpenPreset>(c));
        return is<cmd::OpenPreset>(c) ? std::get<cmd::OpenPreset>(c.front()).index : -2;
    };
    EXPECT_EQ(index(SDLK_1, KMOD_NONE), 0);
    EXPECT_EQ(index(SDLK_9, KMOD_NONE), 8);
    EXPECT_EQ(index(SDLK_0, KMOD_NONE), 9);
    EXPECT_EQ(index(SDLK_1, KMOD_LSHIFT), 10);
    EXPECT_EQ(index(SDLK_3, KMOD_RSHIFT), 12);
    EXPECT_EQ(index(SDLK_9, KMOD_LSHIFT), 18);
    for (int i = 0; i < 19; ++i) {
        const std::string key = cmd::presetKey(i);
        ASSERT_FALSE(key.empty()) << i;
        const bool shift = key.rfind("Shift+", 0) == 0;
        const int digit = key.back() - '0';
        EXPECT_EQ(cmd::presetForDigit(digit, shift), i) << key;
    }
    EXPECT_TRUE(cmd::presetKey(19).empty());
}

TEST(Input, OnlyPanStepAndMassKeysRepeat) {
    EXPECT_TRUE(commandsForKey(keyEvent(SDLK_SPACE, KMOD_NONE, 1), KeyState{}).empty());
    EXPECT_TRUE(is<cmd::Pan>(commandsForKey(keyEvent(SDLK_LEFT, KMOD_NONE, 1), KeyState{})));
    EXPECT_TRUE(is<cmd::SingleStep>(commandsForKey(keyEvent(SDLK_n, KMOD_NONE, 1), KeyState{})));
}

TEST(Input, WhileEditingOnlyThePromptsKeysMeanAnything) {
    EXPECT_TRUE(commandsForKey(keyEvent(SDLK_g), KeyState{.editing = true}).empty());
    EXPECT_TRUE(is<cmd::EditField>(commandsForKey(keyEvent(SDLK_TAB), KeyState{.editing = true})));
    EXPECT_TRUE(
        is<cmd::EditApply>(commandsForKey(keyEvent(SDLK_RETURN), KeyState{.editing = true})));
    EXPECT_TRUE(is<cmd::Back>(commandsForKey(keyEvent(SDLK_ESCAPE), KeyState{.editing = true})));
    EXPECT_TRUE(is<cmd::Screenshot>(commandsForKey(keyEvent(SDLK_F12), KeyState{.editing = true})));
}

TEST(Input, TheQuitDialogsEnterQuitsWithNothingUnsavedAndSavesOtherwise) {
    KeyState clean;
    clean.dialog.kind = Dialog::Kind::Quit;
    const auto enter = commandsForKey(keyEvent(SDLK_RETURN), clean);
    ASSERT_TRUE(is<cmd::AnswerQuit>(enter));
    EXPECT_EQ(std::get<cmd::AnswerQuit>(enter.front()).choice, cmd::AnswerQuit::Choice::Quit);
    EXPECT_TRUE(is<cmd::Back>(commandsForKey(keyEvent(SDLK_ESCAPE), clean)));
    EXPECT_TRUE(commandsForKey(keyEvent(SDLK_d), clean).empty()) << "nothing to discard";
    KeyState unsaved = clean;
    unsaved.dialog.unsaved = true;
    const auto save = commandsForKey(keyEvent(SDLK_RETURN), unsaved);
    ASSERT_TRUE(is<cmd::AnswerQuit>(save));
    EXPECT_EQ(std::get<cmd::AnswerQuit>(save.front()).choice, cmd::AnswerQuit::Choice::Save);
    const auto discard = commandsForKey(keyEvent(SDLK_d), unsaved);
    ASSERT_TRUE(is<cmd::AnswerQuit>(discard));
    EXPECT_EQ(std::get<cmd::AnswerQuit>(discard.front()).choice, cmd::AnswerQuit::Choice::Discard);
}

TEST(Input, MouseCoordinatesAreScaledToDrawablePixels) {
    Input in;
    SDL_Event e{};
    e.type = SDL_MOUSEBUTTONDOWN;
    e.button.button = SDL_BUTTON_LEFT;
    e.button.x = 100;
    e.button.y = 50;
    e.button.timestamp = 2000;
    const auto c = in.translate(e, KeyState{}, 2.0, SDL_Point{1600, 1600});  // a high-DPI screen
    ASSERT_TRUE(is<cmd::PointerDown>(c));
    EXPECT_EQ(std::get<cmd::PointerDown>(c.front()).screen, Vec2(200, 100));
    EXPECT_DOUBLE_EQ(std::get<cmd::PointerDown>(c.front()).time, 2.0);
}

TEST(Input, AFingerLiftedOrAMouseThatLeftIsAPointerGone) {
    // The Peg tool's shade stayed where a finger lifted: a lift is the pointer's leaving too.
    Input in;
    SDL_Event up{};
    up.type = SDL_MOUSEBUTTONUP;
    up.button.button = SDL_BUTTON_LEFT;
    up.button.which = SDL_TOUCH_MOUSEID;
    up.button.x = 100;
    up.button.y = 50;
    const auto lifted = in.translate(up, KeyState{}, 1.0, SDL_Point{800, 800});
    ASSERT_EQ(lifted.size(), 2u);
    EXPECT_TRUE(std::holds_alternative<cmd::PointerUp>(lifted[0]));
    EXPECT_TRUE(std::holds_alternative<cmd::PointerLeave>(lifted[1]));
    up.button.which = 0;  // a mouse's release: it is still there
    const auto released = in.translate(up, KeyState{}, 1.0, SDL_Point{800, 800});
    ASSERT_EQ(released.size(), 1u);
    EXPECT_TRUE(std::holds_alternative<cmd::PointerUp>(released[0]));
    SDL_Event left{};
    left.type = SDL_WINDOWEVENT;
    left.window.event = SDL_WINDOWEVENT_LEAVE;
    const auto gone = in.translate(left, KeyState{}, 1.0, SDL_Point{800, 800});
    ASSERT_EQ(gone.size(), 1u);
    EXPECT_TRUE(std::holds_alternative<cmd::PointerLeave>(gone[0]));
}

TEST(Input, ARightDragPans) {
    Input in;
    SDL_Event e{};
    e.type = SDL_MOUSEBUTTONDOWN;
    e.button.button = SDL_BUTTON_RIGHT;
    e.button.x = 10;
    e.button.y = 10;
    EXPECT_TRUE(in.translate(e, KeyState{}, 1.0, SDL_Point{800, 800}).empty());
    SDL_Event m{};
    m.type = SDL_MOUSEMOTION;
    m.motion.x = 30;
    m.motion.y = 5;
    const auto c = in.translate(m, KeyState{}, 1.0, SDL_Point{800, 800});
    ASSERT_EQ(c.size(), 2u);
    ASSERT_TRUE(std::holds_alternative<cmd::Pan>(c.front()));
    EXPECT_EQ(std::get<cmd::Pan>(c.front()).pixels, Vec2(20, -5));
}

TEST(Renderer, AnOpenGLSoftwareRasteriserIsRecognised) {
    EXPECT_TRUE(isSoftwareRasteriser("llvmpipe (LLVM 15.0.6, 256 bits)"));
    EXPECT_TRUE(isSoftwareRasteriser("softpipe"));
    EXPECT_FALSE(isSoftwareRasteriser("Mesa Intel(R) UHD Graphics 620 (KBL GT2)"));
    EXPECT_FALSE(isSoftwareRasteriser(""));
}

TEST(Renderer, AWindowlessVideoDriverNobodyAskedForIsAnError) {
    // X refused the connection ("Authorization required"): SDL went on with "offscreen".
    const std::string why = noWindowReason("offscreen", nullptr, ":99", nullptr);
    EXPECT_NE(why.find("cannot open a window"), std::string::npos) << why;
    EXPECT_NE(why.find("DISPLAY=:99"), std::string::npos) << why;
    EXPECT_NE(why.find("WAYLAND_DISPLAY unset"), std::string::npos) << why;
    EXPECT_NE(why.find("'offscreen'"), std::string::npos) << why;
    EXPECT_FALSE(noWindowReason("dummy", nullptr, nullptr, nullptr).empty());
    // Asked for by name (the tests' SDL_VIDEODRIVER=dummy), or a real display: no error.
    EXPECT_EQ(noWindowReason("dummy", "dummy", nullptr, nullptr), "");
    EXPECT_EQ(noWindowReason("offscreen", "offscreen", ":99", nullptr), "");
    EXPECT_EQ(noWindowReason("x11", nullptr, ":99", nullptr), "");
    EXPECT_EQ(noWindowReason("wayland", nullptr, nullptr, "wayland-0"), "");
    EXPECT_EQ(noWindowReason("KMSDRM", nullptr, nullptr, nullptr), "");
}

TEST(Input, UndoRedoAndStepBackKeysLeaveThePlainKeysAsTheyWere) {
    EXPECT_TRUE(is<cmd::Undo>(commandsForKey(keyEvent(SDLK_z, KMOD_LCTRL), KeyState{})));
    EXPECT_TRUE(
        is<cmd::Redo>(commandsForKey(keyEvent(SDLK_z, KMOD_LCTRL | KMOD_LSHIFT), KeyState{})));
    EXPECT_TRUE(is<cmd::Redo>(commandsForKey(keyEvent(SDLK_y, KMOD_RCTRL), KeyState{})));
    EXPECT_TRUE(
        is<cmd::Undo>(commandsForKey(keyEvent(SDLK_z, KMOD_LCTRL, 1), KeyState{})));  // held
    EXPECT_TRUE(commandsForKey(keyEvent(SDLK_z), KeyState{}).empty());
    EXPECT_TRUE(commandsForKey(keyEvent(SDLK_y), KeyState{}).empty());
    EXPECT_TRUE(commandsForKey(keyEvent(SDLK_z, KMOD_LCTRL), KeyState{.editing = true})
                    .empty());  // editing
    EXPECT_TRUE(is<cmd::StepBack>(commandsForKey(keyEvent(SDLK_LEFT, KMOD_LSHIFT), KeyState{})));
    EXPECT_TRUE(
        is<cmd::StepForward>(commandsForKey(keyEvent(SDLK_RIGHT, KMOD_RSHIFT, 1), KeyState{})));
    EXPECT_TRUE(is<cmd::Pan>(commandsForKey(keyEvent(SDLK_LEFT), KeyState{})));
    EXPECT_TRUE(is<cmd::Pan>(commandsForKey(keyEvent(SDLK_RIGHT), KeyState{})));
    const auto back = commandsForKey(keyEvent(SDLK_PAGEUP), KeyState{});
    ASSERT_TRUE(is<cmd::SeekBy>(back));
    EXPECT_EQ(std::get<cmd::SeekBy>(back.front()).seconds, -kSeekKeySeconds);
    EXPECT_TRUE(is<cmd::SeekBy>(commandsForKey(keyEvent(SDLK_PAGEDOWN), KeyState{})));
}

}  // namespace
}  // namespace psb::app
