// The momentum view's legend (view/momentum_view.hpp): the total momentum's signed components as
// every other reading writes them, in the axes the user reads, and when its arrow is capped.

#include <gtest/gtest.h>

#include "view/momentum_view.hpp"

namespace psb::app {
namespace {

World twoBalls(double vy) {
    WorldDef def;
    def.width = 10.0;
    def.height = 4.0;
    def.gravity = Vec2::Zero();
    World w(def);
    w.add({.position = Vec2(2.0, 2.0), .velocity = Vec2(2.0, vy), .mass = 1.0, .radius = 0.4});
    w.add({.position = Vec2(7.0, 2.0), .velocity = Vec2(-1.0, 0.0), .mass = 3.0, .radius = 0.6});
    return w;
}

TEST(MomentumLegend, SignedComponentsInTheUsersAxes) {
    const World w = twoBalls(0.5);  // 0.5 m/s down the screen
    const ObservablesSample now = sampleObservables(w);
    const auto down = momentumLegend(w, now, 0.01);
    ASSERT_EQ(down.size(), 3u);
    EXPECT_EQ(down[0], "P = (-1.00, 0.500) kg m/s");
    EXPECT_EQ(momentumLegend(w, now, 0.01, Axes{true, 4.0})[0], "P = (-1.00, -0.500) kg m/s")
        << "y up: moving down the screen is negative";
    EXPECT_EQ(down[1], "m v per particle");
}

TEST(MomentumLegend, SaysWhenTheArrowIsCapped) {
    const World w = twoBalls(0.0);
    const ObservablesSample now = sampleObservables(w);
    // A tenth of the smaller side at most (4 m x 0.4 = 1.6 m): 100 s of motion is far longer.
    EXPECT_NE(momentumLegend(w, now, 100.0)[0].find("(arrow capped)"), std::string::npos);
    EXPECT_EQ(momentumLegend(w, now, 0.01)[0].find("(arrow capped)"), std::string::npos);
}

}  // namespace
}  // namespace psb::app
