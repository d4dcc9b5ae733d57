#include "gui/gui_context.hpp"

#include <algorithm>
#include <cfloat>
#include <stdexcept>
#include <string>
#include <system_error>
#include <utility>

#include <backends/imgui_impl_sdl.h>
#include <imgui.h>
#include <imgui_internal.h>

namespace psb::app {

namespace {

// Without a window (tests), the keys the SDL2 backend maps for ImGui, by SDL scancode as it
// maps them, so that key events fed to handleEvent move through the panel as in the window.
void mapKeys(ImGuiIO& io) {
    const std::pair<ImGuiKey, SDL_Scancode> keys[] = {
        {ImGuiKey_Tab, SDL_SCANCODE_TAB},
        {ImGuiKey_LeftArrow, SDL_SCANCODE_LEFT},
        {ImGuiKey_RightArrow, SDL_SCANCODE_RIGHT},
        {ImGuiKey_UpArrow, SDL_SCANCODE_UP},
        {ImGuiKey_DownArrow, SDL_SCANCODE_DOWN},
        {ImGuiKey_PageUp, SDL_SCANCODE_PAGEUP},
        {ImGuiKey_PageDown, SDL_SCANCODE_PAGEDOWN},
        {ImGuiKey_Home, SDL_SCANCODE_HOME},
        {ImGuiKey_End, SDL_SCANCODE_END},
        {ImGuiKey_Delete, SDL_SCANCODE_DELETE},
        {ImGuiKey_Backspace, SDL_SCANCODE_BACKSPACE},
        {ImGuiKey_Space, SDL_SCANCODE_SPACE},
        {ImGuiKey_Enter, SDL_SCANCODE_RETURN},
        {ImGuiKey_KeyPadEnter, SDL_SCANCODE_KP_ENTER},
        {ImGuiKey_Escape, SDL_SCANCODE_ESCAPE},
    };
    for (const auto& [key, scancode] : keys)
        io.KeyMap[key] = scancode;
}

bool isModifier(SDL_Keycode key) {
    return key == SDLK_LCTRL || key == SDLK_RCTRL || key == SDLK_LSHIFT || key == SDLK_RSHIFT ||
           key == SDLK_LALT || key == SDLK_RALT || key == SDLK_LGUI || key == SDLK_RGUI;
}

// A key press that does something in ImGui beyond the character it types: Tab, Enter, Esc,
// Backspace, Delete, the arrows, Home, End, and anything with Ctrl, Alt or the Super key.
bool acts(const SDL_Event& e) {
    if (e.type != SDL_KEYDOWN || isModifier(e.key.keysym.sym)) return false;
    if ((e.key.keysym.mod & (KMOD_CTRL | KMOD_ALT | KMOD_GUI)) != 0) return true;
    const SDL_Keycode key = e.key.keysym.sym;
    return key < SDLK_SPACE || key >= SDLK_DELETE;
}

// The app's Ctrl shortcuts (Ctrl+S, Ctrl+N, Ctrl+Z, Ctrl+plus...; platform/input.cpp), told
// from a field's own (Ctrl+A selects all, Ctrl+C, V, X the clipboard, Ctrl+Enter a new line,
// Ctrl+arrows, Ctrl+Backspace): Ctrl with a printable key or the keypad's plus, minus and 0.
bool appShortcut(const SDL_KeyboardEvent& key) {
    const Uint16 mod = key.keysym.mod;
    if ((mod & KMOD_CTRL) == 0 || (mod & (KMOD_ALT | KMOD_GUI)) != 0) return false;
    const SDL_Keycode k = key.keysym.sym;
    if (k == SDLK_a || k == SDLK_c || k == SDLK_v || k == SDLK_x) return false;
    return (k > SDLK_SPACE && k < SDLK_DELETE) || k == SDLK_KP_PLUS || k == SDLK_KP_MINUS ||
           k == SDLK_KP_0;
}

// Target pixels per window point: 2 on a high-DPI window, 1 elsewhere.
float windowPixelScale(SDL_Window* window, SDL_Renderer* renderer) {
    int w = 0, h = 0, pw = 0, ph = 0;
    SDL_GetWindowSize(window, &w, &h);
    if (w <= 0 || SDL_GetRendererOutputSize(renderer, &pw, &ph) != 0 || pw <= 0) return 1.f;
    return static_cast<float>(pw) / static_cast<float>(w);
}

}  // namespace

GuiContext::GuiContext(SDL_Renderer* renderer, const GuiOptions& options)
    : GuiContext(nullptr, renderer, options) {}

GuiContext::GuiContext(SDL_Window* window, SDL_Renderer* renderer, const GuiOptions& options)
    : window_(window), sdl_(renderer), options_(options) {
    if (sdl_ == nullptr) throw std::runtime_error("GuiContext: no SDL renderer");
    IMGUI_CHECKVERSION();
    ImGuiContext* previous = ImGui::GetCurrentContext();
    context_ = ImGui::CreateContext();
    makeCurrent();  // CreateContext makes the new context current only when there is none
    try {
        ImGuiIO& io = ImGui::GetIO();
        io.IniFilename = nullptr;
        io.LogFilename = nullptr;
        io.UserData = &tooltips_;  // widgets::tip
        setTheme(Theme::Dark);
        if (window_ != nullptr) {
            if (!ImGui_ImplSDL2_InitForSDLRenderer(window_)) {
                throw std::runtime_error("GuiContext: the SDL2 platform backend did not start");
            }
            platform_ = true;
        } else {
            mapKeys(io);
        }
        // The keyboard moves through the panel (the backend maps the keys it needs); which
        // keys reach it is decided in handleEvent, so ImGui's own capture flag (set whenever
        // its window has focus) is not used.
        io.ConfigFlags |=
            ImGuiConfigFlags_NavEnableKeyboard | ImGuiConfigFlags_NavNoCaptureKeyboard;
        const float scale = window_ != nullptr ? windowPixelScale(window_, sdl_) : 1.f;
        loadFont(scale);
        renderer_ = std::make_unique<ImGuiRenderer>(sdl_);
    } catch (...) {
        shutDown();
        ImGui::SetCurrentContext(previous);
        throw;
    }
}

GuiContext::~GuiContext() {
    shutDown();
}

void GuiContext::shutDown() {
    if (context_ == nullptr) return;
    makeCurrent();
    renderer_.reset();
    if (platform_) ImGui_ImplSDL2_Shutdown();
    platform_ = false;
    ImGui::DestroyContext(context_);
    context_ = nullptr;
}

void GuiContext::makeCurrent() const {
    ImGui::SetCurrentContext(context_);
}

void GuiContext::setScale(float scale) {
    makeCurrent();
    scale = std::clamp(scale, static_cast<float>(kMinUiScale), static_cast<float>(kMaxUiScale));
    if (inFrame_) {
        // ImGui locks the font atlas from NewFrame to Render and aborts on a change in between
        // (Debian's build keeps its assertions): a control of this very frame asked for it, so
        // the next beginFrame makes it.
        pendingScale_ = scale;
        return;
    }
    pendingScale_.reset();
    if (scale == scale_) return;
    scale_ = scale;
    if (loadFont(window_ != nullptr ? windowPixelScale(window_, sdl_) : 1.f)) {
        renderer_->rebuildFontTexture();
    }
}

void GuiContext::setTheme(Theme theme) {
    makeCurrent();
    if (inFrame_) {
        pendingTheme_ = theme;  // the style is read while the frame is built: the next one
        return;
    }
    pendingTheme_.reset();
    ImGuiStyle& style = ImGui::GetStyle();
    if (theme == Theme::Light) {
        ImGui::StyleColorsLight(&style);
        // Darker text, frames and headers than ImGui's light style: read from across a room.
        style.Colors[ImGuiCol_Text] = ImVec4(0.f, 0.f, 0.f, 1.f);
        style.Colors[ImGuiCol_TextDisabled] = ImVec4(0.33f, 0.33f, 0.33f, 1.f);
        style.Colors[ImGuiCol_FrameBg] = ImVec4(0.86f, 0.86f, 0.86f, 1.f);
        style.Colors[ImGuiCol_Border] = ImVec4(0.f, 0.f, 0.f, 0.45f);
        style.Colors[ImGuiCol_NavHighlight] = ImVec4(0.f, 0.45f, 0.70f, 1.f);  // Okabe–Ito blue
        style.FrameBorderSize = 1.f;
    } else {
        ImGui::StyleColorsDark(&style);
        style.FrameBorderSize = 0.f;
    }
    // Lines (a window's title-bar border, the dialogs') as geometry, not as ImGui's textured
    // lines, which want a bilinear-filtered atlas: through this renderer's nearest sampling the
    // line under a dialog's title stopped halfway across it.
    style.AntiAliasedLinesUseTex = false;
    // A slider's value is written over its handle: a faint handle keeps the digits under it
    // legible ("0.▮0" read as nothing on a projector), its frame's border still shows it.
    const ImVec4 text = style.Colors[ImGuiCol_Text];
    style.Colors[ImGuiCol_SliderGrab] = ImVec4(text.x, text.y, text.z, 0.22f);
    style.Colors[ImGuiCol_SliderGrabActive] = ImVec4(text.x, text.y, text.z, 0.32f);
    // Dialogs (quit, new scene, save) and tooltips are opaque: ImGui's 94 % and 98 % let the
    // box's balls and arrows show through the words on a projector.
    style.Colors[ImGuiCol_PopupBg].w = 1.f;
}

bool GuiContext::loadFont(float pixelScale) {
    const GuiOptions& options = options_;
    if (options.font.empty()) return false;
    pixelScale *= scale_;
    if (pixelScale == fontScale_) return false;
    if (!(options.fontPixels > 0.f)) {
        throw std::runtime_error("GuiContext: font size must be > 0 points");
    }
    // Rasterised at the target's pixel size and drawn at 1/scale, so text stays sharp on a
    // high-DPI window instead of being a magnified low-resolution atlas.
    // ImGui asserts (aborts) on a file it cannot read, so the check is made here.
    std::error_code ec;
    if (!std::filesystem::is_regular_file(options.font, ec)) {
        throw std::runtime_error("GuiContext: no font file " + options.font.string());
    }
    ImGuiIO& io = ImGui::GetIO();
    io.Fonts->Clear();
    ImFontConfig config;
    config.OversampleH = 1;
    config.PixelSnapH = true;
    // Latin-1 (ImGui's default) and Greek, for the physics' letters (omega, beta, mu, theta),
    // and the superscripts and subscripts, for powers of ten ("1 part in 10¹⁴").
    static const ImWchar kRanges[] = {0x0020, 0x00FF, 0x0370, 0x03FF, 0x2070, 0x209F, 0};
    if (io.Fonts->AddFontFromFileTTF(options.font.string().c_str(), options.fontPixels * pixelScale,
                                     &config, kRanges) == nullptr) {
        throw std::runtime_error("GuiContext: cannot load font " + options.font.string());
    }
    io.FontGlobalScale = 1.f / pixelScale;
    fontScale_ = pixelScale;
    return true;
}

bool GuiContext::handleEvent(const SDL_Event& event, bool tabToPanel) {
    makeCurrent();
    if (event.type == SDL_KEYDOWN || event.type == SDL_KEYUP) return handleKey(event, tabToPanel);
    if (event.type == SDL_TEXTINPUT) {
        // Into the keys' queue, not to the backend: in the order typed (see the header).
        forwardKey(event);
        return ImGui::GetIO().WantTextInput;
    }
    if (event.type == SDL_FINGERDOWN || event.type == SDL_FINGERMOTION ||
        event.type == SDL_FINGERUP) {
        return handleTouch(event.tfinger);
    }
    if (handleFinger(event)) return true;
    if (platform_) ImGui_ImplSDL2_ProcessEvent(&event);
    if (event.type == SDL_MOUSEMOTION) {
        mouse_ = ImVec2(static_cast<float>(event.motion.x), static_cast<float>(event.motion.y));
    } else if (event.type == SDL_MOUSEBUTTONDOWN || event.type == SDL_MOUSEBUTTONUP) {
        mouse_ = ImVec2(static_cast<float>(event.button.x), static_cast<float>(event.button.y));
    } else if (event.type == SDL_WINDOWEVENT && event.window.event == SDL_WINDOWEVENT_LEAVE) {
        mouse_.reset();
    }
    const ImGuiIO& io = ImGui::GetIO();
    // Whose a press is goes by where it comes down now, not by ImGui's capture flag, which
    // describes the last frame: a click on the box right after one on a field (or on a dialog
    // that has just closed, or with the pointer just arrived from the panel) was the panel's,
    // and the box never saw it. An open popup (a list dropped down) takes every click: one
    // outside closes it.
    const bool popupOpen = !ImGui::GetCurrentContext()->OpenPopupStack.empty();
    switch (event.type) {
        case SDL_MOUSEBUTTONDOWN: {
            const ImVec2 at(static_cast<float>(event.button.x), static_cast<float>(event.button.y));
            const bool taken = popupOpen || overWindow(at);
            if (taken) takenButtons_ |= SDL_BUTTON(event.button.button);
            return taken;
        }
        case SDL_MOUSEBUTTONUP: {
            // The release goes where its press went.
            const Uint32 bit = SDL_BUTTON(event.button.button);
            const bool taken = (takenButtons_ & bit) != 0;
            takenButtons_ &= ~bit;
            return taken;
        }
        case SDL_MOUSEWHEEL: {
#if SDL_VERSION_ATLEAST(2, 26, 0)
            const ImVec2 at(static_cast<float>(event.wheel.mouseX),
                            static_cast<float>(event.wheel.mouseY));
#else
            const ImVec2 at = mouse_.value_or(ImVec2(-FLT_MAX, -FLT_MAX));
#endif
            return popupOpen || overWindow(at);
        }
        case SDL_MOUSEMOTION:
            // A drag the world started goes on over a panel; ImGui's own drags are captured.
            return takenButtons_ != 0;
        case SDL_TEXTEDITING:
            return io.WantTextInput;
        default:
            return false;
    }
}

void GuiContext::releaseIfDue() {
    if (releaseAfter_ > 0 && ImGui::GetFrameCount() >= releaseAfter_) {
        releaseAfter_ = 0;
        releaseKeyboard();
    }
}

bool GuiContext::handleKey(const SDL_Event& event, bool tabToPanel) {
    releaseIfDue();  // a key right after the frame that saw an Esc is the sandbox's
    const SDL_Keycode key = event.key.keysym.sym;
    const bool modifier = isModifier(key);
    // Releases and modifiers always reach ImGui: no key stays down in it, and Ctrl+click on a
    // slider (type a value) sees Ctrl.
    if (event.type == SDL_KEYUP || modifier) {
        const bool had = hasKeyboard();
        forwardKey(event);
        return had && !modifier;
    }
    if (key == SDLK_F12) return false;
    // The app's Ctrl shortcuts are the app's while the panel has the keyboard (not in a dialog,
    // whose field is all there is): at once from the panel's cursor, after the field's text is
    // kept from a field.
    if (tabToPanel && appShortcut(event.key) && hasKeyboard()) {
        if (!ImGui::GetIO().WantTextInput) return false;
        commitThenApp(event);
        return true;
    }
    ImGuiContext& g = *ImGui::GetCurrentContext();
    const bool plainTab = key == SDLK_TAB && (event.key.keysym.mod & (KMOD_CTRL | KMOD_ALT)) == 0;
    if (!hasKeyboard()) {
        if (!plainTab || !tabToPanel) return false;
        // Tab: the keyboard to the panel, its navigation cursor shown, and the Tab itself to
        // ImGui, which moves to the panel's first field.
        if (ImGuiWindow* panel = ImGui::FindWindowByName("Controls")) ImGui::FocusWindow(panel);
        g.NavDisableHighlight = false;
        g.NavDisableMouseHover = true;
        tabEnters_ = true;
    } else if (key == SDLK_ESCAPE) {
        // Esc: the keyboard back to the sandbox. With nothing being typed at once (ImGui would
        // only move the cursor out of a child window); a field being typed in first sees the
        // Esc (it drops what was typed), and the keyboard goes back after that frame.
        if (!ImGui::GetIO().WantTextInput) {
            releaseKeyboard();
            return true;
        }
        releaseAfter_ = ImGui::GetFrameCount() + 1;
    }
    forwardKey(event);
    return true;
}

void GuiContext::forwardKey(const SDL_Event& event) {
    // ImGui 1.86 reads which keys are down at each frame: a key pressed and released between
    // two frames (a quick tap, xdotool's key) would never be seen, and three Tabs typed fast
    // would be one. The events trickle in: each frame takes them in order until a key that has
    // already changed in it, the rest wait for the next (as ImGui 1.87's input queue does).
    // Typed text goes the same way, so that "10", Tab, "4" typed within a frame is not "104".
    keyQueue_.push_back({event});
    if (!inFrame_) trickleKeys();  // within a frame ImGui's keys must not change (it checks)
}

void GuiContext::commitThenApp(const SDL_Event& event) {
    // Enter keeps what a field holds (an edit applied, a title kept: the panel's commands of
    // the frame that sees it); the shortcut acts on the scene with it, as in any editor.
    SDL_Event enter{};
    enter.type = SDL_KEYDOWN;
    enter.key.timestamp = event.key.timestamp;
    enter.key.keysym.scancode = SDL_SCANCODE_RETURN;
    enter.key.keysym.sym = SDLK_RETURN;
    enter.key.keysym.mod = KMOD_NONE;  // Ctrl+Enter would be a new line in the description
    keyQueue_.push_back({enter});
    keyQueue_.push_back({event, true});
    enter.type = SDL_KEYUP;
    keyQueue_.push_back({enter});
    if (!inFrame_) trickleKeys();
}

void GuiContext::trickleKeys() {
    ImGuiIO& io = ImGui::GetIO();
    while (!keyQueue_.empty()) {
        const Queued& q = keyQueue_.front();
        // An app's shortcut waits for the end of the frame that takes the Enter before it.
        // After a key that acts nothing else goes in: a field reads its frame's characters
        // before its keys, and a Tab moves to the next field only as the frame is built.
        if (q.forApp || keyActed_) return;
        if (q.event.type == SDL_TEXTINPUT) {
            // A field a Tab goes to is active from the frame after the Tab's, and takes no
            // characters in that first frame (ImGui 1.86): text waits for the one after.
            if (textWait_ > 0) return;
            io.AddInputCharactersUTF8(q.event.text.text);
        } else {
            const SDL_Scancode code = q.event.key.keysym.scancode;
            if (std::find(changedKeys_.begin(), changedKeys_.end(), code) != changedKeys_.end())
                return;
            changedKeys_.push_back(code);
            passKey(q.event);
            keyActed_ = acts(q.event);
            if (keyActed_) textWait_ = 2;
        }
        keyQueue_.pop_front();
    }
}

std::vector<SDL_Event> GuiContext::takeAppKeys() {
    return std::exchange(appKeys_, {});
}

void GuiContext::passKey(const SDL_Event& event) {
    // What the 1.86 SDL2 backend does with a key, but with the modifiers the event was sent
    // with, not SDL's state now (which a queued Tab would read after Shift's release).
    ImGuiIO& io = ImGui::GetIO();
    const int code = event.key.keysym.scancode;
    if (code >= 0 && code < IM_ARRAYSIZE(io.KeysDown))
        io.KeysDown[code] = event.type == SDL_KEYDOWN;
    const Uint16 mod = event.key.keysym.mod;
    io.KeyShift = (mod & KMOD_SHIFT) != 0;
    io.KeyCtrl = (mod & KMOD_CTRL) != 0;
    io.KeyAlt = (mod & KMOD_ALT) != 0;
    io.KeySuper = (mod & KMOD_GUI) != 0;
}

void GuiContext::keysAfterFrame() {
    // The frame has seen every change so far; the keys that wait come in before the next.
    changedKeys_.clear();
    keyActed_ = false;
    if (textWait_ > 0) --textWait_;
    tabOnward();
    enterActivates();
}

void GuiContext::enterActivates() {
    // ImGui 1.86 maps Space to "activate" and Enter to "input": Enter starts typing in a field
    // or a slider, and on a button, a check box or a section's header did nothing. Here either
    // Enter also activates the item under the cursor, as ImGui's programmatic activation does
    // (the item is pressed once, and let go the next frame); a field still starts typing. Not in
    // a dialog, where Enter is the default button's (section_dialogs.cpp).
    ImGuiContext& g = *ImGui::GetCurrentContext();
    const ImGuiIO& io = g.IO;
    const auto pressed = [&io](ImGuiKey key) {
        const int code = io.KeyMap[key];
        return code >= 0 && code < IM_ARRAYSIZE(io.KeysDown) && io.KeysDown[code] &&
               io.KeysDownDuration[code] == 0.f;
    };
    if (!pressed(ImGuiKey_Enter) && !pressed(ImGuiKey_KeyPadEnter)) return;
    if (g.NavId == 0 || g.NavDisableHighlight || g.NavWindow == nullptr || g.ActiveId != 0 ||
        g.NavActivateId != 0 || (g.NavWindow->Flags & ImGuiWindowFlags_NoNavInputs) != 0 ||
        (g.NavWindow->RootWindow->Flags & ImGuiWindowFlags_Modal) != 0)
        return;
    g.NavActivateId = g.NavActivateDownId = g.NavActivatePressedId = g.NavId;
    g.NavActivateInputId = g.NavId;
    g.NavActivateFlags = ImGuiActivateFlags_PreferInput;
}

void GuiContext::tabOnward() {
    // ImGui 1.86 tabs only through fields (sliders, text) and, from a button or a check box,
    // starts again at the window's first item: the panel marks every item a tab stop
    // (ControlPanel::build), and a Tab within the panel goes on from the item that has the
    // cursor, as later ImGui versions do. The first Tab from the sandbox starts at the top.
    ImGuiContext& g = *ImGui::GetCurrentContext();
    const bool tabbing = g.NavMoveSubmitted && (g.NavMoveFlags & ImGuiNavMoveFlags_Tabbing) != 0;
    if (tabbing && g.NavTabbingDir == 0 && g.NavId != 0 && !std::exchange(tabEnters_, false)) {
        g.NavTabbingDir = +1;
    }
    tabEnters_ = false;
}

bool GuiContext::handleFinger(const SDL_Event& e) {
    const bool motion = e.type == SDL_MOUSEMOTION;
    const bool button = e.type == SDL_MOUSEBUTTONDOWN || e.type == SDL_MOUSEBUTTONUP;
    if (!motion && !button) return false;
    const bool finger =
        motion ? e.motion.which == SDL_TOUCH_MOUSEID
               : e.button.which == SDL_TOUCH_MOUSEID && e.button.button == SDL_BUTTON_LEFT;
    if (motion || e.type == SDL_MOUSEBUTTONDOWN) {
        pointerIsFinger_ = finger;
        forgetMouse_ = 0;
    }
    if (!finger) return false;
    const ImVec2 at = motion
                          ? ImVec2(static_cast<float>(e.motion.x), static_cast<float>(e.motion.y))
                          : ImVec2(static_cast<float>(e.button.x), static_cast<float>(e.button.y));
    const double seconds = (motion ? e.motion.timestamp : e.button.timestamp) / 1000.0;
    if (e.type == SDL_MOUSEBUTTONDOWN) {
        if (!overWindow(at)) return false;
        panelTouch_.down(at, seconds);
        mouse_.reset();  // where a finger was before means nothing once it is lifted
        return true;
    }
    if (!panelTouch_.fingerDown()) {
        // A finger lifted off the world: ImGui sees the release where it was, then no pointer.
        if (!motion) forgetMouse_ = 2;
        return false;
    }
    if (motion) {
        panelTouch_.move(at, seconds);
    } else {
        panelTouch_.up(at, seconds);
    }
    return true;
}

bool GuiContext::handleTouch(const SDL_TouchFingerEvent& f) {
    if (f.type == SDL_FINGERMOTION) return panelFingers_.count(f.fingerId) > 0;
    if (f.type == SDL_FINGERUP) return panelFingers_.erase(f.fingerId) > 0;
    // SDL sends the first finger's mouse press before its finger event: a finger that pressed
    // the panel is down in the gesture already.
    int w = 0, h = 0;
    if (window_ != nullptr) SDL_GetWindowSize(window_, &w, &h);
    const ImVec2 at(f.x * static_cast<float>(w), f.y * static_cast<float>(h));
    if (panelFingers_.empty() && !panelTouch_.fingerDown() && !overWindow(at)) return false;
    // Two fingers on the panel mean nothing: the first one's gesture ends without a press.
    if (!panelFingers_.empty()) panelTouch_.cancel();
    panelFingers_.insert(f.fingerId);
    return true;
}

void GuiContext::fingerFrame() {
    ImGuiIO& io = ImGui::GetIO();
    if (forgetMouse_ > 0 && --forgetMouse_ == 0) {
        mouse_.reset();
        if (!ImGui::IsAnyMouseDown()) io.MousePos = ImVec2(-FLT_MAX, -FLT_MAX);
    }
    const double now = static_cast<double>(SDL_GetTicks64()) / 1000.0;
    panelTouch_.sliderUnder(tooltips_.sliderHovered);  // the last frame's, under the finger
    if (const std::optional<PanelTouch::Pointer> p = panelTouch_.frame(now)) {
        io.MousePos = p->at.value_or(ImVec2(-FLT_MAX, -FLT_MAX));
        io.MouseDown[0] = p->down;
        if (p->scroll != 0.f) scrollWindowAt(p->scrollFrom, p->scroll, scale_);
    }
    tooltips_.startFrame(now, !pointerIsFinger_, io.MousePos.x, io.MousePos.y);
}

std::optional<GuiContext::Typing> GuiContext::typing() const {
    makeCurrent();
    const ImGuiContext& g = *ImGui::GetCurrentContext();
    if (!g.IO.WantTextInput || g.ActiveId == 0) return std::nullopt;
    Typing t;
    t.id = g.ActiveId;
    // ImGui puts the input method's spot at the text cursor each frame the field draws one
    // (its top-left, (1, 1) when none was drawn).
    const ImVec2 p = g.PlatformImePos;
    if (p.x > 1.f || p.y > 1.f) t.caret = {p.x * scale_, p.y * scale_, scale_, g.FontSize * scale_};
    return t;
}

bool GuiContext::hasKeyboard() const {
    makeCurrent();
    const ImGuiContext& g = *ImGui::GetCurrentContext();
    if (g.IO.WantTextInput || g.ActiveId != 0) return true;
    return g.NavWindow != nullptr && g.NavWindow->Active && !g.NavDisableHighlight;
}

void GuiContext::releaseKeyboard() {
    ImGuiContext& g = *ImGui::GetCurrentContext();
    ImGui::ClearActiveID();
    ImGui::FocusWindow(nullptr);
    g.NavDisableHighlight = true;
    // The last frame's flags would still say a field wants the keys until the next frame.
    g.IO.WantTextInput = false;
    g.IO.WantCaptureKeyboard = false;
    g.WantTextInputNextFrame = 0;
}

bool GuiContext::overWindow(ImVec2 p) const {
    makeCurrent();
    const ImGuiContext& g = *ImGui::GetCurrentContext();
    p = ImVec2(p.x / scale_, p.y / scale_);  // ImGui's points
    for (const ImGuiWindow* w : g.Windows) {
        if (!w->Active || w->Hidden || (w->Flags & ImGuiWindowFlags_NoMouseInputs) != 0) continue;
        if (w->OuterRectClipped.Contains(p)) return true;
    }
    return false;
}

void GuiContext::applyPending() {
    if (inFrame_) throw std::logic_error("GuiContext: a frame began before the last one ended");
    if (const std::optional<Theme> theme = std::exchange(pendingTheme_, std::nullopt)) {
        setTheme(*theme);
    }
    if (const std::optional<float> scale = std::exchange(pendingScale_, std::nullopt)) {
        try {
            setScale(*scale);
        } catch (const std::runtime_error& e) {  // the font file gone since the start
            problem_ = e.what();
        }
    }
}

std::optional<std::string> GuiContext::takeProblem() {
    return std::exchange(problem_, std::nullopt);
}

void GuiContext::beginFrame() {
    makeCurrent();
    releaseIfDue();
    if (!platform_) throw std::logic_error("GuiContext::beginFrame(): no window; give a size");
    applyPending();
    ImGui_ImplSDL2_NewFrame();
    // The 1.86 backend polls SDL's global mouse state, which on X11 can lag the events (under
    // Xvfb with XTest input it still held the start position when the click came); the last
    // event's position is the one the app itself acts on.
    if (mouse_ && (SDL_GetMouseFocus() == window_ || ImGui::IsAnyMouseDown())) {
        ImGui::GetIO().MousePos = *mouse_;
    } else if (!mouse_ && !ImGui::IsAnyMouseDown()) {
        // No pointer seen in the window since it opened or the pointer left: none, not the
        // global position the backend polled (a launch preview drawn where no pointer is).
        ImGui::GetIO().MousePos = ImVec2(-FLT_MAX, -FLT_MAX);
    }
    fingerFrame();
    // Debian's 1.86 backend takes the scale from SDL_GL_GetDrawableSize, which is the window
    // size for a window without OpenGL; the renderer's output size is the one drawn into.
    const float scale = windowPixelScale(window_, sdl_);
    ImGuiIO& io = ImGui::GetIO();
    // A new pixel ratio (the window moved to another screen): the atlas again, crisp.
    try {
        if (loadFont(scale)) renderer_->rebuildFontTexture();
    } catch (const std::runtime_error& e) {  // the old atlas stays; not tried again each frame
        problem_ = e.what();
        fontScale_ = scale * scale_;
    }
    // ImGui's point is scale_ window points (see the top of gui_context.hpp).
    io.DisplayFramebufferScale = ImVec2(scale * scale_, scale * scale_);
    io.DisplaySize = ImVec2(io.DisplaySize.x / scale_, io.DisplaySize.y / scale_);
    if (io.MousePos.x > -FLT_MAX / 2)
        io.MousePos = ImVec2(io.MousePos.x / scale_, io.MousePos.y / scale_);
    trickleKeys();
    ImGui::NewFrame();
    keysAfterFrame();
    inFrame_ = true;
}

void GuiContext::beginFrame(float width, float height, float dt, float pixelScale) {
    makeCurrent();
    applyPending();
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(width / scale_, height / scale_);
    io.DisplayFramebufferScale = ImVec2(pixelScale * scale_, pixelScale * scale_);
    io.DeltaTime = dt > 0.f ? dt : 1.f / 60.f;
    trickleKeys();
    ImGui::NewFrame();
    keysAfterFrame();
    inFrame_ = true;
}

void GuiContext::selectNumberOnTap() {
    ImGuiContext& g = *ImGui::GetCurrentContext();
    if (!pointerIsFinger_ || !g.IO.MouseClicked[0] || g.ActiveId == 0) return;
    ImGuiInputTextState& field = g.InputTextState;
    // (ImGui keeps the field's flags only while it is drawn: what it holds says it is a number's.)
    if (field.ID != g.ActiveId || field.CurLenW == 0 || !field.Stb.single_line) return;
    for (int k = 0; k < field.CurLenW; ++k) {
        const ImWchar c = field.TextW[k];
        if (!((c >= '0' && c <= '9') || c == '.' || c == '-' || c == '+' || c == 'e' || c == 'E'))
            return;
    }
    field.SelectAll();
    // Until the finger's release: no drag selects from the cursor.
    field.SelectedAllMouseLock = true;
}

int GuiContext::endFrame() {
    makeCurrent();
    selectNumberOnTap();
    ImGui::Render();
    inFrame_ = false;
    // The frame that took a shortcut's Enter is built: its field's text is kept, the app acts.
    while (!keyQueue_.empty() && keyQueue_.front().forApp) {
        appKeys_.push_back(keyQueue_.front().event);
        keyQueue_.pop_front();
    }
    return renderer_->render(*ImGui::GetDrawData());
}

ImGuiIO& GuiContext::io() {
    makeCurrent();
    return ImGui::GetIO();
}

bool GuiContext::wantsMouse() {
    return io().WantCaptureMouse;
}

bool GuiContext::wantsKeyboard() {
    return io().WantCaptureKeyboard;
}

}  // namespace psb::app
