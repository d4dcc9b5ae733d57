// The counted bins marked on the board: a Galton board has more channels than bins (the outer
// ones catch balls knocked wide), so the bins the chart counts are drawn in the bars' orange
// where they are, with their numbers.

#include <gtest/gtest.h>

#include <cmath>

#include <SDL.h>

#include "render/bin_chart.hpp"
#include "render/bin_marks.hpp"
#include "render/offscreen_test.hpp"
#include "render/sdl_color.hpp"
#include "render/text.hpp"
#include "view/bins_fixture.hpp"

namespace psb::app {
namespace {

class BinMarksTest : public OffscreenTest {
  protected:
    BinMarksTest() : OffscreenTest(400) {}
    [[nodiscard]] int orange(const SDL_Rect& r) const {
        int n = 0;
        for (int y = r.y; y < r.y + r.h; ++y) {
            for (int x = r.x; x < r.x + r.w; ++x) {
                const SDL_Color p = pixel(x, y);
                n += std::abs(p.r - sdlColor(palette(Theme::Dark).binBar).r) <= 10 &&
                     std::abs(p.g - sdlColor(palette(Theme::Dark).binBar).g) <= 10 &&
                     std::abs(p.b - sdlColor(palette(Theme::Dark).binBar).b) <= 10;
            }
        }
        return n;
    }
    /// Pixels of the orange's hue at any brightness (a glyph's antialiased edges).
    [[nodiscard]] int orangish(const SDL_Rect& r) const {
        int n = 0;
        for (int y = r.y; y < r.y + r.h; ++y) {
            for (int x = r.x; x < r.x + r.w; ++x) {
                const SDL_Color p = pixel(x, y);
                n += p.r >= 60 && p.r > p.g && p.g > p.b;
            }
        }
        return n;
    }
};

TEST_F(BinMarksTest, TheCountedBinsAreMarkedWhereTheyAreWithTheirNumbers) {
    // Bins 0..8 from x = 0 to 9 m below y = 5 m, in a box 11 m wide and 9 m high: the channel
    // from 9 to 11 m is not a bin. 30 px/m, the box's corner at (20, 20).
    camera_.set(30.0, Vec2(-20.0 / 30.0, -20.0 / 30.0));
    BinMarks marks;
    marks.draw(sdl_, *font_, camera_, test::eightRows(), 9.0);
    SDL_RenderPresent(sdl_);
    const auto sx = [](double x) { return static_cast<int>(std::lround(20.0 + 30.0 * x)); };
    // Each edge, from the bins' top line (y 170 px) to the floor (290 px).
    for (int k = 0; k <= 9; ++k) {
        EXPECT_GT(orange({sx(k) - 2, 175, 4, 110}), 100) << "edge " << k;
    }
    // Each bin's number just under the top line, between its edges.
    for (int k = 0; k < 9; ++k) {
        EXPECT_GT(orangish({sx(k) + 3, 172, 24, font_->lineHeight()}), 10) << "bin " << k;
    }
    // Nothing in the channel that is not a bin, nor above the top line.
    EXPECT_EQ(orange({sx(9) + 3, 150, 55, 140}), 0);
    EXPECT_EQ(orange({0, 0, 400, 165}), 0);
}

}  // namespace
}  // namespace psb::app
