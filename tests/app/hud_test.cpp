#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

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
    // Paused, the loop sleeps until input: a frame rate would count redraws, not speed.
    EXPECT_FALSE(has("FPS"));
    EXPECT_TRUE(has("Paused: redrawn on input"));
    EXPECT_TRUE(has("Time 12.35 s"));
    EXPECT_TRUE(has("PAUSED"));
    EXPECT_TRUE(has("42 particles"));
    EXPECT_TRUE(has("KE 1234 J"));
    EXPECT_TRUE(has("p [3, -4] kg m/s"));
    d.paused = false;
    const auto running = hudLines(d);
    EXPECT_EQ(running.front().rfind("FPS 60 |", 0), 0u) << running.front();
}

TEST(Hud, ATimeSpeedTheStepsCannotReachShowsTheSpeedReached) {
    HudData d;
    d.timeScale = 8.0;
    d.reachedTimeScale = 3.1;
    EXPECT_NE(hudLines(d)[1].find("x3.1 of x8 asked"), std::string::npos) << hudLines(d)[1];
    d.reachedTimeScale = 7.9;  // within 5 %: what was asked is what is seen
    EXPECT_NE(hudLines(d)[1].find("x8 |"), std::string::npos) << hudLines(d)[1];
    EXPECT_EQ(hudLines(d)[1].find("asked"), std::string::npos);
}

TEST(Hud, TheArrowScaleIsShownWhileArrowsAreOn) {
    HudData d;
    d.arrowSeconds = 0.25;
    EXPECT_NE(hudLines(d).back().find("arrow: 0.25 s of motion"), std::string::npos);
    d.arrowSeconds = 0.0;
    EXPECT_EQ(hudLines(d).back().find("arrow"), std::string::npos);
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

bool anyContains(const std::vector<std::string>& lines, const std::string& s) {
    return std::any_of(lines.begin(), lines.end(),
                       [&](const std::string& l) { return l.find(s) != std::string::npos; });
}

TEST(Hud, LinesShowModeBroadphaseThreadsOverlapAndDrift) {
    HudData d;
    d.mode = "substep x4";
    d.broadphase = "grid";
    d.threads = 2;
    d.maxOverlap = 0.0123;
    d.keDrift = -2.5e-4;
    const auto lines = hudLines(d);
    EXPECT_TRUE(anyContains(lines, "Mode substep x4 | grid | 2 threads"));
    EXPECT_TRUE(anyContains(lines, "Overlap max 0.0123 m"));
    EXPECT_TRUE(anyContains(lines, "KE drift -2.50e-04 since last action"));
    d.keDrift = std::numeric_limits<double>::quiet_NaN();
    EXPECT_TRUE(anyContains(hudLines(d), "KE drift n/a"));
    d.driftName = "KE+PE drift";  // with gravity on, what is conserved
    d.keDrift = 1e-12;
    EXPECT_TRUE(anyContains(hudLines(d), "KE+PE drift +1.00e-12 since last action"));
}

TEST(Hud, ProfileListsEveryStageAndTheFrameTimes) {
    ProfileData d;
    for (const char* stage :
         {"reorder", "gravity", "move", "find pairs", "resolve", "separate", "walls"})
        d.profile.stage(stage);
    d.profile.stage("gravity") = 0.125;
    d.profile.stage("find pairs") = 1.5;
    d.profile.stage("reorder") = 0.25;
    d.profile.total = 3.0;
    d.profile.pairs = 1234;
    d.frameStepMs = 6.0;
    d.frameDrawMs = 4.5;
    const auto lines = profileLines(d);
    for (const char* stage : {"gravity", "move", "find pairs", "resolve", "separate", "walls",
                              "reorder", "total", "frame: step", "frame: draw"}) {
        EXPECT_TRUE(anyContains(lines, stage)) << stage;
    }
    EXPECT_TRUE(anyContains(lines, "1.500"));
    EXPECT_TRUE(anyContains(lines, "1234"));
    EXPECT_TRUE(anyContains(lines, "4.500"));
}

TEST(Hud, ProfileInExactModeNamesTheEventStages) {
    ProfileData d;
    d.mode = StepMode::Exact;
    d.eventsPerStep = 420;
    for (const char* stage : {"rebuild", "events", "sync"})
        d.profile.stage(stage);
    const auto lines = profileLines(d);
    EXPECT_TRUE(anyContains(lines, "rebuild"));
    EXPECT_TRUE(anyContains(lines, "events"));
    EXPECT_TRUE(anyContains(lines, "sync"));
    EXPECT_TRUE(anyContains(lines, "events per step"));
    EXPECT_TRUE(anyContains(lines, "420"));
    EXPECT_FALSE(anyContains(lines, "separate"));
}

TEST(Hud, HelpListsTheModeAndProfileKeys) {
    for (const char* key : {"T", "O / F3"}) {
        EXPECT_TRUE(std::any_of(controls().begin(), controls().end(), [&](const auto& c) {
            return c.first == key;
        })) << key;
    }
}

}  // namespace
}  // namespace psb::app
