// Chart lines as thick as the UI's scale (render/polyline.hpp): one pixel at 100 %, two at
// 200 %, with no gap at a bend.

#include <gtest/gtest.h>

#include "render/offscreen_test.hpp"
#include "render/polyline.hpp"

namespace psb::app {
namespace {

class PolylineTest : public OffscreenTest {
  protected:
    PolylineTest() : OffscreenTest(64) {}

    /// Lit pixels in column `x` (anything not black).
    int litInColumn(int x) {
        int n = 0;
        for (int y = 0; y < 64; ++y) {
            const SDL_Color c = pixel(x, y);
            n += (c.r | c.g | c.b) != 0;
        }
        return n;
    }
    void drawLine(float width) {
        SDL_SetRenderDrawColor(sdl_, 0, 0, 0, 255);
        SDL_RenderClear(sdl_);
        const SDL_FPoint points[] = {{8.f, 20.5f}, {40.f, 20.5f}, {40.f, 56.f}};
        drawPolyline(sdl_, batch_, points, 3, width, SDL_Color{255, 200, 0, 255});
        SDL_RenderPresent(sdl_);
    }
    GeometryBatch batch_;
};

TEST_F(PolylineTest, WidthFollowsTheUiScale) {
    EXPECT_EQ(chartLineWidth(1.0), 1.f);
    EXPECT_EQ(chartLineWidth(0.75), 1.f) << "never thinner than a pixel";
    EXPECT_EQ(chartLineWidth(2.0), 2.f);
    EXPECT_EQ(chartLineWidth(3.0), 3.f);
    EXPECT_EQ(chartLineWidth(std::numeric_limits<double>::quiet_NaN()), 1.f);
}

TEST_F(PolylineTest, AThickLineCoversAsManyPixelsAcrossAsItsWidth) {
    drawLine(1.f);
    EXPECT_EQ(litInColumn(20), 1);
    drawLine(2.f);
    EXPECT_EQ(litInColumn(20), 2);
    drawLine(4.f);
    EXPECT_EQ(litInColumn(20), 4);
    // The bend is filled: the corner pixel just outside both segments' ends is lit.
    EXPECT_NE(pixel(41, 19).r, 0) << "the square at the joint";
}

}  // namespace
}  // namespace psb::app
