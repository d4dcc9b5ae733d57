#include "platform/sdl_context.hpp"

#include <cmath>
#include <cstdlib>
#include <stdexcept>

namespace psb::app {

namespace {

/// The HUD's and the labels' text at a UI scale of 1, pixels per em.
constexpr int kHudPoints = 14;
constexpr int kLabelPoints = 12;

std::string driverName(SDL_Renderer* renderer) {
    SDL_RendererInfo info{};
    if (SDL_GetRendererInfo(renderer, &info) != 0 || info.name == nullptr) return "?";
    return info.name;
}

/// GL_RENDERER of the current OpenGL context (the renderer's, right after it was made).
std::string glRendererString() {
    using GetString = const unsigned char* (*)(unsigned int);
    constexpr unsigned int kGlRenderer = 0x1F01;
    const auto get = reinterpret_cast<GetString>(SDL_GL_GetProcAddress("glGetString"));
    if (get == nullptr) return {};
    const unsigned char* s = get(kGlRenderer);
    return s != nullptr ? std::string(reinterpret_cast<const char*>(s)) : std::string();
}

}  // namespace

bool isSoftwareRasteriser(const std::string& glRenderer) {
    for (const char* name : {"llvmpipe", "softpipe", "swrast", "Software Rasterizer"}) {
        if (glRenderer.find(name) != std::string::npos) return true;
    }
    return false;
}

std::string noWindowReason(const std::string& driver, const char* requested, const char* display,
                           const char* wayland) {
    if (driver != "offscreen" && driver != "dummy") return {};
    if (requested != nullptr && std::string(requested).find(driver) != std::string::npos) return {};
    const auto named = [](const char* name, const char* value) {
        std::string out(name);
        if (value != nullptr && *value != '\0') {
            out += '=';
            out += value;
        } else {
            out += " unset";
        }
        return out;
    };
    return "cannot open a window: no display would let the program in (" +
           named("DISPLAY", display) + ", " + named("WAYLAND_DISPLAY", wayland) +
           "; an X server that says \"Authorization required\" needs XAUTHORITY), and SDL fell "
           "back to its windowless '" +
           driver + "' video driver. Set SDL_VIDEODRIVER=" + driver +
           " to run without a window on purpose.";
}

SdlContext::SdlContext(const SdlContextOptions& options) {
    try {
        if (!options.renderDriver.empty()) {
            SDL_SetHint(SDL_HINT_RENDER_DRIVER, options.renderDriver.c_str());
        }
        // SDL shows a software renderer's frames through an OpenGL texture by default; on a
        // machine without a GPU (Xvfb, llvmpipe) that upload costs more than the drawing. The
        // environment variable still wins (SDL_HINT_DEFAULT priority).
        if (options.renderDriver == "software") {
            SDL_SetHintWithPriority(SDL_HINT_FRAMEBUFFER_ACCELERATION, "0", SDL_HINT_DEFAULT);
        }
        // SIGINT and SIGTERM (Ctrl+C in a terminal, a shutdown, `kill`) end the program as
        // signals do; SDL would turn them into the window's close button, which asks about
        // unsaved changes in a dialog nobody at a terminal or a shutdown sees.
        SDL_SetHint(SDL_HINT_NO_SIGNAL_HANDLERS, "1");
        if (SDL_Init(SDL_INIT_VIDEO) != 0) {
            throw std::runtime_error(std::string("cannot start SDL video: ") + SDL_GetError());
        }
        videoStarted_ = true;
        const char* driver = SDL_GetCurrentVideoDriver();
        const std::string refused =
            noWindowReason(driver != nullptr ? driver : "", std::getenv("SDL_VIDEODRIVER"),
                           std::getenv("DISPLAY"), std::getenv("WAYLAND_DISPLAY"));
        if (!refused.empty()) throw std::runtime_error(refused);
        // SDL starts with text input on; the app wants it only while the edit prompt is open.
        SDL_StopTextInput();
        createWindow(options);
        rendererName_ = driverName(renderer_);
        rendererNote_ = "Renderer: " + rendererName_ +
                        (options.renderDriver.empty() ? " (SDL's choice)" : " (--renderer)");
        if (options.renderDriver.empty() &&
            (rendererName_ == "opengl" || rendererName_ == "opengles2")) {
            const std::string gl = glRendererString();
            if (isSoftwareRasteriser(gl)) {
                destroyWindow();
                SDL_SetHint(SDL_HINT_RENDER_DRIVER, "software");
                SDL_SetHintWithPriority(SDL_HINT_FRAMEBUFFER_ACCELERATION, "0", SDL_HINT_DEFAULT);
                createWindow(options);
                rendererName_ = driverName(renderer_);
                rendererNote_ = "Renderer: " + rendererName_ + " (OpenGL runs on " + gl +
                                ", a software rasteriser; SDL's software renderer is faster "
                                "there; --renderer opengl overrides)";
            }
        }
        fontFile_ = options.font;
        hudFont_ = std::make_unique<Font>(renderer_, options.font, kHudPoints);
        labelFont_ = std::make_unique<Font>(renderer_, options.font, kLabelPoints);
    } catch (...) {
        labelFont_.reset();
        hudFont_.reset();
        destroyWindow();
        if (videoStarted_) SDL_Quit();
        throw;
    }
}

SdlContext::~SdlContext() {
    labelFont_.reset();
    hudFont_.reset();
    destroyWindow();
    if (videoStarted_) SDL_Quit();
}

void SdlContext::createWindow(const SdlContextOptions& options) {
    window_ = SDL_CreateWindow("Particle Sandbox", SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED,
                               options.width, options.height,
                               SDL_WINDOW_RESIZABLE | SDL_WINDOW_ALLOW_HIGHDPI);
    if (window_ == nullptr) {
        throw std::runtime_error(std::string("cannot open a window: ") + SDL_GetError());
    }
    const Uint32 flags = options.vsync ? SDL_RENDERER_PRESENTVSYNC : 0;
    renderer_ = SDL_CreateRenderer(window_, -1, flags);
    if (renderer_ == nullptr) {
        throw std::runtime_error(std::string("cannot create a renderer: ") + SDL_GetError());
    }
}

void SdlContext::destroyWindow() {
    if (renderer_ != nullptr) SDL_DestroyRenderer(renderer_);
    if (window_ != nullptr) SDL_DestroyWindow(window_);
    renderer_ = nullptr;
    window_ = nullptr;
}

void SdlContext::setTextScale(double pointPixels) {
    if (pointPixels == textScale_) return;
    Font hud(renderer_, fontFile_, static_cast<int>(std::lround(kHudPoints * pointPixels)));
    Font label(renderer_, fontFile_, static_cast<int>(std::lround(kLabelPoints * pointPixels)));
    swap(*hudFont_, hud);
    swap(*labelFont_, label);
    textScale_ = pointPixels;
}

SDL_Point SdlContext::windowSize() const {
    SDL_Point p{0, 0};
    SDL_GetWindowSize(window_, &p.x, &p.y);
    return p;
}

SDL_Point SdlContext::outputSize() const {
    SDL_Point p{0, 0};
    SDL_GetRendererOutputSize(renderer_, &p.x, &p.y);
    return p;
}

double SdlContext::pixelRatio() const {
    int w = 0, h = 0;
    SDL_GetWindowSize(window_, &w, &h);
    const SDL_Point out = outputSize();
    return w > 0 && out.x > 0 ? static_cast<double>(out.x) / w : 1.0;
}

void SdlContext::setTitle(const std::string& title) {
    if (title == title_) return;
    SDL_SetWindowTitle(window_, title.c_str());
    title_ = title;
}

void SdlContext::present() {
    SDL_RenderPresent(renderer_);
}

}  // namespace psb::app
