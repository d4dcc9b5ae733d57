#include "platform/input.hpp"

#include <cmath>

#include "platform/clock.hpp"
#include "session/physics_controls.hpp"
#include "session/session.hpp"

namespace psb::app {

namespace {

std::vector<Command> editKey(const SDL_KeyboardEvent& key) {
    // Characters arrive as SDL_TEXTINPUT; here only the keys that steer the prompt, and F12,
    // which types nothing and may well be wanted for a picture of the prompt.
    switch (key.keysym.sym) {
        case SDLK_F12:
            return {cmd::Screenshot{}};
        case SDLK_ESCAPE:
            return {cmd::Back{}};
        case SDLK_TAB:
            return {cmd::EditField{(key.keysym.mod & KMOD_SHIFT) != 0}};
        case SDLK_BACKSPACE:
            return {cmd::EditBackspace{}};
        case SDLK_RETURN:
        case SDLK_KP_ENTER:
            if (key.repeat != 0) return {};
            return {cmd::EditApply{}};
        default:
            return {};
    }
}

/// The keys of an open dialog (when ImGui does not take them: its text field takes Enter).
std::vector<Command> dialogKey(const SDL_KeyboardEvent& key, const Dialog& dialog) {
    if (key.repeat != 0) return {};
    switch (key.keysym.sym) {
        case SDLK_ESCAPE:
            return {cmd::Back{}};
        case SDLK_F12:
            return {cmd::Screenshot{}};
        case SDLK_RETURN:
        case SDLK_KP_ENTER:
            switch (dialog.kind) {
                case Dialog::Kind::Quit:
                    return {cmd::AnswerQuit{dialog.unsaved ? cmd::AnswerQuit::Choice::Save
                                                           : cmd::AnswerQuit::Choice::Quit}};
                case Dialog::Kind::SaveAs:
                    if (!dialog.replace.empty()) return {cmd::SaveAs{dialog.replace, true}};
                    return {cmd::SaveAs{dialog.proposal, false}};
                case Dialog::Kind::NewScene: {
                    const NewSceneSpec& n = dialog.newScene;
                    return {cmd::NewScene{n.width, n.height, n.gravity, n.walls}};
                }
                case Dialog::Kind::None:
                    break;
            }
            return {};
        case SDLK_d:
            if (dialog.kind == Dialog::Kind::Quit && dialog.unsaved) {
                return {cmd::AnswerQuit{cmd::AnswerQuit::Choice::Discard}};
            }
            return {};
        default:
            return {};
    }
}

/// What a key that shows or hides `option` sends: the other value.
cmd::SetShow show(const KeyState& state, ShowOption option) {
    return {option, !state.view.shown(option)};
}

}  // namespace

KeyState keyState(const Session& session) {
    KeyState k;
    k.editing = session.prompt().active();
    k.dialog = session.dialog();
    k.restitution = session.world().def().restitution;
    k.gravity = session.world().def().gravity;
    k.sceneGravity = session.loadedWorld().def().gravity;
    k.solver = session.world().solver();
    k.timeScale = session.timeScale();
    k.view = session.view();
    k.recording = session.data().recording();
    return k;
}

std::vector<Command> commandsForKey(const SDL_KeyboardEvent& key, const KeyState& state) {
    if (state.dialog.open()) return dialogKey(key, state.dialog);
    if (state.editing) return editKey(key);
    const bool ctrl = (key.keysym.mod & KMOD_CTRL) != 0;
    const bool shift = (key.keysym.mod & KMOD_SHIFT) != 0;
    const SDL_Keycode sym = key.keysym.sym;
    const bool repeatable = sym == SDLK_LEFT || sym == SDLK_RIGHT || sym == SDLK_UP ||
                            sym == SDLK_DOWN || sym == SDLK_n || sym == SDLK_LEFTBRACKET ||
                            sym == SDLK_RIGHTBRACKET || sym == SDLK_PAGEUP ||
                            sym == SDLK_PAGEDOWN || (ctrl && (sym == SDLK_z || sym == SDLK_y));
    if (key.repeat != 0 && !repeatable) return {};
    // The UI's scale: Ctrl with plus (on '=' of a US layout, or the keypad's), minus, 0. Before the
    // digits: Ctrl+0 is not preset 0.
    if (ctrl) {
        switch (sym) {
            case SDLK_EQUALS:
            case SDLK_PLUS:
            case SDLK_KP_PLUS:
                return {cmd::SetUiScale{steppedUiScale(state.view.uiScale, +1), false}};
            case SDLK_MINUS:
            case SDLK_KP_MINUS:
                return {cmd::SetUiScale{steppedUiScale(state.view.uiScale, -1), false}};
            case SDLK_0:
            case SDLK_KP_0:
                return {cmd::SetUiScale{state.view.uiScale, true}};
            case SDLK_t:
                return {
                    cmd::SetTheme{state.view.theme == Theme::Dark ? Theme::Light : Theme::Dark}};
            default:
                break;
        }
    }
    switch (sym) {
        case SDLK_ESCAPE:
            return {cmd::Back{}};
        case SDLK_BACKSPACE:
        case SDLK_DELETE:
            return {cmd::DeleteHeld{}};
        case SDLK_s:
            if (ctrl) return {shift ? Command{cmd::AskSaveAs{}} : Command{cmd::Save{}}};
            return {show(state, ShowOption::Labels)};
        case SDLK_a:
            return {show(state, ShowOption::Arrows)};
        case SDLK_c:
            return {cmd::ToggleControls{}};
        case SDLK_m:
            return {cmd::SpawnRandom{}};
        case SDLK_x:
            return {cmd::SetRecording{!state.recording}};
        case SDLK_b:
            return {cmd::SetTool{cmd::Tool::Peg, true}};
        case SDLK_w:
            return {cmd::SetTool{cmd::Tool::Wall, true}};
        case SDLK_h:
            return {cmd::ToggleHelp{}};
        case SDLK_v:
            return {show(state, ShowOption::Momentum)};
        case SDLK_l:
            return {cmd::SetTrails{static_cast<int>(nextTrailMode(state.view.trails))}};
        case SDLK_k:
            return {show(state, ShowOption::Plots)};
        case SDLK_d:
            return {show(state, ShowOption::Speeds)};
        case SDLK_j:
            return {show(state, ShowOption::Collision)};
        case SDLK_i:
            return {show(state, ShowOption::Values)};
        case SDLK_u:
            return {cmd::Stopwatch{shift ? cmd::Stopwatch::Action::LapOrReset
                                         : cmd::Stopwatch::Action::StartStop}};
        case SDLK_t:
            return {modeStep(state.solver)};
        case SDLK_o:
        case SDLK_F3:
            return {show(state, ShowOption::Profile)};
        case SDLK_f:
            return {cmd::Fit{}};
        case SDLK_SPACE:
            return {cmd::TogglePause{}};
        case SDLK_n:
            if (ctrl) return {cmd::AskNewScene{}};
            return {cmd::SingleStep{}};
        case SDLK_COMMA:
            return {cmd::SetTimeScale{state.timeScale * 0.5}};
        case SDLK_PERIOD:
            return {cmd::SetTimeScale{state.timeScale * 2.0}};
        case SDLK_r:
            if (ctrl) return {cmd::ToggleVideo{}};
            return {cmd::Restart{}};
        case SDLK_e:
            return {restitutionStep(state.restitution, shift ? +1 : -1)};
        case SDLK_g:
            if (shift) return {show(state, ShowOption::Grid)};
            return {gravityToggle(state.gravity, state.sceneGravity)};
        case SDLK_q:
            return {show(state, ShowOption::Ruler)};
        case SDLK_F12:
            return {cmd::Screenshot{}};
        case SDLK_RETURN:
        case SDLK_KP_ENTER:
            return {cmd::OpenEdit{}};
        case SDLK_p:
            return {cmd::OpenPreset{-1}};
        case SDLK_0:
        case SDLK_1:
        case SDLK_2:
        case SDLK_3:
        case SDLK_4:
        case SDLK_5:
        case SDLK_6:
        case SDLK_7:
        case SDLK_8:
        case SDLK_9:
            return {cmd::OpenPreset{cmd::presetForDigit(static_cast<int>(sym - SDLK_0), shift)}};
        case SDLK_LEFTBRACKET:
            return {cmd::ChangeSpawnMass{-1}};
        case SDLK_RIGHTBRACKET:
            return {cmd::ChangeSpawnMass{+1}};
        case SDLK_z:  // plain Z and Y do nothing
            if (ctrl) return {shift ? Command{cmd::Redo{}} : Command{cmd::Undo{}}};
            return {};
        case SDLK_y:
            if (ctrl) return {cmd::Redo{}};
            return {};
        case SDLK_LEFT:
            if (shift) return {cmd::StepBack{}};
            return {cmd::Pan{Vec2(kPanKeyPixels, 0.0)}};  // the view moves the way it points
        case SDLK_RIGHT:
            if (shift) return {cmd::StepForward{}};
            return {cmd::Pan{Vec2(-kPanKeyPixels, 0.0)}};
        case SDLK_PAGEUP:
            return {cmd::SeekBy{-kSeekKeySeconds}};
        case SDLK_PAGEDOWN:
            return {cmd::SeekBy{kSeekKeySeconds}};
        case SDLK_UP:
            return {cmd::Pan{Vec2(0.0, kPanKeyPixels)}};
        case SDLK_DOWN:
            return {cmd::Pan{Vec2(0.0, -kPanKeyPixels)}};
        default:
            return {};
    }
}

std::vector<Command> Input::translate(const SDL_Event& e, const KeyState& state, double pixelRatio,
                                      SDL_Point output) {
    const auto at = [pixelRatio](int x, int y) { return Vec2(x * pixelRatio, y * pixelRatio); };
    // The mouse SDL makes of a finger, while two fingers pan and zoom (touch.hpp).
    const bool fromTouch = (e.type == SDL_MOUSEBUTTONDOWN || e.type == SDL_MOUSEBUTTONUP)
                               ? e.button.which == SDL_TOUCH_MOUSEID
                               : e.type == SDL_MOUSEMOTION && e.motion.which == SDL_TOUCH_MOUSEID;
    if (fromTouch && touch_.pinching()) return {};
    switch (e.type) {
        case SDL_QUIT:
            return {cmd::Quit{}};
        case SDL_WINDOWEVENT:
            if (e.window.event == SDL_WINDOWEVENT_SIZE_CHANGED) {
                return {cmd::Resize{output.x, output.y}};
            }
            if (e.window.event == SDL_WINDOWEVENT_LEAVE) return {cmd::PointerLeave{}};
            return {};
        case SDL_KEYDOWN:
            return commandsForKey(e.key, state);
        case SDL_TEXTINPUT:
            if (state.editing) return {cmd::EditType{e.text.text}};
            return {};
        case SDL_MOUSEBUTTONDOWN:
            mouse_ = at(e.button.x, e.button.y);
            if (e.button.button == SDL_BUTTON_LEFT) {
                return {cmd::PointerDown{mouse_, ticksToSeconds(e.button.timestamp)}};
            }
            if (e.button.button == SDL_BUTTON_RIGHT || e.button.button == SDL_BUTTON_MIDDLE) {
                panning_ = true;
            }
            return {};
        case SDL_MOUSEMOTION: {
            const Vec2 m = at(e.motion.x, e.motion.y);
            std::vector<Command> out;
            if (panning_) out.emplace_back(cmd::Pan{m - mouse_});
            mouse_ = m;
            out.emplace_back(cmd::PointerMove{m, ticksToSeconds(e.motion.timestamp)});
            return out;
        }
        case SDL_MOUSEBUTTONUP:
            mouse_ = at(e.button.x, e.button.y);
            if (e.button.button == SDL_BUTTON_LEFT) {
                const cmd::PointerUp up{mouse_, ticksToSeconds(e.button.timestamp)};
                // A finger lifted is a pointer gone: nothing hovers where it was.
                if (e.button.which == SDL_TOUCH_MOUSEID) return {up, cmd::PointerLeave{}};
                return {up};
            }
            if (e.button.button == SDL_BUTTON_RIGHT || e.button.button == SDL_BUTTON_MIDDLE) {
                panning_ = false;
            }
            return {};
        case SDL_MOUSEWHEEL: {
            if (e.wheel.preciseY == 0.0f) return {};
            int x = 0, y = 0;
            SDL_GetMouseState(&x, &y);
            mouse_ = at(x, y);
            return {cmd::Zoom{mouse_, std::pow(kWheelZoomStep, e.wheel.preciseY)}};
        }
        case SDL_FINGERDOWN:
        case SDL_FINGERMOTION:
        case SDL_FINGERUP:
            if (!kTouchGestures) return {};
            return touch_.translate(e.tfinger, output, mouse_);
        case SDL_DROPFILE: {
            // A file dropped on the window, or picked with the page's Open (browser_files.hpp).
            std::vector<Command> out{cmd::OpenFile{std::filesystem::path(e.drop.file)}};
            SDL_free(e.drop.file);
            return out;
        }
        default:
            return {};
    }
}

}  // namespace psb::app
