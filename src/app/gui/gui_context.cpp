#include "gui/gui_context.hpp"

#include <cfloat>
#include <stdexcept>
#include <string>
#include <system_error>

#include <backends/imgui_impl_sdl.h>
#include <imgui.h>
#include <imgui_internal.h>

namespace psb::app {

namespace {

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
    : window_(window), sdl_(renderer) {
    if (sdl_ == nullptr) throw std::runtime_error("GuiContext: no SDL renderer");
    IMGUI_CHECKVERSION();
    ImGuiContext* previous = ImGui::GetCurrentContext();
    context_ = ImGui::CreateContext();
    makeCurrent();  // CreateContext makes the new context current only when there is none
    try {
        ImGuiIO& io = ImGui::GetIO();
        io.IniFilename = nullptr;
        io.LogFilename = nullptr;
        ImGui::StyleColorsDark();
        if (window_ != nullptr) {
            if (!ImGui_ImplSDL2_InitForSDLRenderer(window_)) {
                throw std::runtime_error("GuiContext: the SDL2 platform backend did not start");
            }
            platform_ = true;
        }
        const float scale = window_ != nullptr ? windowPixelScale(window_, sdl_) : 1.f;
        loadFont(options, scale);
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

void GuiContext::loadFont(const GuiOptions& options, float pixelScale) {
    if (options.font.empty()) return;
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
    ImFontConfig config;
    config.OversampleH = 1;
    config.PixelSnapH = true;
    // Latin-1 (ImGui's default) and Greek, for the physics' letters (omega, beta, mu, theta).
    static const ImWchar kRanges[] = {0x0020, 0x00FF, 0x0370, 0x03FF, 0};
    if (io.Fonts->AddFontFromFileTTF(options.font.string().c_str(), options.fontPixels * pixelScale,
                                     &config, kRanges) == nullptr) {
        throw std::runtime_error("GuiContext: cannot load font " + options.font.string());
    }
    io.FontGlobalScale = 1.f / pixelScale;
}

bool GuiContext::handleEvent(const SDL_Event& event) {
    makeCurrent();
    if (platform_) ImGui_ImplSDL2_ProcessEvent(&event);
    if (event.type == SDL_MOUSEMOTION) {
        mouse_ = ImVec2(static_cast<float>(event.motion.x), static_cast<float>(event.motion.y));
    } else if (event.type == SDL_MOUSEBUTTONDOWN || event.type == SDL_MOUSEBUTTONUP) {
        mouse_ = ImVec2(static_cast<float>(event.button.x), static_cast<float>(event.button.y));
    } else if (event.type == SDL_WINDOWEVENT && event.window.event == SDL_WINDOWEVENT_LEAVE) {
        mouse_.reset();
    }
    const ImGuiIO& io = ImGui::GetIO();
    switch (event.type) {
        case SDL_MOUSEBUTTONDOWN: {
            const ImVec2 at(static_cast<float>(event.button.x), static_cast<float>(event.button.y));
            // A finger (SDL's mouse from touch) jumps: where the mouse was in the last frame,
            // over the panel or not, says nothing about where it comes down.
            const bool touch = event.button.which == SDL_TOUCH_MOUSEID;
            const bool taken = (io.WantCaptureMouse && !touch) || overWindow(at);
            if (taken) takenButtons_ |= SDL_BUTTON(event.button.button);
            return taken;
        }
        case SDL_MOUSEBUTTONUP: {
            const Uint32 bit = SDL_BUTTON(event.button.button);
            const bool taken = (takenButtons_ & bit) != 0;
            takenButtons_ &= ~bit;
            return taken || io.WantCaptureMouse;
        }
        case SDL_MOUSEWHEEL: {
#if SDL_VERSION_ATLEAST(2, 26, 0)
            const ImVec2 at(static_cast<float>(event.wheel.mouseX),
                            static_cast<float>(event.wheel.mouseY));
#else
            const ImVec2 at = mouse_.value_or(ImVec2(-FLT_MAX, -FLT_MAX));
#endif
            return io.WantCaptureMouse || overWindow(at);
        }
        case SDL_MOUSEMOTION:
            // A drag the world started goes on over a panel; ImGui's own drags are captured.
            return io.WantCaptureMouse;
        case SDL_KEYDOWN:
        case SDL_KEYUP:
            return io.WantCaptureKeyboard;
        case SDL_TEXTINPUT:
        case SDL_TEXTEDITING:
            return io.WantTextInput;
        default:
            return false;
    }
}

bool GuiContext::overWindow(ImVec2 p) const {
    makeCurrent();
    const ImGuiContext& g = *ImGui::GetCurrentContext();
    for (const ImGuiWindow* w : g.Windows) {
        if (!w->Active || w->Hidden || (w->Flags & ImGuiWindowFlags_NoMouseInputs) != 0) continue;
        if (w->OuterRectClipped.Contains(p)) return true;
    }
    return false;
}

void GuiContext::beginFrame() {
    makeCurrent();
    if (!platform_) throw std::logic_error("GuiContext::beginFrame(): no window; give a size");
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
    // Debian's 1.86 backend takes the scale from SDL_GL_GetDrawableSize, which is the window
    // size for a window without OpenGL; the renderer's output size is the one drawn into.
    const float scale = windowPixelScale(window_, sdl_);
    ImGui::GetIO().DisplayFramebufferScale = ImVec2(scale, scale);
    ImGui::NewFrame();
}

void GuiContext::beginFrame(float width, float height, float dt, float pixelScale) {
    makeCurrent();
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(width, height);
    io.DisplayFramebufferScale = ImVec2(pixelScale, pixelScale);
    io.DeltaTime = dt > 0.f ? dt : 1.f / 60.f;
    ImGui::NewFrame();
}

int GuiContext::endFrame() {
    makeCurrent();
    ImGui::Render();
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
