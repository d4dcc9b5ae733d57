// The edit prompt's text handling and applyEdit's validation: all or nothing, never throwing.

#include <gtest/gtest.h>

#include <cmath>

#include "core/test_util.hpp"
#include "session/edit_prompt.hpp"
#include "session/particle_edit.hpp"

namespace psb::app {
namespace {

using Texts = std::array<std::string, kEditFields>;

constexpr double kDt = 0.01;  ///< the frame length the worlds here are stepped by

World boxWorld(StepMode mode = StepMode::Discrete) {
    SolverSettings s;
    s.mode = mode;
    return World(WorldDef{}, s);  // 700 m × 700 m, walls on, no gravity
}

ParticleId addAt(World& w, Vec2 pos, double radius = 10.0, double mass = 2.0,
                 Vec2 vel = Vec2::Zero()) {
    ParticleDef d;
    d.position = pos;
    d.velocity = vel;
    d.radius = radius;
    d.mass = mass;
    return w.add(d);
}

TEST(EditPrompt, OpensWithTheParticlesValuesOnTheMassField) {
    World w = boxWorld();
    const ParticleId id = addAt(w, {100, 100}, 12.5, 18.0, {-60, 240});
    EditPrompt p;
    p.open(w.get(id));
    EXPECT_TRUE(p.active());
    EXPECT_EQ(p.target(), id);
    EXPECT_EQ(p.field(), EditField::Mass);
    EXPECT_EQ(p.texts(), (Texts{"18", "12.5", "-60", "240", "0", "0.5"}));
}

TEST(EditPrompt, TypingReplacesAFreshFieldThenAppends) {
    World w = boxWorld();
    EditPrompt p;
    p.open(w.get(addAt(w, {100, 100})));
    p.type("2");
    p.type("5");
    EXPECT_EQ(p.text(EditField::Mass), "25");
    p.backspace();
    p.type("0.5");
    EXPECT_EQ(p.text(EditField::Mass), "20.5");
    p.nextField();
    EXPECT_EQ(p.field(), EditField::Radius);
    p.type("7");
    EXPECT_EQ(p.text(EditField::Radius), "7");
    EXPECT_EQ(p.text(EditField::Mass), "20.5");  // the other field keeps its text
}

TEST(EditPrompt, TabCyclesThroughTheSixFieldsBothWays) {
    World w = boxWorld();
    EditPrompt p;
    p.open(w.get(addAt(w, {100, 100})));
    const EditField order[] = {EditField::Radius, EditField::Vx,      EditField::Vy,
                               EditField::Omega,  EditField::Inertia, EditField::Mass};
    for (const EditField f : order) {
        p.nextField();
        EXPECT_EQ(p.field(), f);
    }
    p.previousField();
    EXPECT_EQ(p.field(), EditField::Inertia);
}

TEST(EditPrompt, DropsControlCharactersAndStopsAtTheLengthLimit) {
    World w = boxWorld();
    EditPrompt p;
    p.open(w.get(addAt(w, {100, 100})));
    p.type("1\t2\n\x7f");
    EXPECT_EQ(p.text(EditField::Mass), "12");
    p.type(std::string(100, '9'));
    EXPECT_EQ(p.text(EditField::Mass).size(), EditPrompt::kMaxLength);
}

TEST(ApplyEdit, SetsAllSixValues) {
    World w = boxWorld();
    const ParticleId id = addAt(w, {300, 300}, 10.0, 2.0);
    const EditResult r = applyEdit(w, id, {"25", " 12 ", "+1.5e2", "-40", "-2.5", "0.4"});
    ASSERT_TRUE(r.applied) << r.message;
    const Particle p = w.get(id);
    EXPECT_DOUBLE_EQ(p.angularVelocity, -2.5);
    EXPECT_DOUBLE_EQ(p.inertiaFactor, 0.4);
    EXPECT_NE(r.message.find("omega -2.5 rad/s, k 0.4"), std::string::npos) << r.message;
    EXPECT_DOUBLE_EQ(p.mass, 25.0);
    EXPECT_DOUBLE_EQ(p.radius, 12.0);
    EXPECT_EQ(p.velocity, Vec2(150.0, -40.0));
    EXPECT_EQ(p.position, Vec2(300.0, 300.0));
    EXPECT_NE(r.message.find("mass 25 kg"), std::string::npos) << r.message;
}

struct Refusal {
    Texts texts;
    const char* says;
};

class ApplyEditRefuses : public ::testing::TestWithParam<Refusal> {};

TEST_P(ApplyEditRefuses, AndChangesNothing) {
    World w = boxWorld();
    addAt(w, {100, 100}, 20.0);  // a neighbour 60 m to the left of the edited particle
    const ParticleId id = addAt(w, {160, 100}, 10.0, 2.0, {3, 4});
    const std::uint64_t before = test::stateHash(w);
    const Particle old = w.get(id);
    const EditResult r = applyEdit(w, id, GetParam().texts);
    EXPECT_FALSE(r.applied);
    EXPECT_NE(r.message.find(GetParam().says), std::string::npos) << r.message;
    EXPECT_EQ(test::stateHash(w), before);
    EXPECT_EQ(w.get(id).mass, old.mass);
    EXPECT_EQ(w.get(id).radius, old.radius);
}

INSTANTIATE_TEST_SUITE_P(
    BadValues, ApplyEditRefuses,
    ::testing::Values(
        Refusal{{"nan", "10", "0", "0", "0", "0.5"}, "mass: must be a finite number"},
        Refusal{{"2", "inf", "0", "0", "0", "0.5"}, "radius: must be a finite number"},
        Refusal{{"2", "10", "-infinity", "0", "0", "0.5"}, "vx: must be a finite number"},
        Refusal{{"2", "10", "0", "1e999", "0", "0.5"}, "vy: 1e999 is out of range"},
        Refusal{{"abc", "10", "0", "0", "0", "0.5"}, "mass: 'abc' is not a number"},
        Refusal{{"12kg", "10", "0", "0", "0", "0.5"}, "mass: '12kg' is not a number"},
        Refusal{{"", "10", "0", "0", "0", "0.5"}, "mass: empty"},
        Refusal{{"0", "10", "0", "0", "0", "0.5"}, "mass: must be > 0 kg"},
        Refusal{{"-3", "10", "0", "0", "0", "0.5"}, "mass: must be > 0 kg"},
        Refusal{{"1e-320", "10", "0", "0", "0", "0.5"}, "mass: must be > 0 kg"},
        Refusal{{"2", "0", "0", "0", "0", "0.5"}, "radius: must be > 0 m"},
        Refusal{{"2", "-1", "0", "0", "0", "0.5"}, "radius: must be > 0 m"},
        Refusal{{"2", "400", "0", "0", "0", "0.5"}, "does not fit in the 700 x 700 m box"},
        // 45 m at x = 160 reaches x = 115, past the neighbour's rim at 120.
        Refusal{{"2", "45", "0", "0", "0", "0.5"}, "would overlap the particle at [100.00"},
        Refusal{{"2", "10", "8e5", "0", "0", "0.5"}, "faster than 700000 m/s"},
        Refusal{{"2", "10", "0", "0", "1e5", "0.5"},
                "omega: the rim would move at 1e+06 m/s, faster than 700000 m/s"},
        Refusal{{"2", "10", "0", "0", "0", "0"}, "k: the inertia factor must be"},
        Refusal{{"2", "10", "0", "0", "0", "1.01"}, "k: the inertia factor must be"},
        Refusal{{"2", "10", "0", "0", "nan", "0.5"}, "omega: must be a finite"},
        Refusal{{"2", "10", "0", "0", "0", "x"}, "k: 'x' is not a number"},
        Refusal{{"1e300", "10", "1e5", "0", "0", "0.5"}, "kinetic energy would overflow"}));

TEST(ApplyEdit, ItsMessageHasThreeFiguresAndVectorsNoLineBreaksIn) {
    // "radius 0.142857 m", and "[-1, 0]" wrapped as "[-1," over "0]" in the message band.
    World w = boxWorld();
    const ParticleId id = addAt(w, {300, 300}, 10.0, 2.0);
    const EditResult r = applyEdit(w, id, {"1", "0.142857142857", "-1", "0", "0", "0.5"});
    ASSERT_TRUE(r.applied) << r.message;
    EXPECT_NE(r.message.find("radius 0.143 m"), std::string::npos) << r.message;
    EXPECT_NE(r.message.find("velocity [-1,\u00a00] m/s"), std::string::npos) << r.message;
}

TEST(ApplyEdit, ARadiusThatReachesPastAWallMovesTheCentreInward) {
    World w = boxWorld();
    const ParticleId id = addAt(w, {690, 350}, 10.0);  // touching the right wall
    const EditResult r = applyEdit(w, id, {"2", "30", "0", "0", "0", "0.5"});
    ASSERT_TRUE(r.applied) << r.message;
    EXPECT_NEAR(w.get(id).position.x(), 670.0, 1e-12);
    EXPECT_NEAR(w.get(id).position.y(), 350.0, 1e-12);
    EXPECT_NE(r.message.find("moved to [670.00,\u00a0350.00] m"), std::string::npos) << r.message;
}

TEST(ApplyEdit, AMoveInwardThatWouldOverlapIsRefused) {
    World w = boxWorld();
    const ParticleId id = addAt(w, {690, 350}, 10.0);
    addAt(w, {640, 350}, 10.0);  // 50 m inward: room for 10 m, not for a 30 m disc at 670
    const EditResult r = applyEdit(w, id, {"2", "30", "0", "0", "0", "0.5"});
    EXPECT_FALSE(r.applied);
    EXPECT_NE(r.message.find("overlap the particle at [640.00, 350.00]"), std::string::npos)
        << r.message;
    EXPECT_EQ(w.get(id).position, Vec2(690, 350));
}

TEST(ApplyEdit, ShrinkingAnOverlappingParticleIsAllowed) {
    // Discrete steps leave small overlaps; a smaller radius only reduces them.
    World w = boxWorld();
    addAt(w, {100, 100}, 10.0);
    const ParticleId id = addAt(w, {118, 100}, 10.0);  // 2 m overlap
    EXPECT_TRUE(applyEdit(w, id, {"2", "9", "0", "0", "0", "0.5"}).applied);
    EXPECT_DOUBLE_EQ(w.get(id).radius, 9.0);
}

TEST(ApplyEdit, ANeighbourJustTouchingIsNotAnOverlap) {
    World w = boxWorld();
    addAt(w, {100, 100}, 10.0);
    const ParticleId id = addAt(w, {130, 100}, 10.0);
    EXPECT_TRUE(
        applyEdit(w, id, {"2", "20", "0", "0", "0", "0.5"}).applied);  // rims meet at x = 110
}

TEST(ApplyEdit, KeepsAHeldParticleKinematic) {
    World w = boxWorld();
    const ParticleId id = addAt(w, {300, 300});
    w.setKinematic(id, true);
    ASSERT_TRUE(applyEdit(w, id, {"50", "10", "0", "0", "0", "0.5"}).applied);
    EXPECT_TRUE(w.isKinematic(id));
    EXPECT_DOUBLE_EQ(w.get(id).mass, 50.0);
}

TEST(ApplyEdit, RefusesAParticleThatIsGone) {
    World w = boxWorld();
    const ParticleId id = addAt(w, {300, 300});
    w.remove(id);
    const EditResult r = applyEdit(w, id, {"2", "10", "0", "0", "0", "0.5"});
    EXPECT_FALSE(r.applied);
    EXPECT_NE(r.message.find("no longer exists"), std::string::npos);
}

TEST(ApplyEdit, InExactModeTheEventQueueFollowsTheEdit) {
    // Two exact-mode worlds in the same state, one edited between steps, the other built
    // fresh with the edited values: a stale event queue in the first (a collision predicted
    // with the old velocity or radius) would make them part.
    const auto build = [](Vec2 velocity, double radius) {
        World w = boxWorld(StepMode::Exact);
        addAt(w, {100, 350}, 10.0, 2.0, {50, 0});
        addAt(w, {400, 350}, radius, 3.0, velocity);
        addAt(w, {250, 200}, 15.0, 1.0, {0, 40});
        return w;
    };
    World edited = build({0, 0}, 10.0);
    for (int k = 0; k < 50; ++k)
        edited.step(kDt);
    const ParticleId target = edited.ids()[1];
    const Particle now = edited.get(target);
    // Toward the first particle, larger: the collision comes much earlier than predicted.
    const EditResult r = applyEdit(edited, target, {"3", "20", "-120", "0", "0", "0.5"});
    ASSERT_TRUE(r.applied) << r.message;

    World fresh = boxWorld(StepMode::Exact);
    for (const ParticleId id : edited.ids()) {
        const Particle p = edited.get(id);
        addAt(fresh, p.position, p.radius, p.mass, p.velocity);
    }
    EXPECT_EQ(fresh.get(fresh.ids()[1]).velocity, Vec2(-120, 0));
    EXPECT_NE(now.velocity, Vec2(-120, 0));
    for (int k = 0; k < 200; ++k) {
        edited.step(kDt);
        fresh.step(kDt);
    }
    EXPECT_GT(edited.counters().collisions, 0u);
    const auto ie = edited.ids(), iff = fresh.ids();
    for (std::size_t k = 0; k < ie.size(); ++k) {
        const Particle a = edited.get(ie[k]), b = fresh.get(iff[k]);
        EXPECT_NEAR(a.position.x(), b.position.x(), 1e-9) << k;
        EXPECT_NEAR(a.position.y(), b.position.y(), 1e-9) << k;
        EXPECT_NEAR(a.velocity.x(), b.velocity.x(), 1e-9) << k;
        EXPECT_NEAR(a.velocity.y(), b.velocity.y(), 1e-9) << k;
    }
}

}  // namespace
}  // namespace psb::app
