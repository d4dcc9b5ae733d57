// The accuracy indicators, and grab/spawn/delete in every mode.

#include <gtest/gtest.h>

#include <cmath>

#include <particle_sandbox/diagnostics.hpp>

#include <particle_sandbox/error.hpp>

#include "session/accuracy.hpp"
#include "session/gas_world.hpp"
#include "session/hand_steps.hpp"
#include "session/interaction.hpp"

namespace psb::app {
namespace {

constexpr double kDt = 0.01;  ///< the frame length the worlds here are stepped by

TEST(MonitoredEnergy, IsKineticWithoutGravityAndMechanicalWithIt) {
    // Under gravity kinetic energy alone changes as particles fall, so the HUD's drift would
    // claim energy made or lost: it follows kinetic + potential instead.
    World w = gasWorld();
    EXPECT_EQ(monitoredEnergy(w), kineticEnergy(w));
    w.setGravity({0.0, 200.0});  // strong, so that 30 steps change the kinetic energy a lot
    EXPECT_EQ(monitoredEnergy(w), mechanicalEnergy(w));
    AccuracyMonitor kinetic, monitored;
    kinetic.resetReference(kineticEnergy(w));
    monitored.resetReference(monitoredEnergy(w));
    for (int k = 0; k < 30; ++k)
        w.step(kDt);
    // A falling gas gains kinetic energy; kinetic + potential changes far less.
    const double keDrift = kinetic.drift(kineticEnergy(w));
    const double drift = monitored.drift(monitoredEnergy(w));
    EXPECT_GT(keDrift, 0.01) << keDrift;
    EXPECT_LT(std::abs(drift), 0.1 * keDrift) << drift;
}

TEST(AccuracyMonitor, DriftIsRelativeToTheLastReference) {
    AccuracyMonitor m;
    EXPECT_TRUE(std::isnan(m.drift(5.0)));  // no reference yet
    m.resetReference(10.0);
    EXPECT_NEAR(m.drift(11.0), 0.1, 1e-15);
    EXPECT_NEAR(m.drift(9.0), -0.1, 1e-15);
    m.resetReference(11.0);  // a user action
    EXPECT_NEAR(m.drift(11.0), 0.0, 1e-15);
    m.resetReference(0.0);  // nothing moving: no relative drift to speak of
    EXPECT_TRUE(std::isnan(m.drift(1.0)));
}

TEST(AccuracyMonitor, DriftStartsAtZeroAfterAnActionInAnEnergyChangingWorld) {
    // With gravity the kinetic energy grows as particles fall; a user action makes that
    // growth start again from zero.
    World w = gasWorld(Vec2(0.0, 50.0));
    AccuracyMonitor m;
    m.resetReference(kineticEnergy(w));
    for (int k = 0; k < 20; ++k)
        w.step(kDt);
    EXPECT_GT(std::abs(m.drift(kineticEnergy(w))), 1e-3);
    m.resetReference(kineticEnergy(w));
    EXPECT_EQ(m.drift(kineticEnergy(w)), 0.0);
}

TEST(AccuracyMonitor, OverlapCoversOnlyTheLastFrameThatStepped) {
    World w(WorldDef{});
    ParticleDef a;
    a.position = {100, 100};
    a.radius = 10.0;
    ParticleDef b = a;
    b.position = {117, 100};  // 3 m overlap, separated by the step
    w.add(a);
    w.add(b);
    AccuracyMonitor m;
    m.beginSteps(w);
    w.step(kDt);
    m.endSteps(w);
    EXPECT_NEAR(m.overlap(), 3.0, 1e-9);
    // A paused frame (no step) keeps the figure.
    m.beginSteps(w);
    m.endSteps(w);
    EXPECT_NEAR(m.overlap(), 3.0, 1e-9);
    // The next stepping frame finds them apart: the cumulative counter would still say 3 m.
    m.beginSteps(w);
    w.step(kDt);
    m.endSteps(w);
    EXPECT_LT(m.overlap(), 1e-9);
}

class EveryMode : public ::testing::TestWithParam<StepMode> {};

TEST_P(EveryMode, GrabSpawnAndDeleteKeepWorking) {
    World w = gasWorld();
    SolverSettings s = w.solver();
    s.mode = GetParam();
    s.substeps = 4;
    w.setSolver(s);
    for (int k = 0; k < 5; ++k)
        w.step(kDt);

    // Grab a particle and drag it right through the gas for half a second.
    Interaction in;
    const ParticleId target = w.ids()[12];
    const Vec2 start = w.get(target).position;
    press(in, w, start, 0.0);
    ASSERT_EQ(in.mode(), Interaction::Mode::Holding);
    LaunchSettings ls;
    ls.window = 0.1;
    ls.minDistance = 1.0;
    double t = 0.0;
    for (int k = 1; k <= 50; ++k) {
        t = 0.01 * k;
        in.moveTo(start + Vec2(200.0 * t, 0.0), t);
        applyHold(in, w, t, ls);
        w.step(kDt);
    }
    // A step carries the held particle on with the hand's velocity; the app places it at the
    // hand again before drawing and before the next step.
    applyHold(in, w, t, ls);
    EXPECT_NEAR(w.get(target).position.x(), start.x() + 100.0, 1e-6);

    // Spawn between steps; the next step picks it up.
    ParticleDef d;
    d.position = {650, 650};
    d.velocity = {-30, -10};
    d.radius = 5.0;
    const ParticleId added = w.add(d);
    w.step(kDt);
    EXPECT_LT(w.get(added).position.x(), 650.0);

    // Delete the held particle, then keep stepping.
    const std::size_t before = w.size();
    ASSERT_TRUE(deleteHeld(in, w).has_value());
    EXPECT_EQ(w.size(), before - 1);
    EXPECT_FALSE(w.contains(target));
    for (int k = 0; k < 20; ++k)
        w.step(kDt);
    for (std::size_t i = 0; i < w.size(); ++i) {
        EXPECT_TRUE(std::isfinite(w.particles().x[i]));
        EXPECT_TRUE(std::isfinite(w.particles().y[i]));
    }
    if (GetParam() == StepMode::Exact) {
        EXPECT_LT(maxOverlapBruteForce(w), 1e-6);  // no overlap survives in exact mode
    }
}

INSTANTIATE_TEST_SUITE_P(AppModes, EveryMode,
                         ::testing::Values(StepMode::Discrete, StepMode::Substep, StepMode::Exact),
                         [](const auto& p) { return std::string(toString(p.param)); });

}  // namespace
}  // namespace psb::app
