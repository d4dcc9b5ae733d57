// A slider's value reads wherever its handle is (gui/slider.hpp): drawn offscreen in both
// themes at 100 % and 200 %, the digits' pixels are the same with the handle under them as with
// the handle at the far end, and the handle still shows.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <imgui.h>

#include "gui/gui_context.hpp"
#include "gui/widgets.hpp"
#include "platform/assets.hpp"
#include "render/offscreen_test.hpp"
#include "view/palette.hpp"

namespace psb::app {
namespace {

constexpr int kSize = 600;

class SliderTest : public OffscreenTest {
  protected:
    SliderTest() : OffscreenTest(kSize) {}

    void SetUp() override {
        OffscreenTest::SetUp();
        GuiOptions o;
        o.font = findAsset("fonts/DejaVuSans.ttf");
        o.fontPixels = 15.f;
        gui_ = std::make_unique<GuiContext>(sdl_, o);
    }
    void TearDown() override {
        gui_.reset();
        OffscreenTest::TearDown();
    }

    /// Where the slider and its value's text were drawn, window pixels.
    struct Drawn {
        ImVec2 frame0, frame1;  ///< the slider's frame
        ImVec2 text0, text1;    ///< the value's text, as ImGui centres it
    };

    /// A frame with one slider of `value` in [lo, hi] written "%.2f", 200 points wide, at
    /// `scale`; presented, so that pixel() reads it.
    Drawn draw(double value, double lo, double hi, float scale) {
        Drawn d;
        for (int k = 0; k < 2; ++k) {  // the second frame has the settled layout
            SDL_SetRenderDrawColor(sdl_, 0, 0, 0, 255);
            SDL_RenderClear(sdl_);
            gui_->beginFrame(kSize, kSize);
            ImGui::SetNextWindowPos(ImVec2(10.f, 10.f));
            ImGui::SetNextWindowSize(ImVec2(280.f, 80.f));
            ImGui::Begin("Sliders", nullptr,
                         ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoTitleBar);
            ImGui::SetNextItemWidth(200.f);
            double v = value;
            bool continues = false;
            widgets::slider("Roughness", v, lo, hi, "%.2f", continues);
            const float height = ImGui::GetFrameHeight();
            d.frame0 = ImGui::GetItemRectMin();
            d.frame1 = ImVec2(d.frame0.x + 200.f, d.frame0.y + height);
            const ImVec2 t = ImGui::CalcTextSize("0.50");
            d.text0 = ImVec2(d.frame0.x + (200.f - t.x) / 2.f, d.frame0.y + (height - t.y) / 2.f);
            d.text1 = ImVec2(d.text0.x + t.x, d.text0.y + t.y);
            ImGui::End();
            EXPECT_EQ(gui_->endFrame(), 0);
            SDL_RenderPresent(sdl_);
        }
        // In pixels.
        for (ImVec2* p : {&d.frame0, &d.frame1, &d.text0, &d.text1}) {
            p->x *= scale;
            p->y *= scale;
        }
        return d;
    }

    /// The pixels of a rectangle, row by row.
    [[nodiscard]] std::vector<Uint32> pixels(int x0, int y0, int x1, int y1) const {
        std::vector<Uint32> out;
        for (int y = y0; y < y1; ++y) {
            for (int x = x0; x < x1; ++x) {
                const SDL_Color c = pixel(x, y);
                out.push_back(static_cast<Uint32>(c.r) << 16 | static_cast<Uint32>(c.g) << 8 | c.b);
            }
        }
        return out;
    }

    std::unique_ptr<GuiContext> gui_;
};

TEST_F(SliderTest, ItsDigitsReadTheSameWhereverItsHandleIs) {
    // Roughness 0 in -1..1 put the handle on the middle digit: "0.▮00" on a projector. The
    // value 0.50 with its handle in the middle of the slider (0 to 1) and at its left end
    // (0.5 to 1.5) must show the same pixels where its digits are.
    for (const Theme theme : {Theme::Dark, Theme::Light}) {
        for (const float scale : {1.f, 2.f}) {
            const std::string at = std::string(theme == Theme::Light ? "light" : "dark") + " at " +
                                   std::to_string(static_cast<int>(scale * 100.f)) + " %";
            gui_->setTheme(theme);
            gui_->setScale(scale);
            // The digits' rows: those of the value's line where, with the handle at the far
            // end, anything but the slider's colour is drawn.
            const Drawn left = draw(0.5, 0.5, 1.5, scale);
            const int x0 = static_cast<int>(left.text0.x) - 1;
            const int x1 = static_cast<int>(std::ceil(left.text1.x)) + 1;
            const SDL_Color frameColour =
                pixel(static_cast<int>(left.frame1.x) - 30, static_cast<int>(left.text0.y));
            int y0 = -1, y1 = -1;
            for (int y = static_cast<int>(left.text0.y); y < std::ceil(left.text1.y); ++y) {
                for (int x = x0; x < x1; ++x) {
                    const SDL_Color c = pixel(x, y);
                    if (c.r != frameColour.r || c.g != frameColour.g || c.b != frameColour.b) {
                        if (y0 < 0) y0 = y;
                        y1 = y + 1;
                        break;
                    }
                }
            }
            ASSERT_GT(y1, y0) << at << ": no digits drawn";
            const std::vector<Uint32> awayFromHandle = pixels(x0, y0, x1, y1);

            const Drawn middle = draw(0.5, 0.0, 1.0, scale);
            ASSERT_EQ(left.text0.x, middle.text0.x) << at;
            const std::vector<Uint32> underMiddle = pixels(x0, y0, x1, y1);
            std::size_t differ = 0;
            for (std::size_t i = 0; i < underMiddle.size(); ++i)
                differ += underMiddle[i] != awayFromHandle[i];
            EXPECT_EQ(differ, 0u) << at << ": the handle changed " << differ << " of "
                                  << underMiddle.size() << " pixels of the digits";
            // The handle shows: the slider's middle column above the digits is not all the
            // slider's colour.
            const int cx = static_cast<int>((middle.frame0.x + middle.frame1.x) / 2.f);
            bool handleSeen = false;
            for (int y = static_cast<int>(middle.frame0.y) + 2; y < y0; ++y) {
                const SDL_Color c = pixel(cx, y);
                handleSeen = handleSeen || contrastRatio(Rgba{c.r, c.g, c.b, 255},
                                                         Rgba{frameColour.r, frameColour.g,
                                                              frameColour.b, 255}) >= 1.5;
            }
            EXPECT_TRUE(handleSeen) << at << ": the handle in the middle shows above the digits";
        }
    }
}

}  // namespace
}  // namespace psb::app
