// The gas instruments: the pressure measured on the walls against the hard-disk equation of
// state, in the gas preset; kT from the kinetic energy; the window starting over when the world
// goes back; the numbers the core's (what particle-sim --observables reports for the same run).

#include "session/gas_gauges.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include <particle_sandbox/scene.hpp>

#include "session/test_assets.hpp"

namespace psb::app {
namespace {

/// Runs `world` for `seconds` in frames of `dt`, as the session's monitor samples it.
void run(World& world, GasGauges& gauges, double seconds, double dt) {
    const int frames = static_cast<int>(std::lround(seconds / dt));
    for (int f = 0; f < frames; ++f) {
        world.resetCounters();
        world.step(dt);
        gauges.sample(world);
    }
}

World gasPreset(StepMode mode) {
    World w = makeWorld(loadScene(testAsset("scenes/04-gas-in-a-box.json")));
    SolverSettings s = w.solver();
    s.mode = mode;
    w.setSolver(s);
    return w;
}

TEST(GasGauges, TheGasPresetsMeasuredPressureIsTheHardDiskOneNotTheIdealGas) {
    // 4000 discs of 2.5 cm in 7 m x 7 m cover 16 % of the box: Henderson's equation puts the
    // pressure 42 % above the ideal gas's. The exact mode's wall impulse must find it.
    World w = gasPreset(StepMode::Exact);
    GasGauges g;
    run(w, g, 1.0, 0.01);  // settle
    g.restart();
    run(w, g, GasGauges::kWindow, 0.01);
    const GasReading r = g.reading(w);
    ASSERT_TRUE(r.pressure.has_value());
    EXPECT_NEAR(r.window, GasGauges::kWindow, 0.011);
    EXPECT_NEAR(r.coverage, 4000 * M_PI * 0.025 * 0.025 / 49.0, 1e-12);
    EXPECT_NEAR(r.reach, 6.95 * 6.95, 1e-9);
    EXPECT_FALSE(r.periodic);
    EXPECT_NEAR(r.kT, 0.1, 0.01);  // the preset's temperature
    EXPECT_NEAR(r.hardDiskPressure / r.idealPressure, 1.423, 0.001);
    EXPECT_GT(r.pressureError, 0.0);
    EXPECT_LT(r.pressureError, 0.05 * *r.pressure);
    // Within three standard errors and 2 % (Henderson's 1 %, a finite box's); far from the
    // ideal gas.
    EXPECT_NEAR(*r.pressure, r.hardDiskPressure, 3.0 * r.pressureError + 0.02 * r.hardDiskPressure)
        << "measured " << *r.pressure << " ± " << r.pressureError << ", ideal " << r.idealPressure;
    EXPECT_GT(*r.pressure, 1.2 * r.idealPressure);
    // Collisions counted: the pair rate is of the order of N times the collision frequency.
    EXPECT_GT(r.pairRate, 1000.0);
    EXPECT_GT(r.wallRate, 100.0);
}

TEST(GasGauges, NothingMeasuredBeforeHalfASecondAndTheWindowIsTheLastFourToFiveSeconds) {
    World w = gasPreset(StepMode::Discrete);
    GasGauges g;
    run(w, g, 0.3, 0.01);
    EXPECT_FALSE(g.reading(w).pressure.has_value());
    run(w, g, 0.3, 0.01);
    EXPECT_TRUE(g.reading(w).pressure.has_value());
    // The core's windows are opened and closed, not slid: the gauges open one every 1.25 s and
    // read the oldest, so once five seconds have run the window spans 3.75 to 5 s (it used to
    // be 5 s exactly, a window of the gauges' own).
    for (int k = 0; k < 700; ++k) {
        run(w, g, 0.01, 0.01);
        const double span = g.reading(w).window;
        ASSERT_LE(span, GasGauges::kWindow + 1e-9) << "at t = " << w.time();
        if (w.time() > GasGauges::kWindow) {
            ASSERT_GE(span,
                      GasGauges::kWindow * (GasGauges::kStagger - 1) / GasGauges::kStagger - 0.011)
                << "at t = " << w.time();
        }
    }
}

TEST(GasGauges, PausedFramesAddNothingAndTimeGoingBackStartsOver) {
    World w = gasPreset(StepMode::Discrete);
    GasGauges g;
    run(w, g, 1.0, 0.01);
    const double before = *g.reading(w).pressure;
    for (int i = 0; i < 50; ++i) {
        w.resetCounters();
        g.sample(w);  // paused: the same time
    }
    EXPECT_DOUBLE_EQ(*g.reading(w).pressure, before);
    World earlier = gasPreset(StepMode::Discrete);  // t = 0 again: an undo, a new scene
    earlier.resetCounters();
    g.sample(earlier);
    EXPECT_FALSE(g.reading(earlier).pressure.has_value());
}

TEST(GasGauges, ParticlesAddedOrRemovedWithoutAnEditStartTheWindowOver) {
    // A dropper's ball, or a particle gone: the core's window counts the particles it opened
    // on, so the gauges open new ones rather than divide by the wrong N.
    World w = gasPreset(StepMode::Discrete);
    GasGauges g;
    run(w, g, 1.0, 0.01);
    ASSERT_TRUE(g.reading(w).pressure.has_value());
    w.remove(w.ids()[0]);
    run(w, g, 0.1, 0.01);
    EXPECT_FALSE(g.reading(w).pressure.has_value());
    EXPECT_EQ(g.reading(w).particles, 3999u);
}

TEST(GasGauges, TheWorldCountsItsVirialOnlyWhileTheGaugesMeasureIt) {
    World w = gasPreset(StepMode::Discrete);
    GasGauges g;
    EXPECT_FALSE(w.measuringVirial());
    run(w, g, 0.1, 0.01);
    EXPECT_TRUE(w.measuringVirial());  // a core window is open
    // Gravity (an edit: the gauges start over, then find they no longer apply).
    w.setGravity(Vec2(0.0, 9.81));
    g.restart();
    run(w, g, 0.1, 0.01);
    EXPECT_FALSE(w.measuringVirial());
}

TEST(GasGauges, ThePlotKeepsAPointEveryQuarterSecondThroughAHeatAndDropsThePastUndone) {
    World w = gasPreset(StepMode::Discrete);
    GasGauges g;
    run(w, g, 2.0, 0.01);
    ASSERT_GE(g.history().size(), 8u);
    EXPECT_LE(g.history().size(), 9u);
    for (std::size_t i = 1; i < g.history().size(); ++i)
        EXPECT_NEAR(g.history()[i].time - g.history()[i - 1].time, 0.25, 0.011);
    EXPECT_FALSE(g.history().front().pressure.has_value());  // the window was short
    EXPECT_TRUE(g.history().back().pressure.has_value());
    const double ideal = g.history().back().idealPressure;
    // Heat: every speed x sqrt 2 doubles kT and so the predicted pressures. The window starts
    // over; the plot keeps its past and shows the step.
    for (const ParticleId id : w.ids())
        w.setVelocity(id, std::sqrt(2.0) * w.get(id).velocity);
    g.restart();
    const std::size_t kept = g.history().size();
    run(w, g, 1.0, 0.01);
    EXPECT_GE(g.history().size(), kept + 3);
    EXPECT_NEAR(g.history().back().idealPressure / ideal, 2.0, 0.01);
    EXPECT_FALSE(g.history()[kept].pressure.has_value());  // the new window was short
    // Time going back (an undo) drops the points after it; a new scene drops them all.
    World earlier = gasPreset(StepMode::Discrete);
    run(earlier, g, 1.0, 0.01);
    EXPECT_LE(g.history().back().time, 1.0 + 1e-9);
    EXPECT_LE(g.history().size(), 5u);
    g.restart(true);
    EXPECT_TRUE(g.history().empty());
}

TEST(GasGauges, ApplyToAWalledOrPeriodicBoxWithoutGravity) {
    World w = gasPreset(StepMode::Discrete);
    EXPECT_TRUE(gasGaugesApply(w));
    WorldDef d = w.def();
    d.gravity = Vec2(0, 9.81);
    EXPECT_FALSE(gasGaugesApply(World(d)));
    d = w.def();
    d.walls = false;
    EXPECT_FALSE(gasGaugesApply(World(d)));
    // A periodic box has no walls, but a pressure: the collision virial's. With fixed
    // obstacles it has none the core measures.
    World periodic = gasPreset(StepMode::Discrete);
    periodic.setPeriodic(true);
    EXPECT_TRUE(gasGaugesApply(periodic));
    periodic.addObstacle(Obstacle::peg(Vec2(3.5, 3.5), 0.05));
    EXPECT_FALSE(gasGaugesApply(periodic));
    EXPECT_FALSE(gasGaugesApply(World(w.def())));  // no particles
    World few(w.def());
    for (std::size_t k = 0; k + 1 < kGasMinParticles; ++k)
        few.add({.position = Vec2(1.0 + 0.5 * static_cast<double>(k), 1.0), .radius = 0.1});
    EXPECT_FALSE(gasGaugesApply(few)) << "two balls colliding are not a gas";
    few.add({.position = Vec2(1.0, 3.0), .radius = 0.1});
    EXPECT_TRUE(gasGaugesApply(few));
}

}  // namespace
}  // namespace psb::app
