// The time series the plots (K) show and the Data section exports (monitor.hpp): sampled on
// simulated time, so the same scene gives the same rows at the same instants whatever the
// frames drawn, and a collision rate counted over a stated window of simulated time.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "session/session_fixture.hpp"

namespace psb::app {
namespace {

/// 40 discs in a walled 10 m box, stepped 2 ms at a time: collisions every few steps.
World gas() {
    WorldDef def;
    def.width = def.height = 10.0;
    World w(def);
    for (int k = 0; k < 40; ++k) {
        w.add({.position = Vec2(1.0 + 1.1 * (k % 8), 1.5 + 1.6 * (k / 8)),
               .velocity = Vec2(4.0 * std::cos(1.7 * k), 4.0 * std::sin(2.3 * k)),
               .radius = 0.3});
    }
    return w;
}

/// Two balls heading for each other without walls: 1 kg at 2 m/s from x = 3 and 3 kg at
/// -1 m/s from x = 6, radii 0.5 m; they meet once, at t = 2/3 s.
World twoBalls() {
    WorldDef def;
    def.width = def.height = 10.0;
    def.walls = false;
    World w(def);
    w.add({.position = Vec2(3.0, 5.0), .velocity = Vec2(2.0, 0.0), .mass = 1.0, .radius = 0.5});
    w.add({.position = Vec2(6.0, 5.0), .velocity = Vec2(-1.0, 0.0), .mass = 3.0, .radius = 0.5});
    return w;
}

class SessionTimeSeries : public SessionFixture {
  protected:
    SessionTimeSeries() : SessionFixture("psb-session-series", {}) {}

