#pragma once
// The control panel's test fixture: a session, the panel built in an offscreen ImGui frame,
// mouse input fed through ImGui's io, and the commands it returns applied as the app applies
// them (control_panel_test.cpp, section_values_test.cpp).

#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cstdio>
#include <filesystem>
#include <string>
#include <tuple>
#include <utility>

#include <imgui.h>
#include <imgui_internal.h>

#include <particle_sandbox/presets.hpp>
#include <particle_sandbox/scene.hpp>

#include "gui/control_panel.hpp"
#include "gui/gui_context.hpp"
#include "platform/assets.hpp"
#include "render/offscreen_test.hpp"
#include "session/scene_io.hpp"
#include "session/session.hpp"
#include "view/values_table.hpp"

namespace psb::app {
namespace {

constexpr int kSize = 800;

class ControlPanelTest : public OffscreenTest {
  protected:
    ControlPanelTest() : OffscreenTest(kSize) {}

    void SetUp() override {
        OffscreenTest::SetUp();
        GuiOptions o;
        o.font = findAsset("fonts/DejaVuSans.ttf");
        o.fontPixels = 15.f;
        gui_ = std::make_unique<GuiContext>(sdl_, o);
        SessionOptions so;
        so.paused = true;
        so.viewportWidth = kSize;
        so.viewportHeight = kSize;
        so.layout = windowLayout(*font_, kSize, kSize, controlsWidth(1.0, kSize));
        so.presets = presetScenes();
        session_.emplace(makeWorld(defaultScene()), SceneInfo{.name = "default", .dt = 1.0 / 60.0},
                         so);
        // ImGui settles its layout in the second frame (wrapped text takes the width the first
        // frame found).
        frame();
        frame();
    }
    void TearDown() override {
        gui_.reset();
        OffscreenTest::TearDown();
    }

    /// One frame: the panel built and drawn, its commands applied. Returns how many there were.
    std::size_t frame() {
        SDL_SetRenderDrawColor(sdl_, 0, 0, 0, 255);
        SDL_RenderClear(sdl_);
        gui_->beginFrame(kSize, kSize);
        const std::vector<Command> commands = panel_.build(*session_, FrameStats{}, kSize, 1.f);
        EXPECT_EQ(gui_->endFrame(), 0);
        SDL_RenderPresent(sdl_);
        for (const Command& c : commands)
            session_->apply(c);
        return commands.size();
    }
    [[nodiscard]] ImVec2 centre(const std::string& name) const {
        const PanelItem* i = panel_.item(name);
        EXPECT_NE(i, nullptr) << name;
        if (i == nullptr) return {-1.f, -1.f};
        EXPECT_LT(i->y1, static_cast<float>(kSize)) << name << " is below the window";
        return {(i->x0 + i->x1) / 2.f, (i->y0 + i->y1) / 2.f};
    }
    void click(const std::string& name) {
        ImGuiIO& io = gui_->io();
        frame();
        io.MousePos = centre(name);
        frame();
        io.MouseDown[0] = true;
        frame();
        io.MouseDown[0] = false;
        frame();
        io.MousePos = ImVec2(kSize - 5.f, kSize - 5.f);  // away, so no tooltip stays
        frame();
    }
    /// A drag of the named control from its centre to `to`, in `steps` frames.
    void drag(const std::string& name, ImVec2 to, int steps = 8) {
        ImGuiIO& io = gui_->io();
        frame();
        const ImVec2 from = centre(name);
        io.MousePos = from;
        frame();
        io.MouseDown[0] = true;
        frame();
        for (int k = 1; k <= steps; ++k) {
            const float t = static_cast<float>(k) / static_cast<float>(steps);
            io.MousePos = ImVec2(from.x + (to.x - from.x) * t, from.y + (to.y - from.y) * t);
            frame();
        }
        io.MouseDown[0] = false;
        frame();
    }

    /// Plays, a frame at a time, until the session hears a collision (at most 20 s), and
    /// pauses again: whether it heard one.
    bool runToACollision() {
        session_->apply(cmd::TogglePause{});
        for (int k = 1; k <= 1200 && !session_->lastCollision(); ++k) {
            session_->update(1.0 / 60.0, k / 60.0);
            frame();
        }
        session_->apply(cmd::TogglePause{});
        return session_->lastCollision().has_value();
    }

    /// Expects no two of the panel's `items` to share a point, each named in a failure: the
    /// values table's window and the presets' list (a child window that scrolls and clips its
    /// own lines) aside, and what the panel's scroll took under its pinned top line (which
    /// clips it) against that line's controls.
    static void expectNoOverlap(const std::vector<PanelItem>& items) {
        const auto aside = [](const PanelItem& i) {
            return i.name.rfind("values", 0) == 0 || i.name.rfind("preset ", 0) == 0;
        };
        const auto pinned = [](const PanelItem& i) {
            return i.name == "fold panel" || i.name == "About";
        };
        float topLine = -FLT_MAX;
        for (const PanelItem& i : items) {
            if (pinned(i)) topLine = std::max(topLine, i.y1);
        }
        const auto underTheTopLine = [&](const PanelItem& i, const PanelItem& j) {
            return (pinned(i) && !pinned(j) && j.y0 < topLine) ||
                   (pinned(j) && !pinned(i) && i.y0 < topLine);
        };
        for (std::size_t a = 0; a < items.size(); ++a) {
            const PanelItem& i = items[a];
            if (aside(i)) continue;
            for (std::size_t b = a + 1; b < items.size(); ++b) {
                const PanelItem& j = items[b];
                if (aside(j) || underTheTopLine(i, j)) continue;
                const bool apart = i.x1 <= j.x0 + 0.5f || j.x1 <= i.x0 + 0.5f ||
                                   i.y1 <= j.y0 + 0.5f || j.y1 <= i.y0 + 0.5f;
                EXPECT_TRUE(apart) << i.name << " [" << i.x0 << ", " << i.x1 << "] x [" << i.y0
                                   << ", " << i.y1 << "] overlaps " << j.name << " [" << j.x0
                                   << ", " << j.x1 << "] x [" << j.y0 << ", " << j.y1 << "]";
            }
        }
    }

    std::unique_ptr<GuiContext> gui_;
    std::optional<Session> session_;
    ControlPanel panel_;
};

}  // namespace
}  // namespace psb::app
