// The bins chart drawn offscreen: bars, dots and the normal curve in its box, and axis
// captions that never overlap. What it says: view/bin_histogram_test.cpp.

#include <gtest/gtest.h>

#include <cmath>

#include <SDL.h>

#include "render/analysis_overlays.hpp"
#include "render/bin_chart.hpp"
#include "render/offscreen_test.hpp"
#include "render/sdl_color.hpp"
#include "view/bin_histogram.hpp"
#include "view/bins_fixture.hpp"
#include "view/screen_layout.hpp"

namespace psb::app {
namespace {

using test::eightRows;
using test::kBell;
using test::landed;

class BinHistogramDrawTest : public OffscreenTest {
  protected:
    BinHistogramDrawTest() : OffscreenTest(800) {}
    int count(SDL_Color c, const SDL_Rect& r, int tol = 10) const {
        int n = 0;
        for (int y = r.y; y < r.y + r.h; ++y) {
            for (int x = r.x; x < r.x + r.w; ++x) {
                const SDL_Color p = pixel(x, y);
                n += std::abs(p.r - c.r) <= tol && std::abs(p.g - c.g) <= tol &&
                     std::abs(p.b - c.b) <= tol;
            }
        }
        return n;
    }
};

TEST_F(BinHistogramDrawTest, DrawsTheBarsTheDotsAndTheNormalCurveInItsBox) {
    LayoutRequest req;
    req.width = 800;
    req.height = 800;
    req.bins = true;
    const PanelLayout layout = layoutPanels(req);
    ASSERT_GT(layout.bins.w, 0);
    EXPECT_EQ(layout.bins.h, kBinsMaxHeight);
    World w;
    AnalysisOverlays overlays;
    ViewOptions view;
    const std::optional<BinHistogram> h = binHistogram(eightRows(), landed(kBell));
    overlays.draw(sdl_, *font_, w, sampleObservables(w), camera_, TimeSeries(2), 0.5, view, layout,
                  h);
    SDL_RenderPresent(sdl_);
    // The plot area, below the legend's lines.
    const SDL_Rect plot{layout.bins.x + 44, layout.bins.y + 4 * font_->lineHeight() + 10,
                        layout.bins.w - 54, layout.bins.h - 6 * font_->lineHeight() - 16};
    EXPECT_GT(count(sdlColor(palette(Theme::Dark).binBar), plot), 2000);
    EXPECT_GT(count(sdlColor(palette(Theme::Dark).normalCurve), plot, 0), 100);
    EXPECT_GT(count(sdlColor(palette(Theme::Dark).theoryCurve), plot, 0), 9 * 20);
    // The middle bar is the tallest: its colour reaches higher than the first bar's.
    const auto topOf = [&](int column) {
        for (int y = plot.y; y < plot.y + plot.h; ++y) {
            const SDL_Color p = pixel(column, y);
            if (std::abs(p.r - sdlColor(palette(Theme::Dark).binBar).r) <= 10 &&
                std::abs(p.g - sdlColor(palette(Theme::Dark).binBar).g) <= 10)
                return y;
        }
        return plot.y + plot.h;
    };
    const float binW = static_cast<float>(plot.w) / 9.f;
    EXPECT_LT(topOf(plot.x + static_cast<int>(4.3f * binW)),
              topOf(plot.x + static_cast<int>(1.3f * binW)));
    // Nothing outside its box.
    SDL_Rect left{0, 0, layout.bins.x - 1, 800};
    EXPECT_EQ(count(sdlColor(palette(Theme::Dark).binBar), left), 0);
}

TEST_F(BinHistogramDrawTest, TheAxisCaptionsNeverOverlapEachOtherOrTheTickLabels) {
    // Both captions used to share the line under the bin numbers, "balls" at the left and the
    // x caption right-aligned: they overlapped in every Galton view. Every chart size, from the
    // narrowest panel to a wide one, and legends of one to six lines.
    const auto meet = [](const SDL_FRect& a, const SDL_FRect& b) {
        return a.x < b.x + b.w && b.x < a.x + a.w && a.y < b.y + b.h && b.y < a.y + a.h;
    };
    const float lh = static_cast<float>(font_->lineHeight());
    int drawn = 0;
    for (const char* xTitle : {"bin = times a ball went right", "bin, left to right"}) {
        for (int width = 120; width <= 800; width += 10) {
            for (int lines = 1; lines <= 6; ++lines) {
                const float x = 10, y = 20, height = kBinsMinHeight;
                const float legendBottom = y + 4 + static_cast<float>(lines) * lh;
                const BinChartLayout c = binChartLayout(*font_, x, static_cast<float>(width),
                                                        legendBottom, y + height, "balls", xTitle);
                if (!c.fits()) continue;
                ++drawn;
                SCOPED_TRACE(std::string(xTitle) + ", width " + std::to_string(width) + ", " +
                             std::to_string(lines) + " legend lines");
                EXPECT_FALSE(meet(c.yCaption, c.xCaption));
                EXPECT_GE(c.yCaption.y, legendBottom) << "under the legend";
                EXPECT_GE(c.xCaption.x, x) << "inside the box";
                EXPECT_LE(c.xCaption.y + c.xCaption.h, y + height) << "inside the box";
                // The top tick label (centred on the plot's top) and the bin numbers
                // (the line under the axis) stay clear of the captions.
                const SDL_FRect topTick{x, c.top - lh / 2, c.left - x, lh};
                const SDL_FRect binNumbers{x, c.bottom + 3, static_cast<float>(width), lh};
                EXPECT_FALSE(meet(c.yCaption, topTick));
                EXPECT_FALSE(meet(c.xCaption, binNumbers));
                EXPECT_FALSE(meet(c.yCaption, binNumbers));
            }
        }
    }
    EXPECT_GT(drawn, 100);
}

}  // namespace
}  // namespace psb::app
