// A real window with on-screen controls (GuiContext + ImGuiRenderer) for the end-to-end check
// gui_window_e2e.sh: it logs what the controls did on stdout, and P writes the window as a PNG.
//
//   gui_window_check OUTPUT.png
//
// Log lines: "button x y" (the Play button's centre, window pixels), "slider x0 x1 y" (the
// restitution slider's extent), "pressed N", "restitution E", "arrows on|off", "box click x y"
// (a click the controls did not take), "saved PATH". Exits on Esc, window close, or after 60 s.

#include <cstdio>
#include <fstream>
#include <string>

#include <SDL.h>
#include <imgui.h>

#include "gui/gui_context.hpp"
#include "platform/assets.hpp"
#include "render/screenshot.hpp"

namespace {

void log(const std::string& line) {
    std::printf("%s\n", line.c_str());
    std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: gui_window_check OUTPUT.png\n");
        return 2;
    }
    const std::string output = argv[1];
    SDL_SetHint(SDL_HINT_RENDER_DRIVER, "software");
    if (SDL_Init(SDL_INIT_VIDEO) != 0) {
        std::fprintf(stderr, "gui_window_check: %s\n", SDL_GetError());
        return 1;
    }
    SDL_Window* window = SDL_CreateWindow("GUI check", SDL_WINDOWPOS_UNDEFINED,
                                          SDL_WINDOWPOS_UNDEFINED, 480, 320, SDL_WINDOW_SHOWN);
    SDL_Renderer* sdl =
        window != nullptr ? SDL_CreateRenderer(window, -1, SDL_RENDERER_SOFTWARE) : nullptr;
    if (sdl == nullptr) {
        std::fprintf(stderr, "gui_window_check: %s\n", SDL_GetError());
        return 1;
    }
    int status = 0;
    try {
        psb::app::GuiOptions options;
        options.font = psb::app::findAsset("fonts/DejaVuSans.ttf");
        psb::app::GuiContext gui(window, sdl, options);
        int pressed = 0;
        bool arrows = false;
        float restitution = 1.f;
        bool reported = false;
        bool saveRequested = false;
        const Uint32 start = SDL_GetTicks();
        for (bool running = true; running && SDL_GetTicks() - start < 60000;) {
            SDL_Event e;
            while (SDL_PollEvent(&e) != 0) {
                const bool taken = gui.handleEvent(e);
                if (e.type == SDL_QUIT) running = false;
                if (taken) continue;
                if (e.type == SDL_KEYDOWN && e.key.keysym.sym == SDLK_ESCAPE) running = false;
                if (e.type == SDL_KEYDOWN && e.key.keysym.sym == SDLK_p) saveRequested = true;
                if (e.type == SDL_MOUSEBUTTONDOWN) {
                    log("box click " + std::to_string(e.button.x) + " " +
                        std::to_string(e.button.y));
                }
            }

            SDL_SetRenderDrawColor(sdl, 24, 28, 36, 255);
            SDL_RenderClear(sdl);
            const SDL_Rect box{250, 20, 210, 280};  // where the app would draw the world
            SDL_SetRenderDrawColor(sdl, 200, 200, 200, 255);
            SDL_RenderDrawRect(sdl, &box);

            gui.beginFrame();
            ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_Always);
            ImGui::SetNextWindowSize(ImVec2(230, 200), ImGuiCond_Always);
            ImGui::Begin("Controls", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize);
            if (ImGui::Button("Play", ImVec2(120, 32))) log("pressed " + std::to_string(++pressed));
            const ImVec2 b0 = ImGui::GetItemRectMin(), b1 = ImGui::GetItemRectMax();
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("Start or stop time");
            if (ImGui::Checkbox("Velocity arrows", &arrows)) {
                log(std::string("arrows ") + (arrows ? "on" : "off"));
            }
            ImGui::SetNextItemWidth(120);
            if (ImGui::SliderFloat("Bounce", &restitution, 0.f, 1.f, "%.2f")) {
                log("restitution " + std::to_string(restitution));
            }
            const ImVec2 s0 = ImGui::GetItemRectMin();
            ImGui::Text("Pressed %d times", pressed);
            ImGui::TextWrapped("Energy kept to 1 part in 10\u00b9\u2074");
            ImGui::End();
            if (!reported) {
                log("button " + std::to_string(static_cast<int>((b0.x + b1.x) / 2)) + " " +
                    std::to_string(static_cast<int>((b0.y + b1.y) / 2)));
                log("slider " + std::to_string(static_cast<int>(s0.x)) + " " +
                    std::to_string(static_cast<int>(s0.x + 120)) + " " +
                    std::to_string(static_cast<int>(s0.y + 8)));
                reported = true;
            }
            if (gui.endFrame() != 0) log(std::string("draw failed: ") + SDL_GetError());
            if (saveRequested) {
                std::ofstream(output, std::ios::binary) << psb::app::capturePng(sdl);
                log("saved " + output);
                saveRequested = false;
            }
            SDL_RenderPresent(sdl);
            SDL_Delay(10);
        }
    } catch (const std::exception& ex) {
        std::fprintf(stderr, "gui_window_check: %s\n", ex.what());
        status = 1;
    }
    SDL_DestroyRenderer(sdl);
    SDL_DestroyWindow(window);
    SDL_Quit();
    return status;
}
