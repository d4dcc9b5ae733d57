#pragma once
// The app's SDL resources in one RAII holder: SDL's video subsystem, the window, its renderer
// and the two fonts. Constructed in that order and destroyed in the reverse, whatever throws
// half-way.
//
// The renderer: the one asked for (--renderer), else SDL's choice, except that an OpenGL
// renderer on a software rasteriser (llvmpipe, softpipe, swrast: a virtual display or a machine
// without a GPU driver) is replaced by SDL's software renderer, which draws the same frames
// 2-4 times faster there. rendererNote() says which renderer is used and why.

#include <filesystem>
#include <memory>
#include <string>

#include <SDL.h>

#include "render/text.hpp"

namespace psb::app {

struct SdlContextOptions {
    int width = 800;  ///< window, screen points
    int height = 800;
    bool vsync = true;
    std::string renderDriver;  ///< SDL render driver name; empty: choose (see above)
    std::filesystem::path font;
};

/// Empty when SDL's video driver `driver` shows a window; otherwise why there is none: SDL
/// falls back to its windowless drivers ("offscreen", "dummy") when no display lets it in
/// (an X server refusing the connection, "Authorization required"), and the program would run
/// with nothing on screen. A windowless driver asked for by name (`requested`, the
/// SDL_VIDEODRIVER variable, as the tests do) is fine. `display` and `wayland` are the
/// DISPLAY and WAYLAND_DISPLAY variables (null when unset), named in the reason.
[[nodiscard]] std::string noWindowReason(const std::string& driver, const char* requested,
                                         const char* display, const char* wayland);

/// Whether an OpenGL GL_RENDERER string names a software rasteriser.
[[nodiscard]] bool isSoftwareRasteriser(const std::string& glRenderer);

class SdlContext {
  public:
    /// Throws std::runtime_error with SDL's reason when any part cannot be made.
    explicit SdlContext(const SdlContextOptions& options);
    ~SdlContext();
    SdlContext(const SdlContext&) = delete;
    SdlContext& operator=(const SdlContext&) = delete;

    [[nodiscard]] SDL_Window* window() const { return window_; }
    [[nodiscard]] SDL_Renderer* renderer() const { return renderer_; }
    [[nodiscard]] const Font& hudFont() const { return *hudFont_; }
    [[nodiscard]] const Font& labelFont() const { return *labelFont_; }
    /// The render driver in use ("software", "opengl", ...).
    [[nodiscard]] const std::string& rendererName() const { return rendererName_; }
    /// "Renderer: software (...why...)", for the log.
    [[nodiscard]] const std::string& rendererNote() const { return rendererNote_; }
    /// The drawable size, pixels (larger than the window's size in points on a high-DPI screen).
    [[nodiscard]] SDL_Point outputSize() const;
    /// Drawable pixels per window point (mouse events come in points).
    [[nodiscard]] double pixelRatio() const;
    /// The window's size in points (its height sets the automatic UI scale).
    [[nodiscard]] SDL_Point windowSize() const;
    /// Makes the HUD's and the labels' fonts again for `pointPixels` pixels per point of the UI
    /// (the pixel ratio × the UI's scale): 14 and 12 points at 1. The fonts keep their places
    /// (whoever holds them by reference draws the new size). Throws std::runtime_error naming
    /// the file when it cannot be opened.
    void setTextScale(double pointPixels);
    void setTitle(const std::string& title);
    void present();

  private:
    void createWindow(const SdlContextOptions& options);
    void destroyWindow();

    bool videoStarted_ = false;
    SDL_Window* window_ = nullptr;
    SDL_Renderer* renderer_ = nullptr;
    std::unique_ptr<Font> hudFont_;
    std::unique_ptr<Font> labelFont_;
    std::filesystem::path fontFile_;
    double textScale_ = 1.0;
    std::string rendererName_;
    std::string rendererNote_;
    std::string title_;
};

}  // namespace psb::app
