#pragma once
// One Dear ImGui context with its two backends, owned for its lifetime: Debian's SDL2 platform
// backend (mouse, keys, text, window size, clipboard, cursors) and the SDL_Renderer adapter of
// imgui_renderer.hpp. A frame is
//
//   for each SDL event: handleEvent(e)   true ─► the controls took it; the app ignores it
//   beginFrame()                         ImGui::Begin/Button/... calls go between the two
//   endFrame()                           draws onto the renderer (before SDL_RenderPresent)
//
// as Box2D's samples app does with its GLFW backend: input goes to ImGui first, and the app
// acts only on what ImGui does not want (io.WantCaptureMouse / WantCaptureKeyboard, which
// describe the frame before). Without a window (tests, offscreen images) there is no platform
// backend: the caller feeds io() and gives the display size to beginFrame.
//
// The UI's scale (session/view_options.hpp) makes ImGui's unit, its "point", `scale` window
// points: ImGui is told a display 1/scale the window's size, the pointer's position over scale,
// and a framebuffer scale of the pixel ratio × scale, so that every size the panel asks for (its
// width, a button's, the style's padding) grows with it; the font atlas is rasterised again at
// the pixels a glyph takes on screen (crisp text, not a magnified atlas).
//
// Keyboard navigation (ImGui's NavEnableKeyboard) shares the keys with the sandbox by one rule
// (docs/app.md, "Classroom"): a key goes to the panel only while the panel has the keyboard —
// a field being typed in or a widget held (ImGui's active item), or the navigation cursor shown
// in it (Tab gives it; Esc or a click outside the panel takes it away). Otherwise ImGui never
// sees the key, so an arrow key pans the view rather than moving through the panel. The app's
// Ctrl shortcuts (Ctrl+S, Ctrl+N, Ctrl+Z...) stay the app's while the panel has the keyboard:
// typed in a field, the field's text is kept first (as Enter would keep it), then the app acts
// (takeAppKeys); the field's own (Ctrl+A, C, V, X, Ctrl+Enter, Ctrl+arrows) stay the field's.
//
// Keys and typed text (SDL_TEXTINPUT) reach ImGui through one queue, in the order they were
// typed, and only between frames: ImGui 1.86 reads which keys are down at each frame and a
// field reads a frame's characters before its keys, so a key that acts (Tab, Enter, Backspace,
// an arrow, a Ctrl shortcut) closes the frame's share of the queue: what follows it waits for
// the next frame, and text for the one after (a "4" typed after a Tab goes to the field the
// Tab went to, which ImGui activates in the next frame and fills from the one after that, not
// to the one it left).
//
// No imgui.ini or log file is written: the app's layout is its own, not the working
// directory's. ImGui keeps one "current" context per process; every member makes this one
// current first, so two holders (tests) do not mix.

#include <deque>
#include <filesystem>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <SDL.h>

#include <imgui.h>

#include "gui/imgui_renderer.hpp"
#include "gui/panel_touch.hpp"
#include "gui/tooltips.hpp"
#include "session/view_options.hpp"

namespace psb::app {

struct GuiOptions {
    std::filesystem::path font;  ///< a TTF file; empty for ImGui's built-in bitmap font
    float fontPixels = 16.f;     ///< font size in window points (rasterised at the pixel scale)
};

class GuiContext {
  public:
    /// Controls in `window`, drawn with `renderer` (the window's). Throws std::runtime_error
    /// when a backend cannot start or the font cannot be loaded.
    GuiContext(SDL_Window* window, SDL_Renderer* renderer, const GuiOptions& options = {});
    /// Without a window: drawn with `renderer` (e.g. a software renderer on a surface).
    explicit GuiContext(SDL_Renderer* renderer, const GuiOptions& options = {});
    ~GuiContext();
    GuiContext(const GuiContext&) = delete;
    GuiContext& operator=(const GuiContext&) = delete;

