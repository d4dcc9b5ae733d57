// The simulation clock: real time times the speed owed in whole frames, the catch-up budget,
// single steps while paused, and the speed's limits.

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <thread>

#include "session/sim_clock.hpp"

namespace psb::app {
namespace {

constexpr double kDt = 0.01;

int frames(SimClock& c, double realSeconds, double now = 0.0, double budgetMs = 1e9) {
    int steps = 0;
    c.run(realSeconds, now, kDt, budgetMs, std::chrono::steady_clock::now(), [&] {
        ++steps;
        return kDt;
    });
    return steps;
}

TEST(SimClock, StepsWholeFramesAndCarriesTheRestOver) {
    SimClock c;
    EXPECT_EQ(frames(c, 0.025), 2);  // 0.005 s left over
    EXPECT_EQ(frames(c, 0.005), 1);  // the rest makes a frame
    EXPECT_EQ(frames(c, 0.004), 0);
    c.restart();  // forgets what was owed
    EXPECT_EQ(frames(c, 0.007), 0);
}

TEST(SimClock, TheSpeedScalesTheTimeOwedWithinItsLimits) {
    SimClock c;
    ASSERT_TRUE(c.setScale(2.0));
    EXPECT_EQ(frames(c, 0.05), 10);
    EXPECT_TRUE(c.setScale(100.0));
    EXPECT_EQ(c.scale(), SimClock::kMaxScale);
    EXPECT_TRUE(c.setScale(0.0));
    EXPECT_EQ(c.scale(), SimClock::kMinScale);
    EXPECT_FALSE(c.setScale(std::numeric_limits<double>::quiet_NaN()));
    EXPECT_EQ(c.scale(), SimClock::kMinScale);
}

TEST(SimClock, PausedItStepsOnlyARequestedSingleStep) {
    SimClock c;
    c.paused = true;
    EXPECT_EQ(frames(c, 1.0), 0);
    c.stepRequested = true;
    EXPECT_EQ(frames(c, 0.0), 1);
    EXPECT_FALSE(c.stepRequested);
    EXPECT_EQ(frames(c, 1.0), 0);
}

TEST(SimClock, TheFirstFrameAfterAPauseOwesOneFrameNotThePause) {
    // An idle paused window draws every quarter second; Space then used to run the world a
    // quarter second in one frame (a jump on screen, a gap in the plots and the time series).
    SimClock c;
    c.paused = true;
    EXPECT_EQ(frames(c, 0.25), 0);
    c.paused = false;
    EXPECT_EQ(frames(c, 0.25), 1);   // 1/60 s owed: one step of 0.01 s, the rest carried
    EXPECT_EQ(frames(c, 0.25), 25);  // running: real time again
}

TEST(SimClock, ABacklogBeyondTheBudgetIsDroppedAndTheReachedSpeedSaysSo) {
    SimClock c;
    int steps = 0;
    // Each step takes 2 ms of wall-clock time; the budget is 5 ms: at most three steps a frame.
    const auto slowStep = [&] {
        ++steps;
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
        return kDt;
    };
    c.run(1.0, 10.0, kDt, 5.0, std::chrono::steady_clock::now(), slowStep);
    EXPECT_GE(steps, 1);
    EXPECT_LE(steps, 4);
    EXPECT_LT(c.reachedScale(), c.scale());  // behind: what was reached (smoothed), not asked
    steps = 0;
    c.run(0.0, 10.5, kDt, 5.0, std::chrono::steady_clock::now(), slowStep);
    EXPECT_EQ(steps, 0) << "the backlog was dropped";
    c.run(0.0, 12.0, kDt, 5.0, std::chrono::steady_clock::now(), slowStep);
    EXPECT_EQ(c.reachedScale(), c.scale()) << "a second later it no longer counts as behind";
}

TEST(SimClock, AStepThatCannotCoverItsFrameEndsTheFrameAndCountsAsBehind) {
    // The exact mode under the app's event budget: a step ends at its first event left, having
    // simulated a quarter of its frame. The frame stops there, and the speed reached says so.
    SimClock c;
    int steps = 0;
    const auto shortStep = [&] {
        ++steps;
        return kDt / 4;
    };
    for (int k = 0; k < 30; ++k) {
        steps = 0;
        c.run(0.05, 10.0 + 0.05 * k, kDt, 1e9, std::chrono::steady_clock::now(), shortStep);
        EXPECT_EQ(steps, 1) << "frame " << k;
    }
    EXPECT_LT(c.reachedScale(), 0.1) << "a quarter of 0.01 s in each 0.05 s frame: x0.05";
    EXPECT_GT(c.reachedScale(), 0.03);
}

}  // namespace
}  // namespace psb::app
