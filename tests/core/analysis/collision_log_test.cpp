// The world's record of collisions (collision_log.hpp), in every step mode, against the
// textbook one-dimensional collision: for masses m1, m2 with velocities u1, u2 along a line and
// restitution e,
//     v1 = (m1 u1 + m2 u2 + m2 e (u2 − u1)) / (m1 + m2),
//     v2 = (m1 u1 + m2 u2 + m1 e (u1 − u2)) / (m1 + m2),
// the impulse on 1 is m1 (v1 − u1) and on 2 its opposite.

#include <gtest/gtest.h>

#include <particle_sandbox/collision_log.hpp>
#include <particle_sandbox/scene_builders.hpp>
#include <particle_sandbox/world.hpp>

#include "test_util.hpp"

namespace psb {
namespace {

struct ModeCase {
    const char* name;
    StepMode mode;
    int substeps;
};

const ModeCase kModes[] = {
    {"discrete", StepMode::Discrete, 1},
    {"substep", StepMode::Substep, 4},
    {"exact", StepMode::Exact, 1},
};

SolverSettings solverFor(const ModeCase& m) {
    SolverSettings s;
    s.mode = m.mode;
    s.substeps = m.substeps;
    return s;
}

constexpr double kDt = 0.01;

/// Two discs on the line y = 5 heading for each other: 1 kg at 2 m/s from x = 3, 3 kg at −1 m/s
/// from x = 6, radii 0.5 m. They touch when the 2 m gap has closed at 3 m/s: t = 2/3 s.
struct HeadOn {
    World world;
    ParticleId one, two;
};

HeadOn headOn(const ModeCase& m, double e) {
    WorldDef def;
    def.width = 10.0;
    def.height = 10.0;
    def.walls = false;
    def.restitution = e;
    HeadOn h{World(def, solverFor(m)), {}, {}};
    h.world.setThreads(1);
    h.one = h.world.add(
        {.position = Vec2(3.0, 5.0), .velocity = Vec2(2.0, 0.0), .mass = 1.0, .radius = 0.5});
    h.two = h.world.add(
        {.position = Vec2(6.0, 5.0), .velocity = Vec2(-1.0, 0.0), .mass = 3.0, .radius = 0.5});
    return h;
}

void expectVec(const Vec2& got, double x, double y, const char* what) {
    EXPECT_NEAR(got.x(), x, 1e-12) << what;
    EXPECT_NEAR(got.y(), y, 1e-12) << what;
}

class CollisionLogModes : public ::testing::TestWithParam<ModeCase> {};

void checkHeadOn(const ModeCase& m, double e) {
    HeadOn h = headOn(m, e);
    h.world.recordCollisions();
    for (int k = 0; k < 150; ++k)
        h.world.step(kDt);
    const std::vector<Collision> log = h.world.takeCollisions();
    ASSERT_EQ(log.size(), 1u) << m.name;
    Collision c = log[0];
    ASSERT_EQ(c.with, Collision::With::Particle);
    // Seen from particle one, whichever the stepper named first.
    if (c.a != h.one) {
        std::swap(c.a, c.b);
        std::swap(c.aBefore, c.bBefore);
        std::swap(c.aAfter, c.bAfter);
        c.impulse = -c.impulse;
    }
    EXPECT_EQ(c.a, h.one);
    EXPECT_EQ(c.b, h.two);
    const double m1 = 1.0, m2 = 3.0, u1 = 2.0, u2 = -1.0;
    const double v1 = (m1 * u1 + m2 * u2 + m2 * e * (u2 - u1)) / (m1 + m2);
    const double v2 = (m1 * u1 + m2 * u2 + m1 * e * (u1 - u2)) / (m1 + m2);
    expectVec(c.aBefore, u1, 0.0, "one before");
    expectVec(c.bBefore, u2, 0.0, "two before");
    expectVec(c.aAfter, v1, 0.0, "one after");
    expectVec(c.bAfter, v2, 0.0, "two after");
    expectVec(c.impulse, m1 * (v1 - u1), 0.0, "impulse on one = m1 dv1");
    EXPECT_NEAR(c.impulse.x(), -m2 * (v2 - u2), 1e-12) << "impulse on two = m2 dv2 = -impulse";
    EXPECT_NEAR(m1 * c.aAfter.x() + m2 * c.bAfter.x(), m1 * u1 + m2 * u2, 1e-12) << "momentum";
    // The exact mode records the instant of contact; the discrete ones the end of the (sub)step
    // that found the overlap.
    const double touch = 2.0 / 3.0;
    if (m.mode == StepMode::Exact) {
        EXPECT_NEAR(c.time, touch, 1e-12);
    } else {
        EXPECT_GE(c.time, touch);
        EXPECT_LE(c.time, touch + kDt / m.substeps + 1e-12);
    }
    // What the world did agrees with the record.
    EXPECT_NEAR(h.world.get(h.one).velocity.x(), v1, 1e-12);
    EXPECT_NEAR(h.world.get(h.two).velocity.x(), v2, 1e-12);
}

TEST_P(CollisionLogModes, HeadOnElasticMatchesTheTextbook) {
    checkHeadOn(GetParam(), 1.0);
}

TEST_P(CollisionLogModes, HeadOnInelasticMatchesTheTextbook) {
    checkHeadOn(GetParam(), 0.5);
}

TEST_P(CollisionLogModes, HeadOnPerfectlyInelasticMovesTogether) {
    checkHeadOn(GetParam(), 0.0);
}

TEST_P(CollisionLogModes, WallReboundNamesTheWallAndItsImpulse) {
    const ModeCase m = GetParam();
    WorldDef def;
    def.width = 10.0;
    def.height = 10.0;
    def.restitution = 0.5;
    World w(def, solverFor(m));
    const ParticleId p =
        w.add({.position = Vec2(8.0, 5.0), .velocity = Vec2(3.0, 0.0), .mass = 2.0, .radius = 0.5});
    w.recordCollisions();
    for (int k = 0; k < 60; ++k)
        w.step(kDt);
    const std::vector<Collision> log = w.takeCollisions();
    ASSERT_EQ(log.size(), 1u);
    const Collision& c = log[0];
    EXPECT_EQ(c.with, Collision::With::Wall);
    EXPECT_EQ(c.wall(), WallSide::Right);
    EXPECT_EQ(c.a, p);
    EXPECT_TRUE(c.b.isNull());
    expectVec(c.aBefore, 3.0, 0.0, "before");
    expectVec(c.aAfter, -1.5, 0.0, "after: -e u");
    expectVec(c.impulse, 2.0 * (-1.5 - 3.0), 0.0, "impulse m dv");
    // 1.5 m to the wall at 3 m/s.
    if (m.mode == StepMode::Exact)
        EXPECT_NEAR(c.time, 0.5, 1e-12);
    else
        EXPECT_NEAR(c.time, 0.5, kDt + 1e-12);
}

TEST_P(CollisionLogModes, PegReboundNamesTheObstacle) {
    const ModeCase m = GetParam();
    WorldDef def;
    def.width = 10.0;
    def.height = 10.0;
    def.restitution = 1.0;
    def.obstacles = {Obstacle::peg(Vec2(2.0, 2.0), 0.5), Obstacle::peg(Vec2(5.0, 8.0), 0.5)};
    World w(def, solverFor(m));
    const ParticleId p =
        w.add({.position = Vec2(5.0, 5.0), .velocity = Vec2(0.0, 2.0), .mass = 1.5, .radius = 0.5});
    w.recordCollisions();
    for (int k = 0; k < 150; ++k)  // 1.5 m to the peg's surface at 2 m/s
        w.step(kDt);
    const std::vector<Collision> log = w.takeCollisions();
    ASSERT_GE(log.size(), 1u);
    const Collision& c = log[0];
    EXPECT_EQ(c.with, Collision::With::Obstacle);
    EXPECT_EQ(c.where, 1u);
    EXPECT_EQ(c.a, p);
    expectVec(c.aBefore, 0.0, 2.0, "before");
    expectVec(c.aAfter, 0.0, -2.0, "after");
    expectVec(c.impulse, 0.0, -6.0, "impulse m dv");
}

TEST_P(CollisionLogModes, ChosenParticlesOnly) {
    const ModeCase m = GetParam();
    Scene gas = scenes::gas({.count = 200, .packing = 0.2});
    gas.solver = solverFor(m);
    World w = makeWorld(gas);
    w.setThreads(1);
    const ParticleId chosen = w.ids()[17];
    w.recordCollisions(CollisionLog({chosen}));
    for (int k = 0; k < 200; ++k)
        w.step(kDt * 10);
    const std::vector<Collision> log = w.takeCollisions();
    ASSERT_FALSE(log.empty()) << "the chosen particle collides in 20 s of a dense gas";
    for (const Collision& c : log)
        EXPECT_TRUE(c.involves(chosen));
    for (std::size_t k = 1; k < log.size(); ++k)
        EXPECT_LE(log[k - 1].time, log[k].time) << "in the order they happened";
    EXPECT_TRUE(w.takeCollisions().empty()) << "take() empties the log";
    EXPECT_TRUE(w.recordingCollisions());
}

TEST_P(CollisionLogModes, RecordingChangesNoBitOfTheResults) {
    const ModeCase m = GetParam();
    Scene gas = scenes::gas({.count = 500, .packing = 0.2});
    gas.solver = solverFor(m);
    gas.world.restitution = 0.9;
    gas.world.gravity = Vec2(0.0, 9.81);
    gas.world.friction = 0.3;
    gas.world.obstacles = {
        Obstacle::peg(Vec2(0.5 * gas.world.width, 0.5 * gas.world.height), 0.05 * gas.world.width)};
    World off = makeWorld(gas);
    World on = makeWorld(gas);
    on.recordCollisions();
    std::size_t pairs = 0, walls = 0, obstacles = 0;
    for (int k = 0; k < 40; ++k) {
        off.step(kDt * 10);
        on.step(kDt * 10);
        for (const Collision& c : on.takeCollisions()) {
            pairs += c.with == Collision::With::Particle;
            walls += c.with == Collision::With::Wall;
            obstacles += c.with == Collision::With::Obstacle;
        }
    }
    EXPECT_EQ(test::stateHash(on), test::stateHash(off));
    EXPECT_EQ(pairs, on.counters().collisions);
    EXPECT_GT(walls, 0u);
    EXPECT_GT(obstacles, 0u);
}

TEST_P(CollisionLogModes, MomentumOfEveryRecordedPairIsConserved) {
    const ModeCase m = GetParam();
    Scene gas = scenes::gas({.count = 300, .radius = 1.0, .maxRadius = 3.0, .packing = 0.25});
    gas.solver = solverFor(m);
    gas.world.restitution = 0.7;
    World w = makeWorld(gas);
    w.recordCollisions();
    std::size_t checked = 0;
    for (int k = 0; k < 50; ++k) {
        w.step(kDt * 10);
        for (const Collision& c : w.takeCollisions()) {
            if (c.with != Collision::With::Particle) continue;
            const double ma = w.get(c.a).mass, mb = w.get(c.b).mass;
            const Vec2 before = ma * c.aBefore + mb * c.bBefore;
            const Vec2 after = ma * c.aAfter + mb * c.bAfter;
            EXPECT_LT((after - before).norm(), 1e-9 * (1.0 + before.norm()));
            EXPECT_LT((c.impulse - ma * (c.aAfter - c.aBefore)).norm(), 1e-9);
            EXPECT_LT((c.impulse + mb * (c.bAfter - c.bBefore)).norm(), 1e-9);
            ++checked;
        }
    }
    EXPECT_GT(checked, 100u);
}

INSTANTIATE_TEST_SUITE_P(EveryMode, CollisionLogModes, ::testing::ValuesIn(kModes),
                         [](const auto& param) { return std::string(param.param.name); });

TEST(CollisionLog, OffByDefaultAndStops) {
    HeadOn h = headOn(kModes[0], 1.0);
    EXPECT_FALSE(h.world.recordingCollisions());
    EXPECT_EQ(h.world.collisionLog(), nullptr);
    h.world.recordCollisions(CollisionLog({h.two}));
    ASSERT_NE(h.world.collisionLog(), nullptr);
    EXPECT_FALSE(h.world.collisionLog()->keepsAll());
    h.world.stopRecordingCollisions();
    for (int k = 0; k < 150; ++k)
        h.world.step(kDt);
    EXPECT_TRUE(h.world.takeCollisions().empty());
    EXPECT_EQ(h.world.counters().collisions, 1u);
}

TEST(CollisionLog, ACopyCarriesTheLogAndRecordsOnItsOwn) {
    HeadOn h = headOn(kModes[2], 1.0);
    h.world.recordCollisions();
    for (int k = 0; k < 50; ++k)
        h.world.step(kDt);
    World copy = h.world;
    for (int k = 0; k < 50; ++k) {
        h.world.step(kDt);
        copy.step(kDt);
    }
    EXPECT_EQ(h.world.takeCollisions().size(), 1u);
    EXPECT_EQ(copy.takeCollisions().size(), 1u);
}

TEST(CollisionLog, AnEmptyChoiceKeepsNothing) {
    CollisionLog log(std::vector<ParticleId>{});
    Collision c;
    c.a = ParticleId{3, 0};
    log.add(c);
    EXPECT_TRUE(log.records().empty());
    CollisionLog all;
    all.add(c);
    EXPECT_EQ(all.records().size(), 1u);
    CollisionLog some({ParticleId{5, 1}, ParticleId{3, 0}, ParticleId{5, 1}});
    EXPECT_EQ(some.chosen().size(), 2u);
    EXPECT_TRUE(some.chosen(ParticleId{3, 0}));
    EXPECT_FALSE(some.chosen(ParticleId{3, 1})) << "another generation is another particle";
    c.b = ParticleId{5, 1};
    c.a = ParticleId{9, 0};
    some.add(c);
    EXPECT_EQ(some.records().size(), 1u) << "kept for b";
}

}  // namespace
}  // namespace psb
