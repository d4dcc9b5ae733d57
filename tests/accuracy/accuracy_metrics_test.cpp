// The accuracy metrics (missed collisions, overlap, errors against exact) on cases small
// enough to work out by hand.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <particle_sandbox/scene.hpp>
#include <particle_sandbox/world.hpp>

#include "accuracy_metrics.hpp"
#include "accuracy_sweep.hpp"

namespace psb::cli {
namespace {

/// Two discs of radius 1 m: A at (10, 50) moving (vA, 0), B at (xB, 50 + offsetY) at rest.
ParticleArrays pair(double vA, double xB, double offsetY) {
    World w(WorldDef{.width = 100.0, .height = 100.0});
    w.add({.position = {10.0, 50.0}, .velocity = {vA, 0.0}});
    w.add({.position = {xB, 50.0 + offsetY}});
    return w.particles();
}

TEST(AccuracyMetrics, BulletThatTunnelsInOneStepIsOneMissedCollision) {
    // A moves 20 m in the 0.02 s step: from 10 m left of B to 10 m right of it, passing
    // through B's centre, and neither end overlaps (σ = 2 m).
    const MoveCheck c = checkMove(pair(1000.0, 20.0, 0.0), 0.02, Vec2::Zero());
    EXPECT_EQ(c.missed, 1u);
    EXPECT_EQ(c.detected, 0u);
    EXPECT_EQ(c.maxOverlapOverRadius, 0.0);
}

TEST(AccuracyMetrics, TheDiscreteStepReallyMissesWhatTheMetricCallsMissed) {
    Scene s;
    s.world = WorldDef{.width = 100.0, .height = 100.0};
    s.particles = {{.position = {10.0, 50.0}, .velocity = {1000.0, 0.0}},
                   {.position = {20.0, 50.0}}};
    const RunTotals discrete = runMeasured(s, StepMode::Discrete, 0.02, 1, 0.02);
    EXPECT_EQ(discrete.collisions, 0u);  // the step saw no overlap: tunnelled
    EXPECT_EQ(discrete.missed, 1u);
    const RunTotals exact = runMeasured(s, StepMode::Exact, 0.02, 1, 0.02);
    EXPECT_EQ(exact.collisions, 1u);
    EXPECT_EQ(exact.missed, 0u);
}

TEST(AccuracyMetrics, PairOverlappingAtTheEndOfTheMoveIsDetectedWithItsDepth) {
    // A moves 1.5 m: from 3 m to 1.5 m from B's centre, 0.5 m deep (σ = 2), r = 1.
    const MoveCheck c = checkMove(pair(150.0, 13.0, 0.0), 0.01, Vec2::Zero());
    EXPECT_EQ(c.missed, 0u);
    EXPECT_EQ(c.detected, 1u);
    EXPECT_NEAR(c.maxOverlapOverRadius, 0.5, 1e-12);
}

TEST(AccuracyMetrics, PathPassingWithinOneDiameterIsMissedAndOneOutsideIsNot) {
    // A passes B at a lateral distance of 1.9 m (< σ = 2 m) and 2.1 m (> σ).
    EXPECT_EQ(checkMove(pair(1000.0, 20.0, 1.9), 0.02, Vec2::Zero()).missed, 1u);
    EXPECT_EQ(checkMove(pair(1000.0, 20.0, 2.1), 0.02, Vec2::Zero()).missed, 0u);
}

TEST(AccuracyMetrics, RecedingOrTouchingOrSlowPairsAreNotMissed) {
    // Receding: B is behind A.
    EXPECT_EQ(checkMove(pair(1000.0, 5.0, 0.0), 0.02, Vec2::Zero()).missed, 0u);
    // Touching at the start and passing through: already in contact, not a miss.
    EXPECT_EQ(checkMove(pair(1000.0, 11.5, 0.0), 0.02, Vec2::Zero()).missed, 0u);
    // Approaching but still 1 m apart (gap) at the end: the next step will see it.
    const MoveCheck slow = checkMove(pair(100.0, 20.0, 0.0), 0.07, Vec2::Zero());
    EXPECT_EQ(slow.missed, 0u);
    EXPECT_EQ(slow.detected, 0u);
}

/// The definition in accuracy_metrics.hpp, pair by pair, O(N²): the sweep-and-prune must agree.
MoveCheck checkMoveBruteForce(const ParticleArrays& p, double h) {
    MoveCheck out;
    for (std::size_t i = 0; i < p.size(); ++i) {
        for (std::size_t j = i + 1; j < p.size(); ++j) {
            const double sigma = p.radius[i] + p.radius[j];
            const Vec2 d0(p.x[j] - p.x[i], p.y[j] - p.y[i]);
            const Vec2 D = Vec2(p.vx[j] - p.vx[i], p.vy[j] - p.vy[i]) * h;
            const double end = (d0 + D).norm();
            if (end < sigma) {
                ++out.detected;
                out.maxOverlapOverRadius = std::max(
                    out.maxOverlapOverRadius, (sigma - end) / std::min(p.radius[i], p.radius[j]));
                continue;
            }
            if (d0.norm() < sigma || D.squaredNorm() == 0.0) continue;
            const double s = std::clamp(-d0.dot(D) / D.squaredNorm(), 0.0, 1.0);
            if (s > 0.0 && s < 1.0 && (d0 + s * D).norm() < sigma) ++out.missed;
        }
    }
    return out;
}

TEST(AccuracyMetrics, SweepAndPruneFindsWhatAllPairsFind) {
    // 300 discs of radii 0.5..3 m with speeds up to 400 m/s in a 100 m box, a 0.02 s move:
    // many tunnelling and many overlapping pairs, to be counted the same way by both.
    World w(WorldDef{.width = 100.0, .height = 100.0});
    std::uint64_t state = 12345;
    auto uniform = [&state](double lo, double hi) {
        state = state * 6364136223846793005ULL + 1442695040888963407ULL;
        return lo + (hi - lo) * static_cast<double>(state >> 11) * 0x1.0p-53;
    };
    for (int i = 0; i < 300; ++i) {
        w.add({.position = {uniform(3, 97), uniform(3, 97)},
               .velocity = {uniform(-400, 400), uniform(-400, 400)},
               .radius = uniform(0.5, 3.0)});
    }
    const MoveCheck fast = checkMove(w.particles(), 0.02, Vec2::Zero());
    const MoveCheck slow = checkMoveBruteForce(w.particles(), 0.02);
    EXPECT_GT(slow.missed, 50u);
    EXPECT_GT(slow.detected, 50u);
    EXPECT_EQ(fast.missed, slow.missed);
    EXPECT_EQ(fast.detected, slow.detected);
    EXPECT_NEAR(fast.maxOverlapOverRadius, slow.maxOverlapOverRadius, 1e-12);
}

TEST(AccuracyMetrics, HeadOnPairGivesACollisionRatioOfExactlyOne) {
    // Two discs 20 m apart closing at 20 m/s, well inside a 100 m box: one collision in 2 s
    // in both modes, at dt = 0.01 s (0.1 m per step, far below a radius).
    Scene s;
    s.world = WorldDef{.width = 100.0, .height = 100.0};
    s.particles = {{.position = {40.0, 50.0}, .velocity = {10.0, 0.0}},
                   {.position = {60.0, 50.0}, .velocity = {-10.0, 0.0}}};
    const RunTotals exact = runMeasured(s, StepMode::Exact, 0.01, 1, 2.0);
    const RunTotals discrete = runMeasured(s, StepMode::Discrete, 0.01, 1, 2.0);
    const ErrorMeasures e = compareToExact(discrete, exact);
    EXPECT_EQ(exact.collisions, 1u);
    EXPECT_EQ(e.collisionRatio, 1.0);
    EXPECT_EQ(e.missed, 0u);
    EXPECT_NEAR(e.kineticEnergyError, 0.0, 1e-12);
    EXPECT_TRUE(std::isnan(e.pressureRatio));  // no wall was hit in 2 s: nothing to compare
}

TEST(AccuracyMetrics, ErrorsAndCostAreTheStatedRatios) {
    RunTotals exact;
    exact.simTime = 2.0;
    exact.collisions = 400;
    exact.kineticEnergyInitial = 100.0;
    exact.kineticEnergyFinal = 100.0;
    exact.wallImpulse = 80.0;
    exact.wallLength = 40.0;  // pressure 80 / (2 · 40) = 1 N/m
    RunTotals run = exact;
    run.collisions = 300;
    run.kineticEnergyFinal = 103.0;
    run.wallImpulse = 120.0;  // 1.5 N/m
    run.wallSeconds = 0.5;
    run.particles = 1000;
    run.steps = 250;
    run.missed = 7;
    const ErrorMeasures e = compareToExact(run, exact);
    EXPECT_EQ(e.collisionRatio, 0.75);
    EXPECT_EQ(e.missed, 7u);
    EXPECT_NEAR(e.kineticEnergyError, 0.03, 1e-15);
    EXPECT_NEAR(e.pressureRatio, 1.5, 1e-15);
    EXPECT_EQ(e.wallSecondsPerSimSecond, 0.25);
    EXPECT_NEAR(e.nsPerParticleStep, 2000.0, 1e-9);  // 0.5 s / 250 000 particle-steps
}

TEST(AccuracyMetrics, PositionErrorIsTheFarthestParticleOverTheSmallestRadius) {
    RunTotals exact;
    exact.finalPositions = {Vec2(1.0, 1.0), Vec2(5.0, 2.0)};
    exact.smallestRadius = 0.5;
    RunTotals run = exact;
    run.finalPositions = {Vec2(1.0, 1.1), Vec2(5.3, 2.4)};  // 0.1 and 0.5 m off
    EXPECT_NEAR(compareToExact(run, exact).positionErrorOverRadius, 1.0, 1e-12);
    EXPECT_EQ(compareToExact(exact, exact).positionErrorOverRadius, 0.0);
    run.finalPositions.pop_back();  // not the same particles: nothing to compare
    EXPECT_TRUE(std::isnan(compareToExact(run, exact).positionErrorOverRadius));
}

TEST(AccuracyMetrics, SubstepModeIsKDiscreteStepsOfDtOverK) {
    // The sweep runs a substep row as k discrete steps of dt / k so that each move can be
    // checked; that is only honest if the world's substep mode does exactly that.
    Scene s = loadScene(PSB_ASSETS_DIR "/scenes/06-bullet-into-crowd.json");
    s.solver.mode = StepMode::Substep;
    s.solver.substeps = 4;
    World sub = makeWorld(s);
    s.solver.mode = StepMode::Discrete;
    s.solver.substeps = 1;
    World disc = makeWorld(s);
    const double dt = 1.0 / 120.0;
    for (int f = 0; f < 10; ++f) {
        sub.step(dt);
        for (int k = 0; k < 4; ++k)
            disc.step(dt / 4);
    }
    EXPECT_EQ(sub.counters().collisions, disc.counters().collisions);
    EXPECT_EQ(sub.particles().x, disc.particles().x);
    EXPECT_EQ(sub.particles().vy, disc.particles().vy);
}

}  // namespace
}  // namespace psb::cli
