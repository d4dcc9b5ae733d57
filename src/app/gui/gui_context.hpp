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
// sees the key, so an arrow key pans the view rather than moving through the panel.
//
// No imgui.ini or log file is written: the app's layout is its own, not the working
// directory's. ImGui keeps one "current" context per process; every member makes this one
// current first, so two holders (tests) do not mix.

#include <deque>
#include <filesystem>
#include <memory>
#include <optional>
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
    /// turn is the controls' by where it happens (over any window the last frame drew), not by
    /// ImGui's capture flag alone: that flag is from the last frame, and a pointer that has
    /// just entered a panel (a first click, a wheel turn as the hand arrives) is not in it yet.
    /// The release of a press the controls took is theirs too. A key is theirs while the panel
    /// has the keyboard (hasKeyboard); Tab gives it the keyboard when `tabToPanel` (not while
    /// the sandbox's edit prompt wants Tab), and Esc takes it back (and is the panel's). F12 is
    /// the sandbox's always (a screenshot of the panel with its cursor).
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

    /// The context's IO (input state, capture flags); valid while this object lives.
    [[nodiscard]] ImGuiIO& io();
    [[nodiscard]] bool wantsMouse();
    [[nodiscard]] bool wantsKeyboard();
    [[nodiscard]] ImGuiRenderer& renderer() { return *renderer_; }
    /// The tooltip the last frame showed (empty: none), for --log-controls.
    [[nodiscard]] const std::string& shownTooltip() const { return tooltips_.shown; }

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
    /// A key event to ImGui by passKey, in order, at most one change of a key per frame.
    void forwardKey(const SDL_Event& event);
    /// Passes the queued key events the next frame can still take (between frames only).
    void trickleKeys();
    /// A key event into ImGui's io (by scancode, as the SDL2 backend maps the keys).
    void passKey(const SDL_Event& event);
    /// After NewFrame: a new frame to take key changes, and Tab's way on.
    void keysAfterFrame();
    /// After NewFrame: a Tab within the panel goes to the item after the cursor's.
    void tabOnward();
    /// Makes the scale and theme asked for within the last frame (before NewFrame).
    void applyPending();
    /// handleEvent for the mouse SDL makes of a finger (panel_touch.hpp): true when the panel's
    /// touch gesture takes it.
    bool handleFinger(const SDL_Event& event);
    /// The finger's part of a new frame: the gesture's pointer, the pointer of a finger lifted
    /// off the world forgotten, whether tooltips may show.
    void fingerFrame();

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
    TooltipState tooltips_;
    bool pointerIsFinger_ = false;           // the last pointer event came from a finger
    int forgetMouse_ = 0;                    // frames until a lifted finger's pointer is forgotten
    bool tabEnters_ = false;                 // this frame's Tab gave the panel the keyboard
    std::deque<SDL_Event> keyQueue_;         // key events the frames have not taken yet
    std::vector<SDL_Scancode> changedKeys_;  // keys changed since the last NewFrame
};

}  // namespace psb::app
