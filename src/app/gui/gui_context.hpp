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
// No imgui.ini or log file is written: the app's layout is its own, not the working
// directory's. ImGui keeps one "current" context per process; every member makes this one
// current first, so two holders (tests) do not mix.

#include <filesystem>
#include <memory>
#include <optional>

#include <SDL.h>

#include <imgui.h>

#include "gui/imgui_renderer.hpp"

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
    /// The release of a press the controls took is theirs too.
    bool handleEvent(const SDL_Event& event);
    /// Whether window point `p` is over a window (panel, list, open popup) the last frame
    /// drew; tooltips, which take no input, do not count.
    [[nodiscard]] bool overWindow(ImVec2 p) const;

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

  private:
    void makeCurrent() const;
    void shutDown();
    void loadFont(const GuiOptions& options, float pixelScale);

    SDL_Window* window_ = nullptr;
    SDL_Renderer* sdl_ = nullptr;
    ImGuiContext* context_ = nullptr;
    bool platform_ = false;        // the SDL2 platform backend is initialised
    std::optional<ImVec2> mouse_;  // window points, from the last mouse event
    Uint32 takenButtons_ = 0;      // SDL_BUTTON masks of the presses the controls took
    std::unique_ptr<ImGuiRenderer> renderer_;
};

}  // namespace psb::app
