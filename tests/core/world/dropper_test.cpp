// Ball droppers (dropper.hpp): when a ball is released, where, what it is, waiting for room,
// the drop stage in the profile, the checks, and determinism in every mode.

#include <gtest/gtest.h>

#include <particle_sandbox/error.hpp>
#include <particle_sandbox/world.hpp>

namespace psb {
namespace {

Dropper spout(std::uint64_t balls, double interval) {
    Dropper d;
    d.position = {0.5, 0.1};
    d.balls = balls;
    d.interval = interval;
    d.radius = 0.01;
    d.mass = 0.003;
    d.color = Color{10, 20, 30};
    d.velocity = {0.2, 0.0};
    return d;
}

World box(StepMode mode = StepMode::Discrete) {
    return World(WorldDef{.width = 1.0, .height = 1.0, .gravity = {0.0, 9.81}, .restitution = 0.5},
                 SolverSettings{.mode = mode});
}

TEST(Dropper, ReleasesOneBallEveryIntervalAsTheDropperSays) {
    World w = box();
    w.setDroppers({spout(3, 0.1)});
    w.step(0.01);  // due at t = 0: released at the first step
    ASSERT_EQ(w.size(), 1u);
    const Particle p = w.get(w.ids()[0]);
    EXPECT_EQ(p.mass, 0.003);
    EXPECT_EQ(p.radius, 0.01);
    EXPECT_EQ(p.color, (Color{10, 20, 30}));
    EXPECT_EQ(w.droppers()[0].balls, 2u);
    EXPECT_EQ(w.droppers()[0].released, 1u);
    // The next at t = 0.1 (the step starting then), the last at t = 0.2, then no more.
    int steps = 1;
    while (w.size() < 2) {
        w.step(0.01);
        ++steps;
    }
    EXPECT_EQ(steps, 11);  // the step that starts at t = 0.10
    for (int k = 0; k < 30; ++k)
        w.step(0.01);
    EXPECT_EQ(w.size(), 3u);
    EXPECT_EQ(w.droppers()[0].balls, 0u);
    EXPECT_EQ(w.droppers()[0].released, 3u);
}

TEST(Dropper, ABallLeavesWithinTheSpreadAndTheSameSeedGivesTheSameOffsets) {
    Dropper d = spout(100, 0.1);
    d.spread = 0.02;
    double lo = 1.0, hi = 0.0;
    Dropper again = d;
    for (std::uint64_t k = 0; k < 100; ++k) {
        d.released = again.released = k;
        const Vec2 at = d.nextPosition();
        EXPECT_EQ(at, again.nextPosition());
        EXPECT_EQ(at.y(), 0.1);
        lo = std::min(lo, at.x());
        hi = std::max(hi, at.x());
    }
    EXPECT_GE(lo, 0.48);
    EXPECT_LE(hi, 0.52);
    EXPECT_LT(lo, 0.485);  // it does spread
    EXPECT_GT(hi, 0.515);
    Dropper other = d;
    other.seed = 2;
    EXPECT_NE(other.nextPosition(), d.nextPosition());
    d.spread = 0.0;
    EXPECT_EQ(d.nextPosition(), d.position);
}

TEST(Dropper, WaitsWhileABallIsInTheWayAndDropsOneIntervalAfterTheLateOne) {
    World w = box();
    const ParticleId blocker = w.add({.position = {0.505, 0.1}, .radius = 0.01});
    w.setKinematic(blocker, true);  // held there
    w.setDroppers({spout(2, 0.1)});
    for (int k = 0; k < 20; ++k)
        w.step(0.01);
    EXPECT_EQ(w.size(), 1u);  // still waiting
    EXPECT_EQ(w.droppers()[0].balls, 2u);
    EXPECT_LE(w.droppers()[0].nextIn, 0.0);
    ASSERT_TRUE(w.remove(blocker));
    w.step(0.01);
    EXPECT_EQ(w.size(), 1u);  // released at once
    int steps = 1;
    while (w.size() < 2) {
        w.step(0.01);
        ++steps;
    }
    EXPECT_EQ(steps, 11);  // and the next a whole interval later
}

TEST(Dropper, AWorldWithoutDroppersHasNoDropStageAndOneWithThemListsItFirst) {
    for (const StepMode mode : {StepMode::Discrete, StepMode::Substep, StepMode::Exact}) {
        World w = box(mode);
        w.add({.position = {0.2, 0.9}, .radius = 0.01});
        w.step(0.01);
        for (int k = 0; k < w.profile().stageCount; ++k)
            EXPECT_NE(w.profile().stages[k].name, "drop") << toString(mode);
        w.setDroppers({spout(1, 0.1)});
        w.step(0.01);
        ASSERT_GT(w.profile().stageCount, 0);
        EXPECT_EQ(w.profile().stages[0].name, "drop") << toString(mode);
        EXPECT_EQ(w.size(), 2u) << toString(mode);
    }
}

TEST(Dropper, WorldRefusesADropperItCannotRun) {
    World w = box();
    auto refused = [&](Dropper d) {
        EXPECT_THROW(w.setDroppers({d}), InvalidArgument);
        EXPECT_TRUE(w.droppers().empty());
    };
    Dropper d = spout(1, 0.1);
    d.interval = 0.0;
    refused(d);
    d = spout(1, 0.1);
    d.position = {1.5, 0.1};
    refused(d);
    d = spout(1, 0.1);
    d.spread = 0.495;  // past the wall by a radius
    refused(d);
    d = spout(1, 0.1);
    d.radius = std::nan("");
    refused(d);
    d = spout(1, 0.1);
    d.radius = 0.6;
    refused(d);
    d = spout(kMaxDropperBalls + 1, 0.1);
    refused(d);
    d = spout(1, 0.1);
    d.nextIn = 0.5;  // after the interval
    refused(d);
    w.setDroppers({spout(1, 0.1)});
    EXPECT_THROW(w.setBox(0.4, 1.0), InvalidArgument);  // the spout would be outside
    EXPECT_EQ(w.def().width, 1.0);
}

TEST(Dropper, ResultsAreTheSameForEveryThreadCountAndForACopy) {
    for (const StepMode mode : {StepMode::Discrete, StepMode::Substep, StepMode::Exact}) {
        SCOPED_TRACE(toString(mode));
        World one = box(mode);
        Dropper d = spout(10, 0.1);
        d.spread = 0.05;
        one.setDroppers({d});
        one.setThreads(1);
        World two = one;
        two.setThreads(2);
        for (int k = 0; k < 50; ++k) {
            one.step(0.01);
            two.step(0.01);
        }
        World copy = one;
        for (int k = 0; k < 50; ++k) {
            one.step(0.01);
            two.step(0.01);
            copy.step(0.01);
        }
        EXPECT_EQ(one.droppers(), two.droppers());
        EXPECT_EQ(one.particles().x, two.particles().x);
        EXPECT_EQ(one.particles().vy, two.particles().vy);
        EXPECT_EQ(one.particles().x, copy.particles().x);
        EXPECT_EQ(one.droppers(), copy.droppers());
        EXPECT_EQ(one.size(), 10u);
    }
}

}  // namespace
}  // namespace psb
