// The stopwatch on simulated time (lab_stopwatch.hpp): alone, and through the session's
// commands, where it stops with the clock, leaves out the time it was stopped, and goes back with
// a step back.

#include <gtest/gtest.h>

#include "session/lab_stopwatch.hpp"
#include "session/session_fixture.hpp"

namespace psb::app {
namespace {

TEST(LabStopwatch, StartStopLapResetOnSimulatedTime) {
    LabStopwatch w;
    EXPECT_FALSE(w.used());
    EXPECT_EQ(stopwatchLine(w, 1.0), "");
    w.start(1.0);
    EXPECT_TRUE(w.running());
    EXPECT_DOUBLE_EQ(w.reading(3.5), 2.5);
    w.lap(2.0);
    EXPECT_EQ(w.laps(), std::vector<double>{1.0});
    w.stop(4.0);
    EXPECT_DOUBLE_EQ(w.reading(10.0), 3.0) << "stopped: frozen";
    w.lap(5.0);
    EXPECT_EQ(w.laps().size(), 1u) << "no lap while stopped";
    w.start(6.0);  // again: the two seconds stopped are left out
    EXPECT_DOUBLE_EQ(w.reading(7.0), 4.0);
    EXPECT_EQ(stopwatchLine(w, 7.0), "Stopwatch 4.000 s | lap 1: 1.000 s");
    // The clock taken back before the start: said, not a negative time.
    EXPECT_TRUE(w.beforeStart(2.5));
    EXPECT_NE(stopwatchLine(w, 2.5).find("time went back 0.500 s before its start"),
              std::string::npos);
    w.reset();
    EXPECT_FALSE(w.used());
    EXPECT_TRUE(w.laps().empty());
}

TEST(LabStopwatch, TimeGoneBackBeforeItsStartNamesShiftUOrOnATouchScreenThePanelsReset) {
    LabStopwatch w;
    w.start(3.0);
    EXPECT_EQ(stopwatchLine(w, 2.5),
              "Stopwatch: time went back 0.500 s before its start (Shift+U resets)");
    EXPECT_EQ(stopwatchLine(w, 2.5, true),
              "Stopwatch: time went back 0.500 s before its start (Time: stopwatch Reset)");
}

class SessionStopwatch : public SessionFixture {
  protected:
    SessionStopwatch() : SessionFixture("psb-session-stopwatch", {}) {}
};

TEST_F(SessionStopwatch, ItRunsWithTheSimulationNotTheWallClock) {
    using A = cmd::Stopwatch::Action;
    Session s = session();
    const double frame = 1.0 / 60.0;
    double now = 0.0;
    const auto frames = [&](int n) {
        for (int k = 0; k < n; ++k) {
            now += frame;
            s.update(frame, now);
        }
    };
    s.apply(cmd::Stopwatch{A::StartStop});
    EXPECT_TRUE(said(s.takeNotices(), "Stopwatch started"));
    if (s.paused()) s.apply(cmd::TogglePause{});
    frames(30);
    const double t1 = s.world().time();
    EXPECT_NEAR(s.stopwatch().reading(t1), t1, 1e-12) << "started at t = 0";
    EXPECT_GT(t1, 0.4);
    s.apply(cmd::TogglePause{});
    frames(30);  // paused: simulated time stands still, and so does the stopwatch
    EXPECT_EQ(s.stopwatch().reading(s.world().time()), t1);
    s.apply(cmd::Stopwatch{A::LapOrReset});  // running: a lap
    ASSERT_EQ(s.stopwatch().laps().size(), 1u);
    EXPECT_TRUE(said(s.takeNotices(), "Lap 1:"));
    s.apply(cmd::StepBack{});  // a frame back: the stopwatch reads a frame less
    EXPECT_NEAR(s.stopwatch().reading(s.world().time()), t1 - s.meta().dt, 1e-9);
    s.apply(cmd::Stopwatch{A::StartStop});
    EXPECT_FALSE(s.stopwatch().running());
    s.apply(cmd::Stopwatch{A::LapOrReset});  // stopped: a reset
    EXPECT_FALSE(s.stopwatch().used());
    s.apply(cmd::Stopwatch{A::StartStop});
    s.apply(cmd::Restart{});
    EXPECT_FALSE(s.stopwatch().used()) << "the experiment again: the stopwatch from zero";
}

}  // namespace
}  // namespace psb::app
