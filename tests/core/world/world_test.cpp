// World: particle management through stable ids, argument checks, picking, stepping modes.

#include <gtest/gtest.h>

#include <limits>
#include <random>

#include <particle_sandbox/error.hpp>
#include <particle_sandbox/world.hpp>

#include "test_util.hpp"

namespace psb {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(World, RemovingOneParticleKeepsEveryOtherIdValid) {
    World w;
    std::vector<ParticleId> ids;
    for (int k = 0; k < 10; ++k) {
        ids.push_back(w.add({.position = {10.0 * k + 5, 5.0}, .mass = 1.0 + k}));
    }
    EXPECT_TRUE(w.remove(ids[3]));
    EXPECT_TRUE(w.remove(ids[0]));
    EXPECT_FALSE(w.contains(ids[3]));
    EXPECT_FALSE(w.remove(ids[3]));
    for (int k : {1, 2, 4, 5, 6, 7, 8, 9}) {
        ASSERT_TRUE(w.contains(ids[k]));
        EXPECT_EQ(w.get(ids[k]).mass, 1.0 + k);
        EXPECT_EQ(w.get(ids[k]).position.x(), 10.0 * k + 5);
    }
    EXPECT_EQ(w.size(), 8u);
}

TEST(World, ParticleNumbersCountFromOneAndEmptiedBoxesStartAgainAtOne) {
    // The numbers people read (particleNumber): 1..6 in the order added; stable while they
    // live; a box emptied one particle at a time and given two new balls reads 1 and 2, not
    // the numbers the last removed ones had (a teacher saw #4 and #6 in a two-ball scene).
    World w;
    std::vector<ParticleId> ids;
    for (int k = 0; k < 6; ++k)
        ids.push_back(w.add({.position = {10.0 * k + 5, 5.0}}));
    for (int k = 0; k < 6; ++k)
        EXPECT_EQ(particleNumber(ids[k]), static_cast<std::uint64_t>(k + 1));
    w.remove(ids[1]);
    w.remove(ids[4]);
    EXPECT_EQ(particleNumber(ids[5]), 6u) << "kept while it lives";
    for (const int k : {5, 0, 3, 2})
        w.remove(ids[k]);
    const ParticleId a = w.add({.position = {5.0, 5.0}});
    const ParticleId b = w.add({.position = {50.0, 5.0}});
    EXPECT_EQ(particleNumber(a), 1u);
    EXPECT_EQ(particleNumber(b), 2u);
    World copy = w;  // an undo history's copy numbers them alike
    EXPECT_EQ(particleNumber(copy.ids().front()), 1u);
}

TEST(World, StaleIdNeverAliasesAParticleThatReusesItsSlot) {
    World w;
    const ParticleId a = w.add({.position = {5.0, 5.0}});
    w.remove(a);
    const ParticleId b = w.add({.position = {50.0, 50.0}});
    EXPECT_EQ(a.slot, b.slot);
    EXPECT_FALSE(w.contains(a));
    EXPECT_TRUE(w.contains(b));
    EXPECT_THROW((void)w.get(a), InvalidArgument);
}

TEST(World, ClearInvalidatesOldIds) {
    World w;
    const ParticleId a = w.add({.position = {5.0, 5.0}});
    w.clear();
    EXPECT_EQ(w.size(), 0u);
    EXPECT_FALSE(w.contains(a));
    const ParticleId b = w.add({.position = {5.0, 5.0}});
    EXPECT_FALSE(w.contains(a));
    EXPECT_TRUE(w.contains(b));
}

TEST(World, RejectsBadParticlesAndLeavesTheWorldUnchanged) {
    World w;
    w.add({.position = {5.0, 5.0}});
    const ParticleDef bad[] = {
        {.position = {kNaN, 1.0}},
        {.velocity = {1.0, kInf}},
        {.mass = 0.0},
        {.mass = -1.0},
        {.mass = kNaN},
        {.radius = 0.0},
        {.radius = -2.0},
        {.radius = kInf},
    };
    for (const ParticleDef& d : bad)
        EXPECT_THROW(w.add(d), InvalidArgument);
    EXPECT_EQ(w.size(), 1u);
}

TEST(World, ErrorMessagesNameTheArgumentAndValue) {
    World w;
    try {
        w.add({.mass = -3.0});
        FAIL() << "no throw";
    } catch (const InvalidArgument& e) {
        EXPECT_NE(std::string(e.what()).find("mass"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("-3"), std::string::npos) << e.what();
    }
}

TEST(World, RejectsBadParameters) {
    World w;
    EXPECT_THROW(w.setRestitution(1.5), InvalidArgument);
    EXPECT_THROW(w.setRestitution(-0.1), InvalidArgument);
    EXPECT_THROW(w.setRestitution(kNaN), InvalidArgument);
    EXPECT_THROW(w.setFriction(-1.0), InvalidArgument);
    EXPECT_THROW(w.setGravity({0.0, kNaN}), InvalidArgument);
    EXPECT_THROW(w.setBox(0.0, 10.0), InvalidArgument);
    EXPECT_THROW(w.step(0.0), InvalidArgument);
    EXPECT_THROW(w.step(-1.0), InvalidArgument);
    EXPECT_THROW(w.step(kInf), InvalidArgument);
    EXPECT_THROW(w.step(kNaN), InvalidArgument);  // the step length is step()'s alone
    EXPECT_THROW(w.setSolver({.substeps = 0}), InvalidArgument);
    EXPECT_EQ(w.def().restitution, 1.0);
    EXPECT_THROW(World(WorldDef{.width = -1.0}), InvalidArgument);
}

TEST(World, PickReturnsTheTopmostParticleUnderThePoint) {
    World w;
    const ParticleId low = w.add({.position = {50.0, 50.0}, .radius = 10.0});
    const ParticleId top = w.add({.position = {55.0, 50.0}, .radius = 10.0});
    EXPECT_EQ(w.pick({52.0, 50.0}), top);
    EXPECT_EQ(w.pick({41.0, 50.0}), low);
    EXPECT_EQ(w.pick({50.0, 59.99}), low);  // inside the rim: world units, any zoom
    EXPECT_FALSE(w.pick({100.0, 100.0}).has_value());
    EXPECT_FALSE(w.pick({kNaN, 0.0}).has_value());
}

TEST(World, GravityAcceleratesDownwardAndIsSkippedWhenZero) {
    World w(WorldDef{.width = 1000.0, .height = 1000.0, .gravity = {0.0, 9.81}});
    const ParticleId p = w.add({.position = {500.0, 100.0}});
    for (int k = 0; k < 100; ++k)
        w.step(0.01);
    EXPECT_NEAR(w.get(p).velocity.y(), 9.81, 1e-12);
    EXPECT_GT(w.profile().ms("gravity"), 0.0);

    World still;
    still.add({.position = {50.0, 50.0}});
    still.step(0.01);
    EXPECT_EQ(still.profile().ms("gravity"), 0.0);
}

TEST(World, SubstepsOfAFreeFlightLandWhereOneStepDoes) {
    World one, many;
    many.setSolver({.mode = StepMode::Substep, .substeps = 8});
    const ParticleId a = one.add({.position = {100.0, 100.0}, .velocity = {3.0, -2.0}});
    const ParticleId b = many.add({.position = {100.0, 100.0}, .velocity = {3.0, -2.0}});
    one.step(0.5);
    many.step(0.5);
    EXPECT_NEAR((one.get(a).position - many.get(b).position).norm(), 0.0, 1e-12);
    EXPECT_EQ(many.counters().steps, 8u);
    EXPECT_DOUBLE_EQ(many.time(), 0.5);
}

TEST(World, ExactModeAndEveryBroadphaseAreAccepted) {
    World w;
    EXPECT_NO_THROW(w.setSolver({.mode = StepMode::Exact}));  // exact-mode tests: exact_*_test
    for (BroadPhaseKind k : {BroadPhaseKind::Auto, BroadPhaseKind::AllPairs, BroadPhaseKind::Grid,
                             BroadPhaseKind::Quadtree}) {
        EXPECT_NO_THROW(w.setSolver({.broadphase = k})) << toString(k);
    }
}

TEST(World, CopyIsIndependent) {
    World a;
    const ParticleId p = a.add({.position = {10.0, 10.0}, .velocity = {1.0, 0.0}});
    World b = a;
    b.step(1.0);
    EXPECT_EQ(a.get(p).position.x(), 10.0);
    EXPECT_EQ(b.get(p).position.x(), 11.0);
}

// A dense gas in which every step has collisions: what a copy must carry is then exercised.
// Stepped by kGasDt.
constexpr double kGasDt = 0.01;
World denseGas(StepMode mode) {
    WorldDef def;
    def.width = def.height = 60.0;
    def.restitution = 0.9;
    World w(def, {.mode = mode, .substeps = 3});
    w.setThreads(1);
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(1.0, 59.0);
    std::normal_distribution<double> v(0.0, 4.0);
    for (int k = 0; k < 400; ++k) {
        w.add({.position = {u(rng), u(rng)},
               .velocity = {v(rng), v(rng)},
               .radius = 0.5 + 0.002 * k});
    }
    return w;
}

TEST(World, ACopyStepsBitForBitLikeTheOriginalInEveryMode) {
    for (StepMode mode : {StepMode::Discrete, StepMode::Substep, StepMode::Exact}) {
        World a = denseGas(mode);
        for (int k = 0; k < 30; ++k)
            a.step(kGasDt);
        World b = a;
        EXPECT_EQ(test::stateHash(b), test::stateHash(a)) << toString(mode);
        for (int k = 0; k < 60; ++k) {
            a.step(kGasDt);
            b.step(kGasDt);
        }
        EXPECT_GT(a.counters().collisions, 100u) << toString(mode);
        EXPECT_EQ(test::stateHash(b), test::stateHash(a)) << toString(mode);
        EXPECT_EQ(b.time(), a.time());
        // Assignment too, onto a world that had stepped in another mode.
        World c = denseGas(StepMode::Discrete);
        c.step(kGasDt);
        c = a;
        a.step(kGasDt);
        c.step(kGasDt);
        EXPECT_EQ(test::stateHash(c), test::stateHash(a)) << toString(mode);
    }
}

TEST(World, DroppingTheEventStateKeepsTheParticlesAndFreesItsBytes) {
    World w = denseGas(StepMode::Exact);
    const std::size_t bare = w.stateBytes();
    for (int k = 0; k < 10; ++k)
        w.step(kGasDt);
    const std::uint64_t hash = test::stateHash(w);
    ASSERT_GT(w.stateBytes(), bare + 400u * 128u);
    w.dropEventState();
    EXPECT_EQ(test::stateHash(w), hash);
    EXPECT_EQ(w.stateBytes(), bare);
    // It steps on like a world just edited: the events are rebuilt from the particles.
    World edited = w;
    for (int k = 0; k < 20; ++k) {
        w.step(kGasDt);
        edited.step(kGasDt);
    }
    EXPECT_EQ(test::stateHash(w), test::stateHash(edited));
    EXPECT_GT(w.counters().collisions, 0u);
}

TEST(World, StateBytesCountTheExactModesEventState) {
    World w = denseGas(StepMode::Exact);
    const std::size_t before = w.stateBytes();
    EXPECT_GE(before, 400u * (7 * sizeof(double) + sizeof(Color) + sizeof(ParticleId)));
    w.step(kGasDt);
    EXPECT_GT(w.stateBytes(), before + 400u * 128u);  // two 64-byte lines per particle at least
}

TEST(SolverSettings, NamesRoundTrip) {
    for (StepMode m : {StepMode::Discrete, StepMode::Substep, StepMode::Exact}) {
        EXPECT_EQ(parseStepMode(toString(m)), m);
    }
    for (BroadPhaseKind k : {BroadPhaseKind::Auto, BroadPhaseKind::AllPairs, BroadPhaseKind::Grid,
                             BroadPhaseKind::Quadtree}) {
        EXPECT_EQ(parseBroadPhase(toString(k)), k);
    }
    EXPECT_FALSE(parseStepMode("Discrete").has_value());
    EXPECT_FALSE(parseBroadPhase("octree").has_value());
}

}  // namespace
}  // namespace psb
