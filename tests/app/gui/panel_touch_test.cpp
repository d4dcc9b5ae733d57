// A finger on the control panel (gui/panel_touch.hpp): what ImGui sees, frame by frame, of a
// tap, a drag along the panel (a scroll) and a drag across it (a slider).
#include <gtest/gtest.h>

#include "gui/panel_touch.hpp"

namespace psb::app {
namespace {

constexpr double kFrame = 1.0 / 60.0;

TEST(PanelTouch, NoFingerLeavesThePointerToTheMouse) {
    PanelTouch t;
    EXPECT_FALSE(t.frame(0.0).has_value());
}

TEST(PanelTouch, ATapPressesAndReleasesWhereItCameDownThenLeavesNoPointer) {
    PanelTouch t;
    t.down(ImVec2(100.f, 200.f), 1.0);
    t.move(ImVec2(103.f, 202.f), 1.02);  // a resting finger wobbles
    t.up(ImVec2(103.f, 202.f), 1.05);
    // Lifted before any frame: one frame hovers where it came down, to learn what is there.
    const auto hover = t.frame(1.06 - kFrame);
    ASSERT_TRUE(hover && hover->at);
    EXPECT_FALSE(hover->down);
    EXPECT_FLOAT_EQ(hover->at->x, 100.f);
    t.sliderUnder(false);  // a button
    const auto press = t.frame(1.06);
    ASSERT_TRUE(press && press->at);
    EXPECT_TRUE(press->down);
    EXPECT_FLOAT_EQ(press->at->x, 100.f);
    EXPECT_FLOAT_EQ(press->at->y, 200.f);
    const auto release = t.frame(1.06 + kFrame);
    ASSERT_TRUE(release && release->at);
    EXPECT_FALSE(release->down);
    EXPECT_FLOAT_EQ(release->at->y, 200.f);
    const auto gone = t.frame(1.06 + 2 * kFrame);
    ASSERT_TRUE(gone);
    EXPECT_FALSE(gone->at.has_value()) << "no hover outlives the finger";
    EXPECT_FALSE(gone->down);
    EXPECT_FALSE(t.frame(1.06 + 3 * kFrame).has_value());
}

TEST(PanelTouch, ATapHoldsThePanelStillFromTheFingersDownToItsRelease) {
    // The panel holds its layout while held() (ControlPanel::holdLayout): from the finger's
    // coming down to the frame of the release its tap makes, read after each frame().
    PanelTouch t;
    EXPECT_FALSE(t.held());
    t.down(ImVec2(100.f, 200.f), 1.0);
    EXPECT_TRUE(t.held());
    (void)t.frame(1.0 + kFrame);  // hovered
    EXPECT_TRUE(t.held());
    t.up(ImVec2(100.f, 200.f), 1.05);
    (void)t.frame(1.06);  // pressed
    EXPECT_TRUE(t.held()) << "the press";
    (void)t.frame(1.06 + kFrame);  // released
    EXPECT_TRUE(t.held()) << "the release";
    (void)t.frame(1.06 + 2 * kFrame);  // no pointer
    EXPECT_FALSE(t.held()) << "lifted and done";
}

TEST(PanelTouch, AFingerDraggedUpScrollsByItsPathAndPressesNothing) {
    PanelTouch t;
    t.down(ImVec2(150.f, 600.f), 0.0);
    float scrolled = 0.f;
    double now = 0.0;
    for (int k = 1; k <= 10; ++k) {
        now = k * kFrame;
        t.move(ImVec2(151.f, 600.f - 20.f * k), now);
        const auto p = t.frame(now);
        ASSERT_TRUE(p);
        EXPECT_FALSE(p->down);
        scrolled += p->scroll;
    }
    EXPECT_FLOAT_EQ(scrolled, 200.f) << "the content follows the finger";
    // Lifted while moving: the panel coasts on, less each frame, then stops.
    t.up(ImVec2(151.f, 400.f), now + 0.001);
    float coast = 0.f, last = 1e9f;
    for (int k = 1; k <= 120; ++k) {
        const auto p = t.frame(now + k * kFrame);
        if (!p) break;
        EXPECT_FALSE(p->down);
        EXPECT_FALSE(p->at.has_value());
        EXPECT_LE(p->scroll, last + 1e-3f);
        last = p->scroll;
        coast += p->scroll;
    }
    EXPECT_GT(coast, 20.f);
    EXPECT_LT(coast, 600.f);
    EXPECT_FALSE(t.frame(now + 3.0).has_value());
}

TEST(PanelTouch, AFingerThatStoppedBeforeTheLiftDoesNotCoast) {
    PanelTouch t;
    t.down(ImVec2(150.f, 600.f), 0.0);
    t.move(ImVec2(150.f, 500.f), 0.1);
    (void)t.frame(0.1);
    t.up(ImVec2(150.f, 500.f), 0.5);
    const auto p = t.frame(0.5 + kFrame);
    ASSERT_TRUE(p);
    EXPECT_FLOAT_EQ(p->scroll, 0.f);
}

TEST(PanelTouch, ADragAcrossPressesWhereItCameDownThenFollows) {
    PanelTouch t;
    t.down(ImVec2(100.f, 300.f), 0.0);
    t.move(ImVec2(115.f, 302.f), kFrame);
    const auto first = t.frame(kFrame);
    ASSERT_TRUE(first && first->at);
    EXPECT_TRUE(first->down);
    EXPECT_FLOAT_EQ(first->at->x, 100.f) << "the press lands on the slider's grab";
    t.move(ImVec2(160.f, 303.f), 2 * kFrame);
    const auto second = t.frame(2 * kFrame);
    ASSERT_TRUE(second && second->at);
    EXPECT_TRUE(second->down);
    EXPECT_FLOAT_EQ(second->at->x, 160.f);
    EXPECT_FLOAT_EQ(second->scroll, 0.f);
    t.up(ImVec2(160.f, 303.f), 3 * kFrame);
    const auto release = t.frame(3 * kFrame);
    ASSERT_TRUE(release && release->at);
    EXPECT_FALSE(release->down);
    EXPECT_FLOAT_EQ(release->at->x, 160.f);
}

TEST(PanelTouch, AFingerHeldStillPressesAfterAWhile) {
    PanelTouch t;
    t.down(ImVec2(100.f, 300.f), 0.0);
    const auto waiting = t.frame(0.1);
    ASSERT_TRUE(waiting);
    EXPECT_FALSE(waiting->down);
    const auto held = t.frame(PanelTouch::kHoldSeconds + 0.01);
    ASSERT_TRUE(held);
    EXPECT_TRUE(held->down);
    // Moving up now drags what it pressed: no scroll.
    t.move(ImVec2(100.f, 250.f), PanelTouch::kHoldSeconds + 0.05);
    const auto dragged = t.frame(PanelTouch::kHoldSeconds + 0.05);
    ASSERT_TRUE(dragged);
    EXPECT_TRUE(dragged->down);
    EXPECT_FLOAT_EQ(dragged->scroll, 0.f);
}

TEST(PanelTouch, ATouchStopsACoastingScroll) {
    PanelTouch t;
    t.down(ImVec2(150.f, 600.f), 0.0);
    for (int k = 1; k <= 5; ++k) {
        t.move(ImVec2(150.f, 600.f - 40.f * k), k * kFrame);
        (void)t.frame(k * kFrame);
    }
    t.up(ImVec2(150.f, 400.f), 5 * kFrame);
    const auto coasting = t.frame(6 * kFrame);
    ASSERT_TRUE(coasting);
    EXPECT_GT(coasting->scroll, 0.f);
    t.down(ImVec2(150.f, 400.f), 7 * kFrame);
    const auto stopped = t.frame(7 * kFrame);
    ASSERT_TRUE(stopped);
    EXPECT_FLOAT_EQ(stopped->scroll, 0.f);
    EXPECT_FALSE(stopped->down);
}

TEST(PanelTouch, ATapOnASliderPressesNothing) {
    PanelTouch t;
    t.down(ImVec2(100.f, 300.f), 0.0);
    const auto hover = t.frame(kFrame);
    ASSERT_TRUE(hover && hover->at);
    EXPECT_FALSE(hover->down);
    t.sliderUnder(true);  // that frame drew a slider under the finger
    t.up(ImVec2(101.f, 300.f), 0.08);
    for (int k = 2; k < 6; ++k) {
        const auto p = t.frame(k * kFrame);
        if (!p) break;
        EXPECT_FALSE(p->down) << "frame " << k << ": ImGui would set the value where it came down";
        EXPECT_FALSE(p->at.has_value()) << "frame " << k;
    }
    EXPECT_FALSE(t.frame(6 * kFrame).has_value());
}

TEST(PanelTouch, AFingerRestingOnASliderThenMovingUpScrollsAndPressesNothing) {
    PanelTouch t;
    t.down(ImVec2(100.f, 300.f), 0.0);
    (void)t.frame(kFrame);
    t.sliderUnder(true);
    // Held longer than a long press: over a slider that presses nothing.
    const auto held = t.frame(PanelTouch::kHoldSeconds + 0.1);
    ASSERT_TRUE(held);
    EXPECT_FALSE(held->down);
    float scrolled = 0.f;
    for (int k = 1; k <= 8; ++k) {
        const double now = PanelTouch::kHoldSeconds + 0.1 + k * kFrame;
        t.move(ImVec2(102.f, 300.f - 25.f * k), now);
        const auto p = t.frame(now);
        ASSERT_TRUE(p);
        EXPECT_FALSE(p->down);
        scrolled += p->scroll;
    }
    EXPECT_FLOAT_EQ(scrolled, 200.f);
}

TEST(PanelTouch, ADragAcrossASliderStillPressesIt) {
    PanelTouch t;
    t.down(ImVec2(100.f, 300.f), 0.0);
    (void)t.frame(kFrame);
    t.sliderUnder(true);
    t.move(ImVec2(130.f, 301.f), 2 * kFrame);
    const auto p = t.frame(2 * kFrame);
    ASSERT_TRUE(p && p->at);
    EXPECT_TRUE(p->down);
}

TEST(PanelTouch, ASecondFingerEndsTheGestureWithoutAPress) {
    PanelTouch t;
    t.down(ImVec2(100.f, 300.f), 0.0);
    (void)t.frame(kFrame);
    t.sliderUnder(false);
    t.cancel();  // a second finger came down
    EXPECT_TRUE(t.fingerDown()) << "the first finger's events stay the gesture's";
    t.move(ImVec2(160.f, 240.f), 2 * kFrame);  // across and up: neither a drag nor a scroll
    const auto p = t.frame(2 * kFrame);
    ASSERT_TRUE(p);
    EXPECT_FALSE(p->down);
    EXPECT_FALSE(p->at.has_value());
    EXPECT_FLOAT_EQ(p->scroll, 0.f);
    t.up(ImVec2(160.f, 240.f), 3 * kFrame);
    EXPECT_FALSE(t.fingerDown());
    const auto lifted = t.frame(3 * kFrame);
    ASSERT_TRUE(lifted);
    EXPECT_FALSE(lifted->down);
    EXPECT_FALSE(t.frame(4 * kFrame).has_value());
}

}  // namespace
}  // namespace psb::app
