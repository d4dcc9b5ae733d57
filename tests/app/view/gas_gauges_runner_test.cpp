// The gas gauges read what the runner reports: the same scene run in the window (a session,
// frame after frame, as the app drives it) and by `particle-sim --observables` (the runner,
// in-process) over the same stretch of simulated time gives the same temperature, pressure,
// error and collision rates, and the panel's lines show the runner's numbers.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <particle_sandbox/scene.hpp>

#include "runner.hpp"
#include "session/session_fixture.hpp"
#include "session/units.hpp"
#include "view/gas_lines.hpp"

namespace psb::app {
namespace {

class GasGaugesRunner : public SessionFixture {
  protected:
    GasGaugesRunner() : SessionFixture("psb-gauges-runner", {}) {}

    /// The session over `scene`, run in frames of one step until `seconds` of simulated time;
    /// the gauges sample the set-up first (a paused frame), as the window does when it opens.
    Session runInWindow(const Scene& scene, double seconds) const {
        Session s(makeWorld(scene), SceneInfo{.name = scene.name, .dt = scene.dt}, options());
        s.update(0.0, 0.0, 1e9);  // paused: the gauges' first sample, at t = 0
        s.apply(cmd::TogglePause{});
        double now = 0.0;
        while (s.world().time() < seconds - 1e-9) {
            now += scene.dt;
            s.update(scene.dt, now, 1e9);
        }
        return s;
    }
};

/// `a` and `b` the same to rounding.
::testing::AssertionResult same(double a, double b, double relative = 1e-9) {
    if (std::abs(a - b) <= relative * std::max(std::abs(a), std::abs(b))) {
        return ::testing::AssertionSuccess();
    }
    return ::testing::AssertionFailure() << a << " and " << b << " differ by " << (a - b);
}

TEST_F(GasGaugesRunner, TheGasPresetReadsInTheWindowWhatTheRunnerReportsOverTheSameFiveSeconds) {
    // particle-sim 04-gas-in-a-box.json --duration 5 --observables: 4000 discs, 500 steps.
    const Scene scene = loadScene(testAsset("scenes/04-gas-in-a-box.json"));
    cli::RunOptions o;
    o.duration = 5.0;
    o.observables = true;
    World ran;
    const cli::RunReport report = cli::runScene(scene, o, ran);
    ASSERT_TRUE(report.observables.has_value());
    const ObservablesResult& m = *report.observables;

    const Session s = runInWindow(scene, 5.0);
    EXPECT_EQ(s.world().time(), ran.time());
    const std::optional<GasReading> gas = s.gasReading();
    ASSERT_TRUE(gas.has_value());
    ASSERT_TRUE(gas->pressure.has_value());
    EXPECT_FALSE(gas->periodic);
    EXPECT_TRUE(same(gas->window, m.duration));
    EXPECT_TRUE(same(gas->kT, m.temperature.value));
    EXPECT_TRUE(same(gas->reach, m.area));
    EXPECT_TRUE(same(*gas->pressure, m.pressureWalls.value));
    EXPECT_TRUE(same(gas->pressureError, m.pressureWalls.error, 1e-6));
    EXPECT_TRUE(same(gas->pairRate, 0.5 * m.collisionRate.value * 4000.0));
    // The rebounds: the runner's own count over its run, not only the window's.
    EXPECT_TRUE(same(gas->wallRate, static_cast<double>(report.wallCollisions) / report.simTime));
    EXPECT_TRUE(same(gas->hardDiskPressure / gas->idealPressure, m.hendersonZ));
    // On screen: the runner's numbers, as the panel writes them.
    const std::vector<GasLine> lines = gasLines(*gas);
    ASSERT_GE(lines.size(), 2u);
    EXPECT_EQ(lines[0].value, quantity(m.temperature.value, "J"));
    EXPECT_EQ(lines[1].value, withError(m.pressureWalls.value, m.pressureWalls.error, "N/m"));
}

TEST_F(GasGaugesRunner, APeriodicExactGasReadsTheRunnersVirialPressureAfterItsWarmUp) {
    // 400 exact discs at φ = 0.3 in a periodic box. At t = 6.25 s the gauges read the window
    // they opened at 1.25 s: the runner's --warmup 1.25 --duration 5.
    const Scene scene = parseScene(R"({"version": 6,
        "world": {"width": 1, "height": 1, "periodic": true},
        "solver": {"mode": "exact", "dt": 0.05},
        "generate": {"count": 400, "radius": 0.2, "mass": 1, "temperature": 1, "seed": 2,
                     "packing_fraction": 0.3}})",
                                   "periodic gas");
    cli::RunOptions o;
    o.warmup = 1.25;
    o.duration = 5.0;
    o.observables = true;
    World ran;
    const cli::RunReport report = cli::runScene(scene, o, ran);
    ASSERT_TRUE(report.observables.has_value());
    const ObservablesResult& m = *report.observables;
    ASSERT_TRUE(m.pressureVirial.hasError());
    EXPECT_FALSE(m.pressureWalls.valid());

    const Session s = runInWindow(scene, 6.25);
    EXPECT_EQ(s.world().time(), ran.time());
    const std::optional<GasReading> gas = s.gasReading();
    ASSERT_TRUE(gas.has_value());
    ASSERT_TRUE(gas->pressure.has_value());
    EXPECT_TRUE(gas->periodic);
    EXPECT_TRUE(same(gas->window, m.duration));
    EXPECT_TRUE(same(gas->kT, m.temperature.value));
    EXPECT_TRUE(same(gas->reach, scene.world.width * scene.world.height));
    EXPECT_TRUE(same(*gas->pressure, m.pressureVirial.value));
    EXPECT_TRUE(same(gas->pressureError, m.pressureVirial.error, 1e-6));
    EXPECT_TRUE(same(gas->pairRate, 0.5 * m.collisionRate.value * 400.0));
    EXPECT_EQ(gas->wallRate, 0.0);
    // Z of the dense gas, well away from the ideal gas's 1.
    EXPECT_GT(*gas->pressure, 1.5 * gas->idealPressure);
}

}  // namespace
}  // namespace psb::app
