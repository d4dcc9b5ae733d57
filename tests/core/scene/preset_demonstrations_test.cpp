// What the obstacle presets' descriptions claim, checked in each mode they name: the Galton
// board's bins against the binomial, the funnel's arches, the hourglass's steady flow, the
// ramps' corner, the tennis ball's rebound.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numbers>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <particle_sandbox/bins.hpp>
#include <particle_sandbox/diagnostics.hpp>
#include <particle_sandbox/scene.hpp>
#include <particle_sandbox/world.hpp>

#include "obstacles/obstacle_geometry.hpp"

namespace psb {
namespace {

const std::filesystem::path kScenes = std::filesystem::path(PSB_ASSETS_DIR) / "scenes";

/// The preset, to be stepped in `mode` (nullopt: the one it opens in) with its own dt and
/// substeps.
Scene presetIn(const char* file, std::optional<StepMode> mode = std::nullopt) {
    Scene s = loadScene(kScenes / file);
    if (mode) s.solver.mode = *mode;
    return s;
}

std::string readFile(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// Steps `w` by `dt` (its scene's) for `seconds`.
void runFor(World& w, double dt, double seconds) {
    const long steps = std::lround(seconds / dt);
    for (long k = 0; k < steps; ++k)
        w.step(dt);
}

/// Grains whose centre is above the height `y` (y points down).
int above(const World& w, double y) {
    const ParticleArrays& p = w.particles();
    return static_cast<int>(
        std::count_if(p.y.begin(), p.y.end(), [y](double py) { return py < y; }));
}

/// Grains above `y` every `every` seconds from t = 0 to `until`, in steps of `dt`.
std::vector<int> aboveOverTime(World& w, double dt, double y, double every, double until) {
    std::vector<int> counts{above(w, y)};
    while (w.time() < until - 1e-9) {
        runFor(w, dt, every);
        counts.push_back(above(w, y));
    }
    return counts;
}

// --- 09-galton-board.json: a spout drops 1000 balls, one every 0.05 s, on 8 rows of pegs -------

/// The deepest any ball is inside any peg or bin wall, metres (<= 0 when none is).
double deepestInObstacle(const World& w) {
    double deepest = -INFINITY;
    const ParticleArrays& p = w.particles();
    for (std::size_t i = 0; i < p.size(); ++i) {
        for (const Obstacle& o : w.obstacles()) {
            double qx, qy;
            nearestCorePoint(o, p.x[i], p.y[i], qx, qy);
            deepest =
                std::max(deepest, o.radius + p.radius[i] - std::hypot(p.x[i] - qx, p.y[i] - qy));
        }
    }
    return deepest;
}

TEST(PresetDemonstrations, GaltonBoardInTheExactModeFillsItsBinsAsTheBinomialSays) {
    // The preset as it opens (the exact mode) until its spout is empty (1000 balls, one every
    // 0.05 s) and 3 s more for the last ball to land: 12 to 30 s in Release. The first few
    // hundred balls alone are no cheaper check: balls that meet in a gap between two pegs
    // sometimes stay there, wedged, until later balls knock them through.
#if defined(__SANITIZE_ADDRESS__)
    // 1.3 million events take 12 to 30 s in Release and over the 5-minute limit under the
    // sanitizers: the release stage runs it; the shorter Galton tests run under both.
    GTEST_SKIP() << "too long under the sanitizers (the release stage runs it)";
#endif
    const Scene s = loadScene(kScenes / "09-galton-board.json");
    ASSERT_EQ(s.solver.mode, StepMode::Exact);
    ASSERT_EQ(s.droppers.size(), 1u);
    const std::uint64_t kBalls = s.droppers[0].balls;
    ASSERT_EQ(kBalls, 1000u);
    World w = makeWorld(s);
    runFor(w, s.dt, static_cast<double>(kBalls) * s.droppers[0].interval + 3.0);
    ASSERT_EQ(w.droppers()[0].balls, 0u);
    EXPECT_EQ(w.droppers()[0].released, kBalls);
    ASSERT_EQ(w.size(), kBalls);
    const BinsMeasurement m = measureBins(*s.bins, w.particles());
    EXPECT_EQ(m.counts.counted(), kBalls);  // every ball in the nine bins
    EXPECT_EQ(m.counts.outside, 0u);
    ASSERT_TRUE(m.test && m.test->valid());
    EXPECT_TRUE(m.test->passes()) << "chi-squared " << m.test->statistic << " on " << m.test->dof
                                  << " degrees of freedom, critical " << m.test->critical;
    // Each release rebuilds the exact mode's events; the bins' piles stay asleep across those
    // rebuilds. 1.3 million events in all; when every rebuild woke the piles, the first 20 s
    // alone took more than 12 million (docs/accuracy.md).
    EXPECT_LT(w.counters().events, 4'000'000u);
    // Nothing through a peg or a bin wall, and no two balls overlapping beyond rounding.
    EXPECT_LT(deepestInObstacle(w), 1e-9);
    EXPECT_LT(maxOverlap(w), 1e-9);
}

TEST(PresetDemonstrations, GaltonBoardsSpoutDropsOneBallEveryIntervalInEveryMode) {
    // In each mode, one ball every 0.05 s from t = 0: 20 by t = 0.99 s (the 21st is due at
    // t = 1 s).
    for (const StepMode mode : {StepMode::Discrete, StepMode::Substep, StepMode::Exact}) {
        Scene s = loadScene(kScenes / "09-galton-board.json");
        s.solver.mode = mode;
        if (mode != StepMode::Exact) s.dt = 0.001;
        s.solver.substeps = mode == StepMode::Substep ? 4 : 1;
        World w = makeWorld(s);
        runFor(w, s.dt, 0.99);
        EXPECT_EQ(w.size(), 20u) << toString(mode);
        EXPECT_EQ(w.droppers()[0].balls, 980u) << toString(mode);
        EXPECT_EQ(w.droppers()[0].released, 20u) << toString(mode);
    }
}

// --- 10-funnel.json: 400 balls of 8 mm, a neck of 2.2 cm (2.75 balls wide) at y = 0.5 m -------

constexpr double kFunnelNeck = 0.5;

/// Removes the lowest ball above the funnel's neck: the keystone of the arch that blocks it.
void takeOutTheKeystone(World& w) {
    const ParticleArrays& p = w.particles();
    std::size_t keystone = p.size();
    for (std::size_t i = 0; i < p.size(); ++i)
        if (p.y[i] < kFunnelNeck && (keystone == p.size() || p.y[i] > p.y[keystone])) keystone = i;
    ASSERT_LT(keystone, p.size());
    EXPECT_GT(p.y[keystone], kFunnelNeck - 0.02);  // it sits in the neck
    ASSERT_TRUE(w.remove(p.id[keystone]));
}

TEST(PresetDemonstrations, FunnelFlowsInFitsThenAnArchHoldsUntilABallIsTakenOut) {
    const Scene s = presetIn("10-funnel.json");
    World w = makeWorld(s);
    ASSERT_EQ(w.solver().mode, StepMode::Substep);
    const std::vector<int> n = aboveOverTime(w, s.dt, kFunnelNeck, 0.1, 3.0);  // n[i] at t = 0.1 i
    // Balls go through: some tens, not all.
    EXPECT_LE(n[20], 380);
    EXPECT_GE(n[20], 300);
    // The flow stalls (0.4 s with no ball through) and then starts again, before 2 s.
    bool stallThenFlow = false;
    for (std::size_t i = 2; i + 4 < 20; ++i)
        if (n[i] == n[i + 4] && n[i + 4] > n[20]) stallThenFlow = true;
    EXPECT_TRUE(stallThenFlow) << "no stall followed by more flow before 2 s";
    // From 2.2 s on an arch holds everything above it.
    EXPECT_EQ(n[30], n[22]);

    // Take out the arch's lowest ball (the one nearest the neck): the flow resumes.
    takeOutTheKeystone(w);
    const int before = above(w, kFunnelNeck);
    runFor(w, s.dt, 1.0);
    EXPECT_LE(above(w, kFunnelNeck), before - 5);
    // Until a new arch holds.
    runFor(w, s.dt, 0.5);
    const int again = above(w, kFunnelNeck);
    runFor(w, s.dt, 0.5);
    EXPECT_EQ(above(w, kFunnelNeck), again);
}

TEST(PresetDemonstrations, FunnelInTheDiscreteModePoursOutLikeALiquid) {
    const Scene s = presetIn("10-funnel.json", StepMode::Discrete);
    World w = makeWorld(s);
    const std::vector<int> n = aboveOverTime(w, s.dt, kFunnelNeck, 0.1, 4.5);
    // No arch holds under the weight above it: balls go through in every 0.5 s while more
    // than 60 are left (the preset drains completely by 4.2 s; with other generate seeds an
    // arch can hold the last few dozen).
    for (std::size_t i = 5; i + 5 < n.size() && n[i] > 60; i += 5)
        EXPECT_LT(n[i + 5], n[i]) << "at " << 0.1 * i << " s";
    EXPECT_LE(n[45], 60);
    // Fast while full, slow near the end: the balls through in [0.4, 0.9] s against [1.9, 2.4] s.
    EXPECT_GT(n[4] - n[9], 3 * (n[19] - n[24]));
    EXPECT_GT(n[19] - n[24], 0);
}

TEST(PresetDemonstrations, FunnelInTheExactModeLocksAtOnceAndAgainWhenABallIsTakenOut) {
    // Rigid balls: an arch holds after a few balls, as in the substep mode with stiffer
    // contacts (at 8 substeps, generate seeds 1-5: 8-27 balls through, then locked).
    const Scene s = presetIn("10-funnel.json", StepMode::Exact);
    World w = makeWorld(s);
    runFor(w, s.dt, 0.7);
    const int locked = above(w, kFunnelNeck);
    EXPECT_GE(locked, 370);  // a few tens of balls at most go through
    runFor(w, s.dt, 0.5);
    EXPECT_EQ(above(w, kFunnelNeck), locked);
    // Taking out the keystone lets a ball or two through, and at once a new arch holds. (A
    // slider at rest against a neighbour once met it again at the same instant without end:
    // 4 million events in the first step, the event budget.)
    takeOutTheKeystone(w);
    const std::uint64_t events = w.counters().events;
    w.step(s.dt);
    ASSERT_LT(w.counters().events - events, 100000u);
    runFor(w, s.dt, 0.5);
    const int relocked = above(w, kFunnelNeck);
    EXPECT_LE(relocked, locked - 2);
    EXPECT_GT(relocked, locked - 20);
    runFor(w, s.dt, 0.5);
    EXPECT_EQ(above(w, kFunnelNeck), relocked);
}

/// The funnel preset with its neck widened to `neck` metres (ten balls for 8 cm).
Scene funnelWithNeck(double neck, StepMode mode) {
    Scene s = loadScene(kScenes / "10-funnel.json");
    s.solver.mode = mode;
    s.world.obstacles[0].b.x() = 0.3 - 0.5 * neck;
    s.world.obstacles[1].b.x() = 0.3 + 0.5 * neck;
    return s;
}

TEST(PresetDemonstrations, FunnelWithANeckTenBallsWideDrainsInTheExactModeAsInTheSubstepMode) {
    // No arch spans ten balls: the funnel empties in both modes, by 1 s. The exact mode's sleeping
    // rules once locked it with 72 balls left: grains counted a sleeper above or beside them as a
    // support, and a grain whose support left was never woken.
    for (StepMode mode : {StepMode::Substep, StepMode::Exact}) {
        SCOPED_TRACE(static_cast<int>(mode));
        const Scene s = funnelWithNeck(0.08, mode);
        World w = makeWorld(s);
        const std::vector<int> n = aboveOverTime(w, s.dt, kFunnelNeck, 0.5, 2.5);
        EXPECT_LT(n[1], 300);  // the first 0.5 s
        EXPECT_EQ(n[5], 0);
    }
}

// --- 11-hourglass.json: 400 grains of 6 mm, a 3 cm neck at y = 0.45 m, 60 degree bulbs ------

constexpr double kHourglassNeck = 0.45;

TEST(PresetDemonstrations, HourglassFlowsAtANearlyConstantRateHoweverFullTheBulbIs) {
    const Scene s = presetIn("11-hourglass.json");
    World w = makeWorld(s);
    ASSERT_EQ(w.solver().mode, StepMode::Substep);
    // The first grains reach the neck at 0.25 s; after the first rush, from 0.4 s to 2 s the
    // bulb goes from 80 % full to nearly empty ...
    runFor(w, s.dt, 0.4);
    const std::vector<int> n =
        aboveOverTime(w, s.dt, kHourglassNeck, 0.4, 2.0);  // t = 0.4, 0.8, ...
    EXPECT_GE(n[0], 300);
    EXPECT_LE(n[4], 20);
    // ... and lets through as many grains in the first 0.8 s as in the last, to 15 %, and in
    // each 0.4 s within 20 % of their mean. (The count per 0.4 s is noisy: over generate seeds
    // 1 to 4 it ranged over 73-90; the two halves agreed to 10 %.)
    const int first = n[0] - n[2], last = n[2] - n[4];
    EXPECT_GT(std::min(first, last), 0);
    EXPECT_LE(std::max(first, last), 1.15 * std::min(first, last)) << first << " " << last;
    const double mean = (n[0] - n[4]) / 4.0;
    for (std::size_t i = 0; i < 4; ++i)
        EXPECT_NEAR(n[i] - n[i + 1], mean, 0.2 * mean) << "window " << i;
}

TEST(PresetDemonstrations, HourglassInTheDiscreteModeDrainsFastThenSlowlyLikeWater) {
    const Scene s = presetIn("11-hourglass.json", StepMode::Discrete);
    World w = makeWorld(s);
    const std::vector<int> n = aboveOverTime(w, s.dt, kHourglassNeck, 0.1, 0.7);
    // The first grains reach the neck at 0.2 s. From 0.3 s each tenth of a second lets through
    // less than 2/3 of the one before, and by 0.7 s the bulb is empty.
    EXPECT_GT(2 * (n[3] - n[4]), 3 * (n[4] - n[5]));
    EXPECT_GT(2 * (n[4] - n[5]), 3 * (n[5] - n[6]));
    EXPECT_GT(n[5] - n[6], 0);
    EXPECT_EQ(n[7], 0);
}

TEST(PresetDemonstrations, HourglassInTheExactModeFlowsUntilTheBulbIsEmpty) {
    // As in the substep mode, if slower: 57 grains through by 0.5 s, 143 by 1 s, all 400 by
    // 2.6 s, against 94, 196 and all by 2.5 s in the substep mode. (Over generate seeds 1 and
    // 2: 73 and 61 by 0.5 s; seed 1 empties by 2.5 s, in seed 2 an arch holds the last 222 from
    // 1.5 s: whether a pour arches is chance, docs/exact.md.) The exact mode once locked it into
    // a fake arch after about 45 grains (grains held up by the sleepers above or beside them).
    const Scene s = presetIn("11-hourglass.json", StepMode::Exact);
    World w = makeWorld(s);
    const std::vector<int> n = aboveOverTime(w, s.dt, kHourglassNeck, 0.5, 3.0);  // t = 0, 0.5, ...
    // Grains pass in every half second until the bulb is empty: no arch holds.
    for (std::size_t i = 1; i + 1 < n.size() && n[i] > 0; ++i)
        EXPECT_GE(n[i] - n[i + 1], std::min(n[i], 20)) << "from " << 0.5 * i << " s";
    EXPECT_LE(n[2], 340);  // at 1 s
    EXPECT_LE(n[6], 3);    // at 3 s
}

TEST(PresetDemonstrations, HourglassWithASevenCentimetreNeckDrainsInASecondInTheExactMode) {
    // 500 grains, a neck 12 grains wide: all through by 1 s in the substep mode and in the exact
    // mode (measured: 360 at 0.5 s). It once froze with 188 through.
    std::string json = readFile(kScenes / "11-hourglass.json");
    for (const auto& [from, to] :
         {std::pair{"0.135, 0.45", "0.115, 0.45"}, std::pair{"0.165, 0.45", "0.185, 0.45"},
          std::pair{"\"count\": 400", "\"count\": 500"}, std::pair{"0.29, 0.2012", "0.29, 0.22"}}) {
        for (std::size_t at = json.find(from); at != std::string::npos; at = json.find(from, at))
            json.replace(at, std::string_view(from).size(), to);
    }
    Scene s = parseScene(json, "hourglass with a 7 cm neck");
    s.solver.mode = StepMode::Exact;
    World w = makeWorld(s);
    ASSERT_EQ(w.size(), 500u);
    runFor(w, s.dt, 1.5);
    EXPECT_EQ(above(w, kHourglassNeck), 0);
}

// --- 12-ramp.json: a ball, a disc and a block race down three 20 degree ramps ----------------

/// The distance along a 20° ramp (down and to the right) of particle `i`'s centre, metres.
double alongRamp(const World& w, std::size_t i) {
    const double angle = 20.0 * std::numbers::pi / 180.0;
    return w.particles().x[i] * std::cos(angle) + w.particles().y[i] * std::sin(angle);
}

TEST(PresetDemonstrations, RampBallAndDiscRollAtGSinThetaOverOnePlusKAndTheBlockSlides) {
    // Rolling without slipping (0.2 >= k tan 20 / (1 + k): 0.10 for the ball, 0.12 for the
    // disc) at g sin 20 / (1 + k); the block, which cannot turn, slides at
    // g (sin 20 - 0.2 cos 20), in every mode (the exact mode rolls them as closed-form motion).
    const double angle = 20.0 * std::numbers::pi / 180.0, g = 9.81;
    const double ball = g * std::sin(angle) / 1.4, disc = g * std::sin(angle) / 1.5;
    const double block = g * (std::sin(angle) - 0.2 * std::cos(angle));
    EXPECT_NEAR(ball, 2.40, 0.005);  // the figures of the description
    EXPECT_NEAR(disc, 2.24, 0.005);
    EXPECT_NEAR(block, 1.51, 0.005);
    for (StepMode mode : {StepMode::Discrete, StepMode::Substep, StepMode::Exact}) {
        SCOPED_TRACE(static_cast<int>(mode));
        const Scene s = presetIn("12-ramp.json", mode);
        World w = makeWorld(s);
        ASSERT_EQ(w.size(), 3u);
        // Distances at 0.4, 0.8 and 1.2 s (before the first reaches the wall, at 1.75 s): the
        // second difference over (0.4 s)² is the acceleration.
        std::array<double, 3> start{};
        for (std::size_t i = 0; i < 3; ++i)
            start[i] = alongRamp(w, i);
        std::array<std::array<double, 3>, 3> d{};
        for (std::size_t k = 0; k < 3; ++k) {
            runFor(w, s.dt, 0.4);
            for (std::size_t i = 0; i < 3; ++i)
                d[k][i] = alongRamp(w, i);
        }
        const auto accel = [&](std::size_t i) {
            return (d[2][i] - 2.0 * d[1][i] + d[0][i]) / (0.4 * 0.4);
        };
        EXPECT_NEAR(accel(2), block, 0.005 * block);
        EXPECT_EQ(w.get(w.ids()[2]).angularVelocity, 0.0) << "the block never turns";
        EXPECT_NEAR(accel(0), ball, 0.005 * ball);
        EXPECT_NEAR(accel(1), disc, 0.005 * disc);
        // Rolling: the rim's speed is the centre's, omega r = v.
        for (std::size_t i = 0; i < 2; ++i) {
            const Particle p = w.get(w.ids()[i]);
            EXPECT_NEAR(p.angularVelocity * p.radius, p.velocity.norm(), 1e-3 * p.velocity.norm())
                << i;
        }
        // The race, each from the same start on its ramp: the ball ahead of the disc, the disc
        // ahead of the block.
        EXPECT_GT(d[2][0] - start[0], d[2][1] - start[1] + 0.05);
        EXPECT_GT(d[2][1] - start[1], d[2][2] - start[2] + 0.3);
    }
}

TEST(PresetDemonstrations, RampBodiesEndAtRestAgainstTheRightWallOnTheirOwnRampsInEveryMode) {
    for (StepMode mode : {StepMode::Discrete, StepMode::Substep, StepMode::Exact}) {
        SCOPED_TRACE(static_cast<int>(mode));
        const Scene s = presetIn("12-ramp.json", mode);
        World w = makeWorld(s);
        runFor(w, s.dt, 8.0);
        const ParticleArrays& p = w.particles();
        for (std::size_t i = 0; i < 3; ++i) {
            // Touching the right wall, resting on its own ramp (which ends there 1.456 m below
            // where it starts), at rest to the mode's jitter.
            EXPECT_NEAR(p.x[i], w.def().width - p.radius[i], 1e-3) << i;
            const Obstacle& ramp = w.obstacles()[i];
            const double rampY =
                ramp.b.y() - ramp.radius / std::cos(20.0 * std::numbers::pi / 180.0);
            EXPECT_LT(p.y[i], rampY) << i;
            EXPECT_GT(p.y[i], rampY - 2.5 * p.radius[i]) << i;
            EXPECT_LT(std::hypot(p.vx[i], p.vy[i]), 0.02) << i;
        }
    }
}

// --- 14-bowling.json: slide, then roll ----------------------------------------------------------

TEST(PresetDemonstrations, BowlingBallRollsAfterSlidingTheBlockStopsTheDrawShotComesBack) {
    // v0 = 4 m/s, mu = 0.2, k = 2/5, r = 0.11 m. The ball without spin rolls from
    // t* = k v0 / (mu g (1 + k)) at v0 / (1 + k); the block stops after v0² / (2 mu g); the ball
    // with backspin omega0 = -150 rad/s rolls back at (v0 + k r omega0) / (1 + k) from
    // t = (v0 - omega0 r) / (mu g (1 + 1/k)). The exact mode is left out: a block resting on
    // the box's floor feels no kinetic friction there (docs/exact-gravity.md, Gravity, Limits).
    const double g = 9.81, mu = 0.2, v0 = 4.0, k = 0.4, r = 0.11, w0 = -150.0;
    const double tStar = k * v0 / (mu * g * (1 + k));
    const double rolling = v0 / (1 + k);
    const double stop = v0 * v0 / (2 * mu * g);
    const double back = (v0 + k * r * w0) / (1 + k);
    const double tBack = (v0 - w0 * r) / (mu * g * (1 + 1 / k));
    // The figures of the description.
    EXPECT_NEAR(tStar, 0.58, 0.005);
    EXPECT_NEAR(rolling, 2.86, 0.005);
    EXPECT_NEAR(stop, 4.08, 0.005);
    EXPECT_NEAR(back, -1.86, 0.005);
    EXPECT_NEAR(tBack, 2.99, 0.005);
    for (StepMode mode : {StepMode::Discrete, StepMode::Substep}) {
        SCOPED_TRACE(static_cast<int>(mode));
        const Scene s = presetIn("14-bowling.json", mode);
        World w = makeWorld(s);
        const auto particle = [&](std::size_t i) { return w.get(w.ids()[i]); };
        runFor(w, s.dt, 0.4);
        EXPECT_GT(particle(0).velocity.x() - particle(0).angularVelocity * r, 0.5)
            << "still sliding before t*";
        runFor(w, s.dt, 0.6);  // t = 1 s
        EXPECT_NEAR(particle(0).velocity.x(), rolling, 0.002 * rolling);
        EXPECT_NEAR(particle(0).angularVelocity * r, rolling, 0.002 * rolling);
        runFor(w, s.dt, 2.5);  // t = 3.5 s
        EXPECT_NEAR(particle(1).position.x() - 0.5, stop, 0.01);
        EXPECT_EQ(particle(1).velocity.x(), 0.0);
        EXPECT_NEAR(particle(2).velocity.x(), back, 0.002 * std::abs(back));
        EXPECT_NEAR(particle(2).angularVelocity * r, back, 0.002 * std::abs(back));
    }
}

// --- 13-basketball-and-tennis-ball.json -------------------------------------------------------

TEST(PresetDemonstrations, TennisBallClimbsFiveTimesTheHeightThePairFell) {
    // The basketball (0.6 kg) hits the floor after a 1 m fall and meets the tennis ball
    // (0.058 kg) still falling at the same speed v. With e = 0.9 for both impacts the tennis
    // ball leaves at v (e(2 + e) M - m) / (M + m) = 2.292 v, and so climbs 2.292² = 5.25 times
    // the fall, from where the two met (its centre 0.273 m above the floor).
    const double e = 0.9, M = 0.6, m = 0.058;
    const double ratio = std::pow((e * (2 + e) * M - m) / (M + m), 2);
    EXPECT_NEAR(ratio, 5.25, 0.01);
    for (StepMode mode : {StepMode::Discrete, StepMode::Substep, StepMode::Exact}) {
        SCOPED_TRACE(static_cast<int>(mode));
        const Scene s = presetIn("13-basketball-and-tennis-ball.json", mode);
        World w = makeWorld(s);
        const double floorY = w.def().height;
        ASSERT_NEAR(floorY - (w.particles().y[0] + w.particles().radius[0]), 1.0, 1e-12);
        double top = floorY;
        for (int k = 0; k < 180; ++k) {  // 1.5 s: the apex comes at about 1.48 s
            w.step(s.dt);
            top = std::min(top, w.particles().y[1]);
        }
        const double climb = (floorY - top) - 0.273;
        // The exact mode to 1 %; the substeps of 1/960 s lose a little, the discrete mode's
        // steps of 1/120 s (the scene's frame) about 3 %.
        if (mode == StepMode::Exact)
            EXPECT_NEAR(climb, ratio, 0.01 * ratio);
        else
            EXPECT_GT(climb, (mode == StepMode::Substep ? 0.98 : 0.95) * ratio);
        EXPECT_LT(climb, ratio * 1.01);  // never above what e = 0.9 allows
    }
}

}  // namespace
}  // namespace psb
