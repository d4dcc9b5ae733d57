// Arrows kept inside the box: cut at the wall they would pass, never shortened to fit.

#include "view/arrow_clip.hpp"

#include <gtest/gtest.h>

namespace psb::app {
namespace {

const Camera::ScreenBox kBox{Vec2(100.0, 50.0), Vec2(400.0, 200.0)};  // x 100-500, y 50-250

TEST(ArrowClip, AnArrowInsideTheBoxIsDrawnAsItIs) {
    const ClippedArrow a = clipArrow(Vec2(200.0, 100.0), Vec2(300.0, 180.0), kBox);
    EXPECT_FALSE(a.cut);
    EXPECT_EQ(a.tip, Vec2(300.0, 180.0));
}

TEST(ArrowClip, PastTheLeftWallItEndsOnTheWallCutAlongItsOwnLine) {
    // Lesson 1: the 1 kg ball by the left wall, its arrow 30 pixels past it.
    const ClippedArrow a = clipArrow(Vec2(130.0, 150.0), Vec2(70.0, 150.0), kBox);
    EXPECT_TRUE(a.cut);
    EXPECT_DOUBLE_EQ(a.tip.x(), 100.0);
    EXPECT_DOUBLE_EQ(a.tip.y(), 150.0);
}

TEST(ArrowClip, AnObliqueArrowThroughTheTopWallStopsWhereItMeetsIt) {
    // The default scene: an arrow ran through the top wall under the HUD.
    const Vec2 from(300.0, 70.0), tip(340.0, 30.0);
    const ClippedArrow a = clipArrow(from, tip, kBox);
    EXPECT_TRUE(a.cut);
    EXPECT_DOUBLE_EQ(a.tip.y(), 50.0);
    EXPECT_DOUBLE_EQ(a.tip.x(), 320.0) << "along the arrow's own direction, not bent";
    // Through a corner: the first wall it meets.
    const ClippedArrow corner = clipArrow(Vec2(480.0, 60.0), Vec2(540.0, 0.0), kBox);
    EXPECT_TRUE(corner.cut);
    EXPECT_DOUBLE_EQ(corner.tip.x(), 490.0);
    EXPECT_DOUBLE_EQ(corner.tip.y(), 50.0);
}

TEST(ArrowClip, TheScaleStaysHonestTheCutArrowIsTheUncutOnesFirstPart) {
    // The drawn part is as long as the arrow's first stretch to the wall: the scale is not
    // changed for the one arrow, and a longer arrow in the same direction is cut at the same
    // place.
    const Vec2 from(450.0, 150.0);
    const ClippedArrow a = clipArrow(from, Vec2(520.0, 150.0), kBox);
    const ClippedArrow b = clipArrow(from, Vec2(900.0, 150.0), kBox);
    EXPECT_EQ(a.tip, b.tip);
    EXPECT_DOUBLE_EQ((a.tip - from).norm(), 50.0);
}

TEST(ArrowClip, AnArrowFromOutsideTheBoxIsLeftAlone) {
    const ClippedArrow a = clipArrow(Vec2(50.0, 150.0), Vec2(10.0, 150.0), kBox);
    EXPECT_FALSE(a.cut);
    EXPECT_EQ(a.tip, Vec2(10.0, 150.0));
}

}  // namespace
}  // namespace psb::app