    /// Passes an SDL event to ImGui; true when the controls take it (a click or wheel over a
    /// panel, typing into a field), so the app should not act on it as well. A press or a wheel
    /// turn is the controls' by where it happens (over any window the last frame drew, or
    /// anywhere while a popup is open), never by ImGui's capture flag: that flag is from the
    /// last frame, so a pointer that has just entered a panel is not in it yet, and one that
    /// has just left it (a click on a ball right after a field, or after a dialog closed) still
    /// is. The release of a press, and the moves between, go where the press went. A key is theirs
    /// while the panel has the keyboard (hasKeyboard); Tab gives it the keyboard when `tabToPanel`
    /// (not while the sandbox's edit prompt wants Tab), and Esc takes it back (and is the panel's).
    /// F12 is the sandbox's always (a screenshot of the panel with its cursor).
    bool handleEvent(const SDL_Event& event, bool tabToPanel = true);
    /// Whether window point `p` is over a window (panel, list, open popup) the last frame
    /// drew; tooltips, which take no input, do not count.
    [[nodiscard]] bool overWindow(ImVec2 p) const;
    /// Whether the panel has the keyboard (see the top of this file): keys go to it.
    [[nodiscard]] bool hasKeyboard() const;

    /// The UI's scale, kMinUiScale to kMaxUiScale (see the top of this file); the font atlas
    /// is rasterised again when it changes. Throws std::runtime_error when the font cannot be
    /// loaded. Called between beginFrame and endFrame (a control of the frame asked for it), it
    /// takes effect at the next beginFrame: ImGui aborts on a change to its font atlas within a
    /// frame.
    void setScale(float scale);
    /// The scale the frames are drawn at (a scale asked for within a frame: from the next).
    [[nodiscard]] float scale() const { return scale_; }
    /// ImGui's colours for `theme` (view/palette.hpp); within a frame, from the next one.
    void setTheme(Theme theme);
    /// What went wrong making a change asked for within a frame, or the atlas for a new pixel
    /// ratio (the font file gone since the start: the old atlas stays), once; nullopt if nothing.
    [[nodiscard]] std::optional<std::string> takeProblem();

    /// Starts a frame in the window: size and input from the platform backend, pixel scale
    /// from the renderer's output size over the window's size.
    void beginFrame();
    /// Starts a frame without a window: `width` × `height` points, `dt` seconds since the last
    /// frame, `pixelScale` target pixels per point.
    void beginFrame(float width, float height, float dt = 1.f / 60.f, float pixelScale = 1.f);
    /// Ends the frame and draws it. Returns the number of failed SDL draw calls (0 normally).
    int endFrame();
    /// The app's shortcuts pressed while a field was being typed in whose field has now kept
    /// its text (the frame that saw the Enter standing for them is done): the app acts on them
    /// now, in order (see the top of this file). Empty most of the time.
    [[nodiscard]] std::vector<SDL_Event> takeAppKeys();

    /// The context's IO (input state, capture flags); valid while this object lives.
    [[nodiscard]] ImGuiIO& io();
    [[nodiscard]] bool wantsMouse();
    [[nodiscard]] bool wantsKeyboard();
    [[nodiscard]] ImGuiRenderer& renderer() { return *renderer_; }
    /// The tooltip the last frame showed (empty: none), for --log-controls.
    [[nodiscard]] const std::string& shownTooltip() const { return tooltips_.shown; }
    /// The message band, in the panel's points: tooltips keep off it (tooltips.hpp).
    void setTooltipAvoid(const TipRect& band) { tooltips_.avoid = band; }
    /// A finger on a panel whose tap, press or scroll is not done (panel_touch.hpp): the panel
    /// holds its layout still under it (ControlPanel::holdLayout).
    [[nodiscard]] bool fingerOnPanel() const { return panelTouch_.held(); }
    /// The field being typed in as the last frame drew it, window points: ImGui's id of it and
    /// its text cursor (a line high); nullopt when no field takes text.
    struct Typing {
        unsigned id = 0;
        TipRect caret;
    };
    [[nodiscard]] std::optional<Typing> typing() const;

