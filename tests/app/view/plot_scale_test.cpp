// The plots' words (plot_scale.hpp): the collision rate's title names its window.

#include <gtest/gtest.h>

#include "session/monitor.hpp"
#include "view/plot_scale.hpp"

namespace psb::app {
namespace {

TEST(PlotScale, TheCollisionRatesTitleNamesItsWindowOfSimulatedTime) {
    EXPECT_EQ(collisionRateTitle(Monitor::rateWindow(1.0 / 60.0)), "collisions/s, last 0.5 s");
    EXPECT_EQ(collisionRateTitle(Monitor::rateWindow(0.002)), "collisions/s, last 0.5 s");
    // A dt that does not divide the window: two figures of what it is (26 samples of 0.019 s).
    EXPECT_NEAR(Monitor::rateWindow(0.019), 0.494, 1e-12);
    EXPECT_EQ(collisionRateTitle(Monitor::rateWindow(0.019)), "collisions/s, last 0.49 s");
}

}  // namespace
}  // namespace psb::app
