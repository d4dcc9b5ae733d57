// A slider's value reads wherever its handle is (gui/slider.hpp): drawn offscreen in both
// themes at 100 % and 200 %, the handle's column is never crossed by a digit, and the value is
// drawn beside it.

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

using widgets::sliderValueX;

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

TEST(SliderValue, IsCentredWhenClearOfTheHandleAndBesideItOtherwise) {
    // A 200-point frame, a 40-point value, a 4-point handle, a 5-point gap.
    EXPECT_FLOAT_EQ(sliderValueX(0.f, 200.f, 2.f, 6.f, 40.f, 5.f), 80.f) << "handle at the left";
    EXPECT_FLOAT_EQ(sliderValueX(0.f, 200.f, 194.f, 198.f, 40.f, 5.f), 80.f);
    // The handle in the middle: the value goes beside it, a gap away, inside the frame.
    for (const float h0 : {60.f, 80.f, 98.f, 99.f, 110.f, 130.f}) {
        const float h1 = h0 + 4.f;
        const float x = sliderValueX(0.f, 200.f, h0, h1, 40.f, 5.f);
        EXPECT_TRUE(x + 40.f + 5.f <= h0 + 1e-4f || x >= h1 + 5.f - 1e-4f)
            << "handle at " << h0 << ": the value at " << x << " crosses it";
        EXPECT_GE(x, 0.f);
        EXPECT_LE(x + 40.f, 200.f);
    }
}

TEST(SliderValue, KeepsHalfAGapFromTheFramesEdgeWhereThereIsRoom) {
    // The UI scale at 200 % in a narrow panel: "200 %" beside the handle touched the frame's
    // left edge. A 94-point frame, a 42-point value, the handle at 50, a 4.5-point gap.
    const float x = sliderValueX(0.f, 94.f, 50.f, 54.f, 42.f, 4.5f);
    EXPECT_GE(x, 2.25f - 1e-4f) << "touches the frame's left edge";
    EXPECT_LE(x + 42.f + 4.5f, 50.f + 1e-4f) << "crosses the handle";
    // The handle at the left, the value right of it, clear of the frame's right edge.
    const float right = sliderValueX(0.f, 94.f, 40.f, 44.f, 42.f, 4.5f);
    EXPECT_LE(right + 42.f, 94.f - 2.25f + 1e-4f) << "touches the frame's right edge";
    EXPECT_GE(right, 44.f + 4.5f - 1e-4f);
}

TEST_F(SliderTest, ItsHandleNeverCrossesItsDigits) {
    // Roughness 0 in -1..1 put the handle on the middle digit: "0.▮00", then "0.0|0" with a bar
    // showing above and below the digits, on a projector. With the handle anywhere, its column
    // is the bar from the top of the frame to the bottom: no digit drawn over or under it.
    for (const Theme theme : {Theme::Dark, Theme::Light}) {
        for (const float scale : {1.f, 2.f}) {
            const std::string at = std::string(theme == Theme::Light ? "light" : "dark") + " at " +
                                   std::to_string(static_cast<int>(scale * 100.f)) + " %";
            gui_->setTheme(theme);
            gui_->setScale(scale);
            for (const double value : {0.3, 0.45, 0.5, 0.55, 0.7}) {
                const Drawn d = draw(value, 0.0, 1.0, scale);
                // The handle's centre column, as ImGui places it (2 points of padding, a bar of
                // kSliderHandleWidth).
                const float usable = 200.f - 4.f - widgets::kSliderHandleWidth;
                const int cx = static_cast<int>((d.frame0.x / scale + 2.f +
                                                 static_cast<float>(value) * usable +
                                                 widgets::kSliderHandleWidth / 2.f) *
                                                scale);
                const int top = static_cast<int>(d.text0.y), bottom = static_cast<int>(d.text1.y);
                const SDL_Color bar = pixel(cx, top);
                int differ = 0;
                for (int y = top; y < bottom; ++y) {
                    const SDL_Color c = pixel(cx, y);
                    differ += c.r != bar.r || c.g != bar.g || c.b != bar.b;
                }
                EXPECT_EQ(differ, 0) << at << ", value " << value
                                     << ": the handle's column is crossed by the digits";
                // The value is drawn: something of the text's colour beside the handle.
                const SDL_Color frameColour = pixel(static_cast<int>(d.frame0.x) + 3, top);
                int text = 0;
                for (int y = top; y < bottom; ++y) {
                    for (int x = static_cast<int>(d.frame0.x) + 8; x < d.frame1.x - 8; ++x) {
                        if (std::abs(x - cx) < 4 * scale) continue;
                        const SDL_Color c = pixel(x, y);
                        text += contrastRatio(
                                    Rgba{c.r, c.g, c.b, 255},
                                    Rgba{frameColour.r, frameColour.g, frameColour.b, 255}) >= 3.0;
                    }
                }
                EXPECT_GT(text, 20) << at << ", value " << value << ": no value drawn";
            }
        }
    }
}

}  // namespace
}  // namespace psb::app