  private:
    void makeCurrent() const;
    void shutDown();
    /// Rasterises the font for `pixelScale` pixels per window point (× the UI's scale); false
    /// when the atlas is already that.
    bool loadFont(float pixelScale);
    /// Drops the keyboard: no focused window, no navigation cursor (Esc).
    void releaseKeyboard();
    /// The keyboard back to the sandbox once the frame that saw an Esc (in a field) is done.
    void releaseIfDue();
    /// handleEvent for a key press or release.
    bool handleKey(const SDL_Event& event, bool tabToPanel);
    /// A key or text event to ImGui through the queue (see the top of this file).
    void forwardKey(const SDL_Event& event);
    /// An app's Ctrl shortcut pressed in a field: an Enter into the queue to keep the field's
    /// text, and the shortcut to go to the app once the frame that takes the Enter is done.
    void commitThenApp(const SDL_Event& event);
    /// Passes the queued events the next frame can still take (between frames only): in order,
    /// until a key that has already changed in it, or anything after a key that acts.
    void trickleKeys();
    /// A key event into ImGui's io (by scancode, as the SDL2 backend maps the keys).
    void passKey(const SDL_Event& event);
    /// After NewFrame: a new frame to take key changes, and Tab's way on.
    void keysAfterFrame();
    /// After NewFrame: a Tab within the panel goes to the item after the cursor's.
    void tabOnward();
    /// Enter or the keypad's Enter on the control under the keyboard's cursor presses it, as
    /// Space does (ImGui 1.86 lets Enter only start typing in a field).
    void enterActivates();
    /// Makes the scale and theme asked for within the last frame (before NewFrame).
    void applyPending();
    /// handleEvent for the mouse SDL makes of a finger (panel_touch.hpp): true when the panel's
    /// touch gesture takes it.
    bool handleFinger(const SDL_Event& event);
    /// handleEvent for a finger's own events: true for the fingers that came down on a panel
    /// (or while one is on it), which never pan or pinch the box behind it (platform/touch.hpp);
    /// a second finger there ends the first one's gesture (PanelTouch::cancel).
    bool handleTouch(const SDL_TouchFingerEvent& f);
    /// The finger's part of a new frame: the gesture's pointer, the pointer of a finger lifted
    /// off the world forgotten, whether tooltips may show.
    void fingerFrame();
    /// After a frame: a finger's tap into a field holding a number, already being typed in, put
    /// the text cursor where it landed and cleared the selection shown; the number is selected
    /// whole again, so that what a finger types replaces it, as after the field's first tap
    /// (ImGui's AutoSelectAll: the New scene dialog's width read 7 selected, and 10 made 710).
    /// A field of words keeps the cursor where the finger put it.
    void selectNumberOnTap();

    SDL_Window* window_ = nullptr;
    SDL_Renderer* sdl_ = nullptr;
    ImGuiContext* context_ = nullptr;
    bool platform_ = false;        // the SDL2 platform backend is initialised
    std::optional<ImVec2> mouse_;  // window points, from the last mouse event
    Uint32 takenButtons_ = 0;      // SDL_BUTTON masks of the presses the controls took
    std::unique_ptr<ImGuiRenderer> renderer_;
    GuiOptions options_;
    float scale_ = 1.f;      // the UI's scale
    float fontScale_ = 0.f;  // pixels per ImGui point the atlas was rasterised for
    int releaseAfter_ = 0;   // the frame after which Esc gives the keyboard back (0: none)
    bool inFrame_ = false;   // between NewFrame and Render: the font atlas is locked
    std::optional<float> pendingScale_;  // asked for within the frame, made at the next
    std::optional<Theme> pendingTheme_;
    std::optional<std::string> problem_;
    PanelTouch panelTouch_;
    std::set<SDL_FingerID> panelFingers_;  // fingers down that came down on a panel
    TooltipState tooltips_;
    bool pointerIsFinger_ = false;  // the last pointer event came from a finger
    int forgetMouse_ = 0;           // frames until a lifted finger's pointer is forgotten
    bool tabEnters_ = false;        // this frame's Tab gave the panel the keyboard
    struct Queued {
        SDL_Event event;
        bool forApp = false;  // an app's shortcut, after the field's Enter queued before it
    };
    std::deque<Queued> keyQueue_;            // key and text events the frames have not taken
    std::vector<SDL_Scancode> changedKeys_;  // keys changed since the last NewFrame
    bool keyActed_ = false;                  // a key that acts was passed since the last NewFrame
    int textWait_ = 0;                       // NewFrames before text may follow such a key
    std::vector<SDL_Event> appKeys_;         // shortcuts for the app, their field's text kept
};

}  // namespace psb::app