    /// Runs until `seconds` of simulated time have passed, frame after frame of `frames`
    /// (cycled) real seconds at time speed `scale`, with no wall-clock budget to fall behind.
    static void runFor(Session& s, double seconds, const std::vector<double>& frames,
                       double scale = 1.0) {
        s.apply(cmd::SetTimeScale{scale});
        s.apply(cmd::TogglePause{});
        double now = 0.0;
        for (std::size_t k = 0; s.world().time() < seconds; ++k) {
            const double frame = frames[k % frames.size()];
            now += frame;
            s.update(frame, now, 1e9);
        }
        s.apply(cmd::TogglePause{});
    }
};

TEST_F(SessionTimeSeries, TheRowsAreTheSameWhateverTheFramesAndTheTimeSpeed) {
    const double dt = 0.002;
    std::vector<std::vector<ObservablesSample>> runs;
    struct Frames {
        std::vector<double> lengths;
        double scale;
    };
    // 60 and 30 frames a second, a jittery frame rate, and slow motion at a quarter speed.
    for (const Frames& f : {Frames{{1.0 / 60.0}, 1.0}, Frames{{1.0 / 30.0}, 1.0},
                            Frames{{0.013, 0.041, 0.007, 0.1}, 1.0}, Frames{{1.0 / 60.0}, 0.25}}) {
        Session s = session();
        SceneInfo meta{.name = "gas", .dt = 1.0 / 60.0};
        meta.dt = dt;
        s.setWorld(gas(), meta);
        runFor(s, 2.0, f.lengths, f.scale);
        std::vector<ObservablesSample> rows;
        for (const ObservablesSample& r : s.data().run())
            if (r.time <= 2.0 + 1e-9) rows.push_back(r);
        runs.push_back(rows);
    }
    // A row every 10 steps of 2 ms, t = 0 to 2 s: 101 rows, at 0.02 s apart on any machine.
    const std::vector<ObservablesSample>& first = runs.front();
    ASSERT_EQ(first.size(), 101u);
    for (std::size_t k = 0; k < first.size(); ++k)
        EXPECT_NEAR(first[k].time, 0.02 * static_cast<double>(k), 1e-9) << k;
    EXPECT_GT(first.back().collisions, 20u) << "a gas that collides";
    for (std::size_t r = 1; r < runs.size(); ++r) {
        ASSERT_EQ(runs[r].size(), first.size()) << "run " << r;
        for (std::size_t k = 0; k < first.size(); ++k) {
            const ObservablesSample &a = first[k], &b = runs[r][k];
            EXPECT_EQ(b.time, a.time) << "run " << r << " row " << k;
            EXPECT_EQ(b.kineticEnergy, a.kineticEnergy) << "run " << r << " row " << k;
            EXPECT_EQ(b.momentum, a.momentum) << "run " << r << " row " << k;
            EXPECT_EQ(b.collisions, a.collisions) << "run " << r << " row " << k;
            EXPECT_TRUE(b.collisionRate == a.collisionRate ||
                        (std::isnan(a.collisionRate) && std::isnan(b.collisionRate)))
                << "run " << r << " row " << k;
        }
    }
}

TEST_F(SessionTimeSeries, OneCollisionReadsAsOnePerWindowNotOnePerFrame) {
    Session s = session();
    s.setWorld(twoBalls(),
               SceneInfo{.name = "two balls", .dt = 1.0 / 60.0});  // dt 1/60 s: a sample every step
    EXPECT_NEAR(s.rateWindow(), 0.5, 1e-12);
    runFor(s, 1.5, {1.0 / 60.0});
    const TimeSeries& series = s.series();
    ASSERT_GE(series.size(), 90u);
    ASSERT_EQ(series.back().collisions, 1u);
    std::size_t hit = 0;  // the first sample that counts the collision
    while (series[hit].collisions == 0)
        ++hit;
    EXPECT_NEAR(series[hit].time, 2.0 / 3.0, 1.0 / 60.0 + 1e-9);
    for (std::size_t k = 0; k < series.size(); ++k) {
        const ObservablesSample& p = series[k];
        if (p.time < 0.5 - 1e-9) {
            EXPECT_TRUE(std::isnan(p.collisionRate)) << "no whole window yet at t = " << p.time;
        } else if (k >= hit && p.time < series[hit].time + 0.5 - 1e-9) {
            // 1 collision in 0.5 s, for the half second after it, whatever the frame rate.
            EXPECT_NEAR(p.collisionRate, 2.0, 1e-9) << "t = " << p.time;
        } else {
            EXPECT_EQ(p.collisionRate, 0.0) << "t = " << p.time;
        }
    }
}

TEST_F(SessionTimeSeries, AnUndoTakesTheSeriesBackAndItCarriesOnOnTheSameInstants) {
    Session s = session();
    SceneInfo meta{.name = "gas", .dt = 1.0 / 60.0};
    meta.dt = 0.002;
    s.setWorld(gas(), meta);
    runFor(s, 1.0, {1.0 / 60.0});
    const std::vector<ObservablesSample> before = s.data().run();
    // An edit at about 1 s, undone: the world goes back to its time then, and so do the rows.
    s.apply(cmd::SpawnRandom{});
    runFor(s, 1.5, {1.0 / 60.0});
    s.apply(cmd::Undo{});
    const double t = s.world().time();
    ASSERT_LT(t, 1.5);
    EXPECT_LE(s.series().back().time, t) << "the plots hold no undone future";
    runFor(s, 2.0, {1.0 / 45.0});
    // One history in the table and the plots, on the same 0.02 s grid as before the undo.
    std::vector<ObservablesSample> rows;
    for (const ObservablesSample& r : s.data().run())
        if (r.time <= 2.0 + 1e-9) rows.push_back(r);
    ASSERT_EQ(rows.size(), 101u);
    for (std::size_t k = 0; k < rows.size(); ++k)
        EXPECT_NEAR(rows[k].time, 0.02 * static_cast<double>(k), 1e-9) << k;
    for (std::size_t k = 1; k < s.series().size(); ++k) {
        EXPECT_NEAR(s.series()[k].time - s.series()[k - 1].time, 0.02, 1e-9) << k;
    }
    for (std::size_t k = 0; k < before.size(); ++k)
        EXPECT_EQ(s.data().run()[k].time, before[k].time) << k;
}

}  // namespace
}  // namespace psb::app
