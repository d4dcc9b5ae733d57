// What on-screen controls cost a frame with SDL's software renderer (the renderer the app uses
// under Xvfb): Dear ImGui's frame (widgets, layout, draw lists) plus the SDL_Renderer adapter
// (src/app/gui/imgui_renderer.hpp) drawing it into a 900 × 800 surface, without a window.
//
//   build/release/src/app/bench/gui_bench
//
// A frame without a panel (clear and present: the baseline), and three panels: a control panel of
// the size issue 14 asks for (about forty widgets: buttons, sliders, checkboxes, a table of
// readouts, tooltips closed), ImGui's own demo window (larger, many widget kinds), and the
// control panel on an opaque background (ImGui's dark style makes windows 94 % opaque, which
// SDL's software renderer must blend). Each iteration is one whole frame: clear, the ImGui frame,
// the adapter's draw, present. Counters: vertices and draw commands per frame. Compare with the
// 16.7 ms of a 60 Hz frame and with the app's --bench frame times (docs/app.md).

#include <benchmark/benchmark.h>

#include <SDL.h>
#include <imgui.h>

#include "gui/gui_context.hpp"
#include "platform/assets.hpp"

namespace {

constexpr int kWidth = 900, kHeight = 800;

// A stand-in for the control panel: its size and widget kinds, not its final contents.
void controlPanel() {
    static bool playing = true, arrows = true, labels = false, walls = true, gravity = false;
    static float restitution = 1.f, friction = 0.f, speed = 1.f, mass = 1.f, radius = 0.2f;
    static int mode = 0, tool = 0;
    ImGui::SetNextWindowPos(ImVec2(kWidth - 300.f, 0.f));
    ImGui::SetNextWindowSize(ImVec2(300.f, static_cast<float>(kHeight)));
    ImGui::Begin("Controls", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize);
    if (ImGui::CollapsingHeader("Time", ImGuiTreeNodeFlags_DefaultOpen)) {
        ImGui::Button(playing ? "Pause" : "Play");
        ImGui::SameLine();
        ImGui::Button("Step");
        ImGui::SameLine();
        ImGui::Button("Step back");
        ImGui::SameLine();
        ImGui::Button("Reset");
        ImGui::SliderFloat("Time speed", &speed, 0.125f, 8.f, "x%.3g");
    }
    if (ImGui::CollapsingHeader("Physics", ImGuiTreeNodeFlags_DefaultOpen)) {
        ImGui::RadioButton("Fast", &mode, 0);
        ImGui::SameLine();
        ImGui::RadioButton("Substeps", &mode, 1);
        ImGui::SameLine();
        ImGui::RadioButton("Exact", &mode, 2);
        ImGui::TextWrapped("Fast: one collision pass per frame; quick, may miss collisions.");
        ImGui::SliderFloat("Bounciness", &restitution, 0.f, 1.f, "%.2f");
        ImGui::SliderFloat("Friction", &friction, 0.f, 1.f, "%.2f");
        ImGui::Checkbox("Gravity (9.81 m/s\xc2\xb2)", &gravity);
        ImGui::Checkbox("Walls", &walls);
    }
    if (ImGui::CollapsingHeader("Show", ImGuiTreeNodeFlags_DefaultOpen)) {
        ImGui::Checkbox("Velocity arrows", &arrows);
        ImGui::Checkbox("Labels", &labels);
        static bool on[5] = {};
        const char* names[5] = {"Momentum", "Centre of mass", "Trails", "Plots", "Histogram"};
        for (int k = 0; k < 5; ++k)
            ImGui::Checkbox(names[k], &on[k]);
    }
    if (ImGui::CollapsingHeader("Tools", ImGuiTreeNodeFlags_DefaultOpen)) {
        ImGui::Combo("Left mouse", &tool, "Fling\0Launch\0Select\0Pan\0");
        ImGui::SliderFloat("Mass", &mass, 0.1f, 20.f, "%.2f kg");
        ImGui::SliderFloat("Radius", &radius, 0.05f, 1.f, "%.2f m");
    }
    if (ImGui::CollapsingHeader("Readouts", ImGuiTreeNodeFlags_DefaultOpen) &&
        ImGui::BeginTable("readouts", 2, ImGuiTableFlags_RowBg)) {
        const char* rows[][2] = {{"Time", "12.34 s"},
                                 {"Particles", "10000"},
                                 {"Kinetic energy", "1234.5 J"},
                                 {"Momentum", "(1.2, -0.4) kg m/s"},
                                 {"Energy kept", "to 1 part in 10\u00b9\u2074"},
                                 {"Deepest overlap", "0 mm"}};
        for (const auto& row : rows) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(row[0]);
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(row[1]);
        }
        ImGui::EndTable();
    }
    ImGui::End();
}

void BM_PanelFrame(benchmark::State& state) {
    SDL_Surface* surface =
        SDL_CreateRGBSurfaceWithFormat(0, kWidth, kHeight, 32, SDL_PIXELFORMAT_ARGB8888);
    SDL_Renderer* sdl = surface != nullptr ? SDL_CreateSoftwareRenderer(surface) : nullptr;
    if (sdl == nullptr) {
        state.SkipWithError(SDL_GetError());
        return;
    }
    {
        psb::app::GuiOptions options;
        options.font = psb::app::findAsset("fonts/DejaVuSans.ttf");
        psb::app::GuiContext gui(sdl, options);
        // 0 none, 1 controls, 2 demo, 3 controls on an opaque background
        const int panel = static_cast<int>(state.range(0));
        if (panel == 3) ImGui::GetStyle().Colors[ImGuiCol_WindowBg].w = 1.f;
        int vertices = 0, commands = 0;
        for (auto _ : state) {
            SDL_SetRenderDrawColor(sdl, 20, 24, 30, 255);
            SDL_RenderClear(sdl);
            if (panel > 0) {
                gui.beginFrame(kWidth, kHeight);
                if (panel == 2) {
                    ImGui::SetNextWindowPos(ImVec2(0, 0));
                    ImGui::SetNextWindowSize(ImVec2(600, static_cast<float>(kHeight)));
                    ImGui::ShowDemoWindow();
                } else {
                    controlPanel();
                }
                if (gui.endFrame() != 0) state.SkipWithError("a draw call failed");
            }
            SDL_RenderPresent(sdl);
            if (panel > 0) {
                const ImDrawData& d = *ImGui::GetDrawData();
                vertices = d.TotalVtxCount;
                commands = 0;
                for (int n = 0; n < d.CmdListsCount; ++n)
                    commands += d.CmdLists[n]->CmdBuffer.Size;
            }
        }
        const char* labels[] = {"no panel (clear and present only)", "control panel",
                                "ImGui demo window", "control panel, opaque background"};
        state.SetLabel(labels[panel]);
        state.counters["vertices"] = vertices;
        state.counters["draw_commands"] = commands;
    }
    SDL_DestroyRenderer(sdl);
    SDL_FreeSurface(surface);
}
BENCHMARK(BM_PanelFrame)->ArgName("panel")->DenseRange(0, 3)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
