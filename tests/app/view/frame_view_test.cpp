// The frame view's pieces that need no session: the marker pointing to a box off screen.

#include <gtest/gtest.h>

#include "session/camera.hpp"
#include "view/frame_view.hpp"

namespace psb::app {
namespace {

TEST(BoxMarker, ShownOnlyWhenTheBoxIsOffScreenAndPointsToIt) {
    Camera c;
    c.setViewport(800, 600);
    c.fit(7.0, 7.0);
    EXPECT_FALSE(boxMarker(c, 7.0, 7.0).has_value());
    c.panPixels(Vec2(-5000, 0));  // the box far to the left
    const auto m = boxMarker(c, 7.0, 7.0);
    ASSERT_TRUE(m.has_value());
    EXPECT_LT(m->direction.x(), -0.99);
    EXPECT_GE(m->at.x(), 0.0);
    EXPECT_LT(m->at.x(), 50.0);  // at the left edge
    EXPECT_NE(m->label.find("F"), std::string::npos);
}

}  // namespace
}  // namespace psb::app
