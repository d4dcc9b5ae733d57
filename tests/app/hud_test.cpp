#include <gtest/gtest.h>

#include <algorithm>

#include "hud.hpp"

namespace psb::app {
namespace {

TEST(Hud, TitleShowsTheCountAndPaused) {
    EXPECT_EQ(windowTitle(6, false), "Particle Sandbox - 6 particles");
    EXPECT_EQ(windowTitle(1, true), "Particle Sandbox - 1 particle - PAUSED");
    EXPECT_EQ(windowTitle(2, false, "Gas"), "Particle Sandbox - 2 particles - Gas");
}

TEST(Hud, LinesShowFpsTimeCountEnergyAndMomentumWithUnits) {
    HudData d;
    d.fps = 59.6;
    d.simTime = 12.345;
    d.particles = 42;
    d.kineticEnergy = 1234.5;
    d.momentum = Vec2(3.0, -4.0);
    d.paused = true;
    const auto lines = hudLines(d);
    const auto has = [&](const std::string& s) {
        return std::any_of(lines.begin(), lines.end(),
                           [&](const std::string& l) { return l.find(s) != std::string::npos; });
    };
    EXPECT_TRUE(has("FPS 60"));
    EXPECT_TRUE(has("Time 12.35 s"));
    EXPECT_TRUE(has("PAUSED"));
    EXPECT_TRUE(has("42 particles"));
    EXPECT_TRUE(has("KE 1234 J"));
    EXPECT_TRUE(has("p [3, -4] kg m/s"));
}

TEST(Hud, HelpListsEveryControl) {
    const auto lines = helpLines();
    EXPECT_EQ(lines.size(), controls().size() + 2);
    for (const char* key : {"M", "S", "A", "Space", "Wheel", "Ctrl+S", "Esc", "H"}) {
        EXPECT_TRUE(std::any_of(controls().begin(), controls().end(), [&](const auto& c) {
            return c.first == key;
        })) << key;
    }
}

}  // namespace
}  // namespace psb::app
