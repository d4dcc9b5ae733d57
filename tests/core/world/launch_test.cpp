// The launch velocity the app uses: the recent part of a drag, over a time window.

#include <gtest/gtest.h>

#include <limits>
#include <vector>

#include <particle_sandbox/launch.hpp>

namespace psb {
namespace {

TEST(LaunchVelocity, SteadyDragGivesItsVelocity) {
    std::vector<TrajectorySample> s;
    for (int k = 0; k <= 30; ++k)
        s.push_back({k / 60.0, Vec2(100.0 + 2.0 * k, 50.0 - 1.0 * k)});
    const Vec2 v = launchVelocity(s);
    EXPECT_NEAR(v.x(), 120.0, 1e-9);
    EXPECT_NEAR(v.y(), -60.0, 1e-9);
}

TEST(LaunchVelocity, OnlyTheRecentWindowCounts) {
    std::vector<TrajectorySample> s;
    // Half a second dragging right, then 0.2 s dragging down.
    for (int k = 0; k <= 50; ++k)
        s.push_back({k * 0.01, Vec2(3.0 * k, 0.0)});
    for (int k = 1; k <= 20; ++k)
        s.push_back({0.5 + k * 0.01, Vec2(150.0, 2.0 * k)});
    const Vec2 v = launchVelocity(s, {.window = 0.1});
    EXPECT_NEAR(v.x(), 0.0, 1e-9);
    EXPECT_NEAR(v.y(), 200.0, 1e-9);
}

TEST(LaunchVelocity, PauseBeforeReleaseLaunchesAtRest) {
    std::vector<TrajectorySample> s;
    for (int k = 0; k <= 20; ++k)
        s.push_back({k * 0.01, Vec2(5.0 * k, 0.0)});
    // Held still for 0.3 s: the last 100 ms show no movement.
    for (int k = 1; k <= 30; ++k)
        s.push_back({0.2 + k * 0.01, Vec2(100.0, 0.0)});
    EXPECT_EQ(launchVelocity(s), Vec2::Zero());
}

// A page drawing slow frames delivers one move per frame (here every 150 ms, longer than the
// window), and the release comes at the last move's spot: the drag was still a fling.
TEST(LaunchVelocity, SparseReportsWidenTheWindowSoAFlingIsNotReadAsAStop) {
    std::vector<TrajectorySample> s;
    for (int k = 0; k <= 4; ++k)
        s.push_back({k * 0.15, Vec2(30.0 * k, 0.0)});
    s.push_back({0.601, Vec2(120.0, 0.0)});  // the release, 1 ms after the last move
    const Vec2 v = launchVelocity(s, {.window = 0.1});
    EXPECT_NEAR(v.x(), 30.0 / 0.151, 1e-9);
    EXPECT_EQ(v.y(), 0.0);
}

TEST(LaunchVelocity, SparseReportsThenAStopLongerThanTheirSpacingIsAtRest) {
    std::vector<TrajectorySample> s;
    for (int k = 0; k <= 4; ++k)
        s.push_back({k * 0.15, Vec2(30.0 * k, 0.0)});
    s.push_back({0.6 + 0.3, Vec2(120.0, 0.0)});  // released 0.3 s after the last move
    EXPECT_EQ(launchVelocity(s, {.window = 0.1}), Vec2::Zero());
}

TEST(LaunchVelocity, AFlingCoalescedIntoOneMoveKeepsItsSpeed) {
    // A slow page delivers a quick fling's moves as one, 0.11 s after the press: that gap is a
    // report of motion, and the window widens to take the press in.
    const std::vector<TrajectorySample> s{{0.0, {0.0, 0.0}}, {0.11, {11.0, 0.0}}};
    EXPECT_NEAR(launchVelocity(s, {.window = 0.1}).x(), 100.0, 1e-9);
    EXPECT_NEAR(launchWindow(s, {.window = 0.1}), 0.165, 1e-12);
    // Released there a moment later: that pause is no report of motion, and is not counted.
    const std::vector<TrajectorySample> r{
        {0.0, {0.0, 0.0}}, {0.11, {11.0, 0.0}}, {0.3, {11.0, 0.0}}};
    EXPECT_EQ(launchVelocity(r, {.window = 0.1}), Vec2::Zero());
}

TEST(LaunchVelocity, TheWindowIsTheSettingWidenedToTheReportsSpacing) {
    // Reports every 10 ms: the setting's 0.1 s. Every 0.15 s: 1.5 spacings, 0.225 s. A second
    // apart: held to four times the setting.
    std::vector<TrajectorySample> dense, sparse, rare;
    for (int k = 0; k <= 4; ++k) {
        dense.push_back({k * 0.01, Vec2(k, 0.0)});
        sparse.push_back({k * 0.15, Vec2(k, 0.0)});
        rare.push_back({k * 1.0, Vec2(k, 0.0)});
    }
    EXPECT_DOUBLE_EQ(launchWindow(dense, {.window = 0.1}), 0.1);
    EXPECT_NEAR(launchWindow(sparse, {.window = 0.1}), 0.225, 1e-12);
    EXPECT_DOUBLE_EQ(launchWindow(rare, {.window = 0.1}), 0.4);
    EXPECT_DOUBLE_EQ(launchWindow({}, {.window = 0.1}), 0.1);
}

TEST(LaunchVelocity, TheWidenedWindowStopsAtFourTimesTheSetting) {
    // Reports a second apart: the window would be 1.5 s, but stays at 0.4 s, so a release
    // 0.5 s after the last move is a hand at rest.
    const std::vector<TrajectorySample> s{
        {0.0, {0.0, 0.0}}, {1.0, {10.0, 0.0}}, {2.0, {20.0, 0.0}}, {2.5, {20.0, 0.0}}};
    EXPECT_EQ(launchVelocity(s, {.window = 0.1}), Vec2::Zero());
    // Reports 0.3 s apart (a window of 0.45 s, held to 0.4 s), released 50 ms after the last:
    // the move before it is 0.35 s back, inside.
    const std::vector<TrajectorySample> t{
        {0.0, {0.0, 0.0}}, {0.3, {10.0, 0.0}}, {0.6, {20.0, 0.0}}, {0.65, {20.0, 0.0}}};
    EXPECT_NEAR(launchVelocity(t, {.window = 0.1}).x(), 10.0 / 0.35, 1e-9);
}

TEST(LaunchVelocity, ShortJitterBelowMinDistanceIsAtRest) {
    const std::vector<TrajectorySample> s{{0.0, {10.0, 10.0}}, {0.05, {10.4, 10.2}}};
    EXPECT_EQ(launchVelocity(s, {.minDistance = 1.0}), Vec2::Zero());
    EXPECT_NE(launchVelocity(s, {.minDistance = 0.1}), Vec2::Zero());
}

TEST(LaunchVelocity, DegenerateInputsGiveZeroOrAreSkipped) {
    constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(launchVelocity({}), Vec2::Zero());
    const std::vector<TrajectorySample> one{{1.0, {3.0, 3.0}}};
    EXPECT_EQ(launchVelocity(one), Vec2::Zero());
    const std::vector<TrajectorySample> sameTime{{1.0, {3.0, 3.0}}, {1.0, {9.0, 3.0}}};
    EXPECT_EQ(launchVelocity(sameTime), Vec2::Zero());
    const std::vector<TrajectorySample> withNaN{
        {0.0, {0.0, 0.0}}, {0.05, {kNaN, 1.0}}, {0.1, {10.0, 0.0}}, {kNaN, {1.0, 1.0}}};
    EXPECT_NEAR(launchVelocity(withNaN).x(), 100.0, 1e-9);
}

TEST(LaunchVelocity, MaxSpeedClamps) {
    const std::vector<TrajectorySample> s{{0.0, {0.0, 0.0}}, {0.01, {30.0, 40.0}}};
    const Vec2 v = launchVelocity(s, {.maxSpeed = 100.0});
    EXPECT_NEAR(v.norm(), 100.0, 1e-9);
    EXPECT_NEAR(v.x() / v.y(), 0.75, 1e-12);
}

}  // namespace
}  // namespace psb
