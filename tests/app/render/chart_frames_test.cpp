// The side column's charts drawn offscreen at 200 % (a 24 px font in a frame as narrow as the
// column gets): their text stays inside their frames (view/chart_text.hpp). The speed
// histogram's legend ran past the frame's right edge, the plots' tick labels past its left.

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <SDL.h>

#include "render/offscreen_test.hpp"
#include "render/plot_chart.hpp"
#include "render/speed_chart.hpp"
#include "view/screen_layout.hpp"

namespace psb::app {
namespace {

constexpr SDL_Color kOutside{255, 0, 255, 255};
/// The side column's narrowest frame at 200 %.
constexpr int kWidth = 2 * kSideColumnMinWidth;

class ChartFrameTest : public OffscreenTest {
  protected:
    ChartFrameTest() : OffscreenTest(1000) {}
    void SetUp() override {
        OffscreenTest::SetUp();
        big_ = std::make_unique<Font>(sdl_, findAsset("fonts/DejaVuSansMono.ttf"), 24);
        SDL_SetRenderDrawColor(sdl_, kOutside.r, kOutside.g, kOutside.b, 255);
        SDL_RenderClear(sdl_);
    }
    void TearDown() override {
        big_.reset();
        OffscreenTest::TearDown();
    }
    /// Pixels outside `box` that are not the background: what the chart drew beyond its frame.
    [[nodiscard]] int outside(const PixelRect& box) const {
        int n = 0;
        for (int y = 0; y < size_; ++y) {
            for (int x = 0; x < size_; ++x) {
                if (x >= box.x && x < box.x + box.w && y >= box.y && y < box.y + box.h) continue;
                const SDL_Color p = pixel(x, y);
                n += p.r != kOutside.r || p.g != kOutside.g || p.b != kOutside.b;
            }
        }
        return n;
    }
    /// The speed histogram of w's particles drawn at 200 % in a frame of the plots' width and
    /// twice its least height: the pixels it drew outside that frame.
    [[nodiscard]] int speedsDrawnOutsideTheirFrame(const World& w) {
        const PixelRect box{300, 100, kWidth, 2 * kSpeedsMinHeight};
        SpeedChart chart;
        chart.draw(sdl_, *big_, w.particles(), box, palette(Theme::Light), 2.f);
        SDL_RenderPresent(sdl_);
        return outside(box);
    }
    std::unique_ptr<Font> big_;
};

TEST_F(ChartFrameTest, TheSpeedHistogramsLegendStaysInItsFrameAt200Percent) {
    WorldDef def;
    def.width = def.height = 100.0;
    World w(def);
    std::mt19937_64 rng(3);
    std::normal_distribution<double> g(0.0, 1.0);
    for (int k = 0; k < 400; ++k) {
        w.add({.position = Vec2(2.0 + (k % 20) * 4.0, 2.0 + (k / 20) * 4.0),
               .velocity = Vec2(g(rng), g(rng)),
               .radius = 0.5});
    }
    EXPECT_EQ(speedsDrawnOutsideTheirFrame(w), 0) << "pixels drawn outside the histogram's frame";
}

TEST_F(ChartFrameTest, TheSpeedHistogramsLastTickLabelStaysInsideItsFrame) {
    // Every particle at 2 m/s: the speed axis ends at 2, a tick there, its label "2.0" centred
    // on the axis's right end ran past the frame's edge (at the window's edge, at 200 %).
    WorldDef def;
    def.width = 100.0;
    def.height = 100.0;
    World w(def);
    for (int k = 0; k < 100; ++k) {
        const double a = 0.0628 * k;
        w.add({.position = Vec2(5.0 + (k % 10) * 9.0, 5.0 + (k / 10) * 9.0),
               .velocity = Vec2(2.0 * std::cos(a), 2.0 * std::sin(a)),
               .radius = 0.5});
    }
    EXPECT_EQ(speedsDrawnOutsideTheirFrame(w), 0) << "pixels drawn outside the histogram's frame";
}

TEST_F(ChartFrameTest, ThePlotsTickLabelsAndTitlesStayInTheirFrameAt200Percent) {
    // A momentum px from -10.1 to -10.0 kg m/s (its tick labels "-10.075", seven characters),
    // py negative, in two rows as short as they get at 200 % and in four.
    TimeSeries series(200);
    for (int k = 0; k < 200; ++k) {
        ObservablesSample s;
        s.time = 0.02 * k;
        s.kineticEnergy = 3.5 - 0.001 * k;
        s.momentum = Vec2(-10.1 + 0.0005 * k, -1.25 + 0.01 * k);
        s.collisions = static_cast<std::uint64_t>(k);
        series.record(s);
    }
    for (const std::vector<int>& which : {std::vector<int>{1, 2}, std::vector<int>{0, 1, 2, 3}}) {
        const int rows = static_cast<int>(which.size());
        SDL_RenderClear(sdl_);
        const int rowHeight = 2 * kPlotRowMinHeight;
        const PixelRect box{300, 100, kWidth, rows * rowHeight + 8};
        PlotChart chart;
        chart.draw(sdl_, *big_, series, box, rowHeight, 4.0, 0.5, palette(Theme::Light), true, 2.f,
                   which);
        SDL_RenderPresent(sdl_);
        EXPECT_EQ(outside(box), 0) << rows << " rows: pixels drawn outside the plots' frame";
    }
}

TEST_F(ChartFrameTest, FourPlotsSideBySideUnderTheBoxKeepTheirTitlesInTheirFrames) {
    // Lesson 1 at 200 % in 1600 x 1000: the four plots stand side by side in the band under
    // the box, each 271 pixels wide; "momentum px (kg m/s)" and "collisions/s, last 0.5 s"
    // would run past a frame that narrow: the brief titles ("px (kg m/s)") stay in it.
    TimeSeries series(120);
    for (int k = 0; k < 120; ++k) {
        ObservablesSample s;
        s.time = k / 60.0;
        s.kineticEnergy = 3.5;
        s.momentum = Vec2(-1.0, 0.0);
        s.collisions = static_cast<std::uint64_t>(k / 30);
        series.record(s);
    }
    const int each = (1104 - 3 * kPanelGap) / 4;
    for (int plot = 0; plot < kPlotCount; ++plot) {
        SDL_RenderClear(sdl_);
        const PixelRect box{300, 100, each, 2 * kPlotRowMinHeight + 8};
        PlotChart chart;
        chart.draw(sdl_, *big_, series, box, 2 * kPlotRowMinHeight, 4.0, 0.5, palette(Theme::Light),
                   true, 2.f, {plot});
        SDL_RenderPresent(sdl_);
        EXPECT_EQ(outside(box), 0) << "plot " << plot << ": pixels outside its frame";
    }
}

}  // namespace
}  // namespace psb::app
