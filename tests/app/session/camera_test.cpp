// The camera is the only place screen and world coordinates meet.

#include <gtest/gtest.h>

#include "session/camera.hpp"

namespace psb::app {
namespace {

constexpr double kTol = 1e-9;  // pixels or metres

TEST(Camera, MapsWorldToScreenLikeTheOriginal) {
    Camera c;
    c.setViewport(700, 700);
    c.set(0.5, Vec2(100.0, 50.0));
    // screen = (world - offset) * zoom
    const Vec2 s = c.worldToScreen(Vec2(300.0, 250.0));
    EXPECT_NEAR(s.x(), 100.0, kTol);
    EXPECT_NEAR(s.y(), 100.0, kTol);
    EXPECT_NEAR(c.toScreen(20.0), 10.0, kTol);
    EXPECT_NEAR(c.toWorld(10.0), 20.0, kTol);
}

TEST(Camera, ScreenToWorldInvertsWorldToScreen) {
    Camera c;
    c.setViewport(800, 600);
    c.set(1.7, Vec2(-33.0, 12.5));
    for (const Vec2& w : {Vec2(0, 0), Vec2(700, 700), Vec2(-5.25, 1e3)}) {
        const Vec2 back = c.screenToWorld(c.worldToScreen(w));
        EXPECT_NEAR(back.x(), w.x(), 1e-9);
        EXPECT_NEAR(back.y(), w.y(), 1e-9);
    }
}

TEST(Camera, ZoomAboutAPointKeepsThatPointStill) {
    Camera c;
    c.setViewport(800, 800);
    c.fit(700.0, 700.0);
    const Vec2 cursor(613.0, 187.0);
    const Vec2 under = c.screenToWorld(cursor);
    const double z0 = c.zoom();
    c.zoomAbout(cursor, 1.15);
    EXPECT_NEAR(c.zoom(), z0 * 1.15, 1e-12);
    const Vec2 after = c.worldToScreen(under);
    EXPECT_NEAR(after.x(), cursor.x(), kTol);
    EXPECT_NEAR(after.y(), cursor.y(), kTol);
}

TEST(Camera, ZoomStopsAtItsLimitsInsteadOfCollapsing) {
    Camera c;
    c.setViewport(800, 800);
    c.fit(700.0, 700.0);
    for (int k = 0; k < 1000; ++k)
        c.zoomAbout(Vec2(400, 400), 1.0 / 1.15);
    EXPECT_DOUBLE_EQ(c.zoom(), c.minZoom());
    EXPECT_GT(c.minZoom(), 0.0);
    for (int k = 0; k < 2000; ++k)
        c.zoomAbout(Vec2(400, 400), 1.15);
    EXPECT_DOUBLE_EQ(c.zoom(), c.maxZoom());
    // Bad factors are ignored.
    const double z = c.zoom();
    c.zoomAbout(Vec2(400, 400), 0.0);
    c.zoomAbout(Vec2(400, 400), std::nan(""));
    EXPECT_DOUBLE_EQ(c.zoom(), z);
}

TEST(Camera, FitCentresTheBoxWithAMargin) {
    Camera c;
    c.setViewport(1000, 600);
    c.fit(700.0, 700.0, 10.0);
    EXPECT_NEAR(c.zoom(), 580.0 / 700.0, 1e-12);  // height limits: 600 - 2 * 10 pixels
    const Vec2 topLeft = c.worldToScreen(Vec2(0, 0));
    const Vec2 bottomRight = c.worldToScreen(Vec2(700, 700));
    EXPECT_NEAR(topLeft.y(), 10.0, kTol);
    EXPECT_NEAR(bottomRight.y(), 590.0, kTol);
    EXPECT_NEAR((topLeft.x() + bottomRight.x()) / 2.0, 500.0, kTol);
}

TEST(Camera, FitKeepsATopInsetFreeForTheHud) {
    Camera c;
    c.setViewport(600, 600);
    c.fit(700.0, 700.0, 10.0, 80.0);
    EXPECT_NEAR(c.zoom(), 500.0 / 700.0, 1e-12);  // 600 - 80 - 2 * 10 pixels of height
    EXPECT_NEAR(c.worldToScreen(Vec2(0, 0)).y(), 90.0, kTol);
    EXPECT_NEAR(c.worldToScreen(Vec2(0, 700)).y(), 590.0, kTol);
    EXPECT_NEAR(c.worldToScreen(Vec2(350, 0)).x(), 300.0, kTol);
}

TEST(Camera, FitKeepsTheHudsBandFreeWhenItsLinesWrapToNearHalfTheWindow) {
    // The ramp at 200 % in 1024 x 768 beside the open control panel: the HUD's lines wrap to
    // a band 340 pixels high, and the messages take 111 at the bottom. The top inset was given
    // up past a third of the window (256 pixels), and the box's top ran under the HUD's lines.
    Camera c;
    c.setViewport(400, 768);
    c.fit(10.0, 10.0, 10.0, 340.0, 111.0);
    const Camera::ScreenBox b = c.boxOnScreen(10.0, 10.0);
    EXPECT_GE(b.topLeft.y(), 340.0 + 10.0 - kTol);
    EXPECT_LE(b.topLeft.y() + b.size.y(), 768.0 - 111.0 - 10.0 + kTol);
}

TEST(Camera, PanMovesTheWorldWithTheDrag) {
    Camera c;
    c.setViewport(800, 800);
    c.set(2.0, Vec2(0, 0));
    const Vec2 w(10.0, 10.0);
    const Vec2 before = c.worldToScreen(w);
    c.panPixels(Vec2(30.0, -20.0));
    const Vec2 after = c.worldToScreen(w);
    EXPECT_NEAR(after.x() - before.x(), 30.0, kTol);
    EXPECT_NEAR(after.y() - before.y(), -20.0, kTol);
}

TEST(Camera, PanningKeepsTheBoxWithinOneViewportOfTheScreen) {
    Camera c;
    c.setViewport(800, 600);
    c.fit(7.0, 7.0);
    for (int k = 0; k < 1000; ++k) {
        c.panPixels(Vec2(-50, 30));
        c.keepNear(7.0, 7.0);
    }
    const Camera::ScreenBox b = c.boxOnScreen(7.0, 7.0);
    EXPECT_GE(b.topLeft.x() + b.size.x(), -800.0 - 1e-9);  // at most a viewport to the left
    EXPECT_LE(b.topLeft.y(), 2.0 * 600.0 + 1e-9);          // and one below
    EXPECT_LT(b.topLeft.x() + b.size.x(), 0.0);            // but off screen: the marker's case
    // Panning back brings it into view again.
    for (int k = 0; k < 40; ++k)
        c.panPixels(Vec2(50, -30));
    const Camera::ScreenBox back = c.boxOnScreen(7.0, 7.0);
    EXPECT_GT(back.topLeft.x() + back.size.x(), 0.0);
}

}  // namespace
}  // namespace psb::app
