#include <gtest/gtest.h>

#include <cmath>

#include <particle_sandbox/time_series.hpp>
#include <particle_sandbox/world.hpp>

namespace psb {
namespace {

ObservablesSample at(double time, std::uint64_t collisions) {
    ObservablesSample s;
    s.time = time;
    s.collisions = collisions;
    return s;
}

TEST(TimeSeries, SampleHoldsTheWorldsTotals) {
    World w;
    w.add({.position = {10.0, 10.0}, .velocity = {3.0, 4.0}, .mass = 2.0});
    w.add({.position = {50.0, 10.0}, .velocity = {-1.0, 0.0}, .mass = 6.0});
    const ObservablesSample s = sampleObservables(w);
    EXPECT_EQ(s.time, 0.0);
    EXPECT_DOUBLE_EQ(s.kineticEnergy, 28.0);  // ½·2·25 + ½·6·1
    EXPECT_EQ(s.momentum, Vec2(0.0, 8.0));
    EXPECT_EQ(s.centreOfMass, Vec2(40.0, 10.0));
    EXPECT_EQ(s.collisions, 0u);
    EXPECT_EQ(s.collisionRate, 0.0);
}

TEST(TimeSeries, RateIsCollisionsPerSimulatedSecondOverTheInterval) {
    TimeSeries series(8);
    ASSERT_TRUE(series.record(at(0.0, 0)));
    ASSERT_TRUE(series.record(at(0.5, 10)));
    ASSERT_TRUE(series.record(at(1.5, 13)));
    EXPECT_TRUE(std::isnan(series[0].collisionRate)) << "no interval yet: no rate, not 0";
    EXPECT_DOUBLE_EQ(series[1].collisionRate, 20.0);  // 10 in 0.5 s
    EXPECT_DOUBLE_EQ(series[2].collisionRate, 3.0);   // 3 in 1 s
}

TEST(TimeSeries, TheRateCountsOverTheLastWindowOfSamples) {
    // Samples every 0.1 s, the rate over the last 5 intervals (0.5 s): one collision at
    // 0.3 s reads as 2 per second in each sample whose window holds it, not as 10 per second
    // in one sample.
    TimeSeries series(64, 5);
    EXPECT_EQ(series.rateSamples(), 5u);
    for (int k = 0; k <= 20; ++k)
        ASSERT_TRUE(series.record(at(0.1 * k, k >= 3 ? 1 : 0)));
    for (std::size_t k = 0; k < 5; ++k)
        EXPECT_TRUE(std::isnan(series[k].collisionRate)) << "no whole window before 0.5 s: " << k;
    for (std::size_t k = 5; k < series.size(); ++k) {
        // The window (t - 0.5 s, t] holds the collision for samples 5 to 7 (t = 0.5 to 0.7).
        EXPECT_NEAR(series[k].collisionRate, k <= 7 ? 2.0 : 0.0, 1e-12) << "t = " << series[k].time;
    }
}

TEST(TimeSeries, AWindowNeverReachesPastTheRingsCapacity) {
    EXPECT_EQ(TimeSeries(4, 10).rateSamples(), 3u);
    EXPECT_EQ(TimeSeries(1, 10).rateSamples(), 1u);
    EXPECT_EQ(TimeSeries(8, 0).rateSamples(), 1u);
    // A full ring still finds its window's start: 3 back from the sample being added.
    TimeSeries series(4, 3);
    for (int k = 0; k < 10; ++k)
        ASSERT_TRUE(series.record(at(k, 4 * static_cast<std::uint64_t>(k))));
    EXPECT_DOUBLE_EQ(series.back().collisionRate, 4.0);
}

TEST(TimeSeries, DroppingTheFutureKeepsThePastAndItsRates) {
    TimeSeries series(16, 2);
    for (int k = 0; k <= 6; ++k)
        ASSERT_TRUE(series.record(at(k, static_cast<std::uint64_t>(k * k))));
    const double rate3 = series[3].collisionRate;
    series.dropAfter(3.5);  // an undo to 3.5 s
    ASSERT_EQ(series.size(), 4u);
    EXPECT_EQ(series.recorded(), 4u);
    EXPECT_EQ(series.back().time, 3.0);
    EXPECT_EQ(series.back().collisionRate, rate3);
    // Carrying on from there: the window reaches back into what was kept.
    ASSERT_TRUE(series.record(at(4.0, 10)));
    EXPECT_DOUBLE_EQ(series.back().collisionRate, (10.0 - 4.0) / 2.0);
}

TEST(TimeSeries, RingKeepsTheNewestSamplesOldestFirst) {
    TimeSeries series(3);
    for (int k = 0; k < 7; ++k)
        ASSERT_TRUE(series.record(at(k, 2 * static_cast<std::uint64_t>(k))));
    ASSERT_EQ(series.size(), 3u);
    EXPECT_EQ(series.capacity(), 3u);
    EXPECT_EQ(series.recorded(), 7u);
    EXPECT_EQ(series[0].time, 4.0);
    EXPECT_EQ(series[1].time, 5.0);
    EXPECT_EQ(series.back().time, 6.0);
    EXPECT_DOUBLE_EQ(series.back().collisionRate, 2.0);
}

TEST(TimeSeries, AnUnchangedClockAppendsNothingButTakesTheStateNow) {
    TimeSeries series(4);
    ASSERT_TRUE(series.record(at(0.0, 0)));
    ASSERT_TRUE(series.record(at(1.0, 5)));
    const double rate = series.back().collisionRate;
    // Paused at t = 1 s, the world edited (a ball given 3.5 J): the instant's sample is the
    // state now, so the plots start from the set-up, not from what it was before it.
    ObservablesSample edited = at(1.0, 5);
    edited.kineticEnergy = 3.5;
    EXPECT_FALSE(series.record(edited));
    EXPECT_EQ(series.size(), 2u);
    EXPECT_EQ(series.back().kineticEnergy, 3.5);
    EXPECT_EQ(series.back().collisionRate, rate) << "the rate of the interval before it, kept";
}

TEST(TimeSeries, AClockGoingBackwardsStartsANewSeries) {
    TimeSeries series(4);
    ASSERT_TRUE(series.record(at(1.0, 5)));
    ASSERT_TRUE(series.record(at(2.0, 9)));
    ASSERT_TRUE(series.record(at(0.0, 0)));  // a new world
    ASSERT_EQ(series.size(), 1u);
    EXPECT_EQ(series[0].time, 0.0);
    EXPECT_TRUE(std::isnan(series[0].collisionRate));
    ASSERT_TRUE(series.record(at(1.0, 0)));
    ASSERT_TRUE(series.record(at(2.0, 0)));
    ASSERT_TRUE(series.record(at(3.0, 0)));  // the counters were reset under the series
    EXPECT_EQ(series.size(), 4u);
}

TEST(TimeSeries, ElasticBoxKeepsItsEnergyAndCountsItsCollisions) {
    // 60 equal discs in a closed box with e = 1: the discrete step conserves energy in every
    // collision and wall rebound, so every sample's KE equals the first to rounding.
    World w(WorldDef{.width = 100.0, .height = 100.0});
    for (int k = 0; k < 60; ++k) {
        const double x = 8.0 + 12.0 * (k % 8), y = 8.0 + 12.0 * (k / 8);
        w.add({.position = {x, y},
               .velocity = {std::cos(1.7 * k) * 20.0, std::sin(2.3 * k) * 20.0},
               .radius = 2.0});
    }
    TimeSeries series(1000);
    ASSERT_TRUE(series.record(w));
    for (int k = 0; k < 500; ++k) {
        w.step(0.01);
        ASSERT_TRUE(series.record(w));
    }
    const double e0 = series[0].kineticEnergy;
    double rateIntegral = 0.0;
    for (std::size_t k = 0; k < series.size(); ++k) {
        EXPECT_NEAR(series[k].kineticEnergy, e0, 1e-12 * e0) << "sample " << k;
        if (k > 0) rateIntegral += series[k].collisionRate * (series[k].time - series[k - 1].time);
    }
    EXPECT_GT(series.back().collisions, 0u);
    EXPECT_EQ(series.back().collisions, w.counters().collisions);
    // Σ rate·Δt gives back the count.
    EXPECT_NEAR(rateIntegral, static_cast<double>(series.back().collisions), 1e-6);
}

TEST(TimeSeries, ExactModeCountsCollisionsToo) {
    World w(WorldDef{.width = 20.0, .height = 10.0}, SolverSettings{.mode = StepMode::Exact});
    w.add({.position = {5.0, 5.0}, .velocity = {1.0, 0.0}, .radius = 1.0});
    w.add({.position = {15.0, 5.0}, .velocity = {-1.0, 0.0}, .radius = 1.0});
    TimeSeries series(16);
    ASSERT_TRUE(series.record(w));
    w.step(5.0);  // they meet at t = 4 s
    ASSERT_TRUE(series.record(w));
    EXPECT_EQ(series.back().collisions, 1u);
    EXPECT_DOUBLE_EQ(series.back().collisionRate, 0.2);
}

}  // namespace
}  // namespace psb
