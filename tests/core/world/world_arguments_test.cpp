// World's public API refuses what would break the step later (an infinite inverse mass, a
// substep count that never finishes, an enumerator cast from a stray integer) and survives the
// changes it accepts (a box shrunk around its particles, walls switched on with particles
// outside).

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include <particle_sandbox/error.hpp>
#include <particle_sandbox/scene.hpp>
#include <particle_sandbox/validation.hpp>
#include <particle_sandbox/world.hpp>

namespace psb {
namespace {

constexpr double kSubnormal = 4.9406564584124654e-324;
constexpr double kSmallestNormal = std::numeric_limits<double>::min();

std::string messageOf(auto&& call) {
    try {
        call();
    } catch (const InvalidArgument& e) {
        return e.what();
    }
    return "(no throw)";
}

void expectAllFiniteAndInside(const World& w) {
    const ParticleArrays& p = w.particles();
    for (std::size_t i = 0; i < p.size(); ++i) {
        ASSERT_TRUE(std::isfinite(p.x[i]) && std::isfinite(p.y[i]) && std::isfinite(p.vx[i]) &&
                    std::isfinite(p.vy[i]))
            << "particle " << i;
        const double r = p.radius[i];
        EXPECT_TRUE(p.x[i] >= r && p.x[i] <= w.def().width - r && p.y[i] >= r &&
                    p.y[i] <= w.def().height - r)
            << "particle " << i << " at (" << p.x[i] << ", " << p.y[i] << ")";
    }
}

TEST(WorldArguments, AMassWhoseInverseOverflowsIsRefused) {
    // 1 / 4.9e-324 is infinity: separating such a particle from another computed inf / inf.
    World w;
    const ParticleId a = w.add({.position = {10.0, 10.0}});
    EXPECT_EQ(messageOf([&] { w.add({.mass = kSubnormal}); }),
              "World::add: mass must be at least 2.2250738585072014e-308 so that its inverse is "
              "finite (got 5e-324)");
    EXPECT_EQ(messageOf([&] { w.setMass(a, 1e-310); }),
              "World::setMass: mass must be at least 2.2250738585072014e-308 so that its "
              "inverse is finite (got 1e-310)");
    EXPECT_EQ(w.size(), 1u);
    EXPECT_EQ(w.get(a).mass, 1.0);
}

TEST(WorldArguments, TheSmallestNormalMassCollidesWithoutNaN) {
    WorldDef def{.width = 100.0, .height = 100.0};
    World w(def);
    w.add({.position = {40.0, 50.0}, .velocity = {1.0, 0.0}, .mass = kSmallestNormal});
    w.add({.position = {41.5, 50.0}, .velocity = {-1.0, 0.0}, .mass = 1.0});  // overlapping
    for (int k = 0; k < 10; ++k)
        w.step(0.01);
    expectAllFiniteAndInside(w);
}

TEST(WorldArguments, SubstepsAreBoundedSoThatAStepEnds) {
    World w;
    const std::string limit = std::to_string(kMaxSubsteps);
    EXPECT_EQ(messageOf([&] { w.setSolver({.substeps = kMaxSubsteps + 1}); }),
              "World::setSolver: substeps must be in [1, " + limit + "] (got " +
                  std::to_string(kMaxSubsteps + 1) + ")");
    EXPECT_EQ(messageOf([&] { World(WorldDef{}, {.substeps = 2'000'000'000}); }),
              "World: substeps must be in [1, " + limit + "] (got 2000000000)");
    EXPECT_EQ(w.solver().substeps, 1);
    w.setSolver({.mode = StepMode::Substep, .substeps = kMaxSubsteps});
    EXPECT_EQ(w.solver().substeps, kMaxSubsteps);
}

TEST(WorldArguments, EnumeratorsOutsideTheirListsAreRefused) {
    World w;
    EXPECT_EQ(messageOf([&] { w.setSolver({.mode = static_cast<StepMode>(7)}); }),
              "World::setSolver: mode is not a known step mode");
    EXPECT_EQ(messageOf([&] { w.setSolver({.broadphase = static_cast<BroadPhaseKind>(-1)}); }),
              "World::setSolver: broadphase is not a known broadphase");
    EXPECT_EQ(w.solver().mode, StepMode::Discrete);
}

TEST(WorldArguments, AFailedSetBoxLeavesTheBoxAsItWas) {
    World w(WorldDef{.width = 30.0, .height = 40.0});
    EXPECT_THROW(w.setBox(std::numeric_limits<double>::quiet_NaN(), 10.0), InvalidArgument);
    EXPECT_THROW(w.setBox(10.0, std::numeric_limits<double>::infinity()), InvalidArgument);
    EXPECT_THROW(w.setBox(10.0, -1.0), InvalidArgument);
    EXPECT_EQ(w.def().width, 30.0);
    EXPECT_EQ(w.def().height, 40.0);
}

TEST(WorldArguments, ShrinkingTheBoxAroundParticlesBringsThemInsideOnTheNextStep) {
    // setBox accepts a box that some particles no longer fit in (the app resizes the box under
    // a running world); the next step's wall stage puts every centre back in [r, extent - r].
    World w(WorldDef{.width = 100.0, .height = 100.0});
    for (int k = 0; k < 10; ++k)
        w.add({.position = {5.0 + 9.0 * k, 95.0 - 9.0 * k}, .velocity = {3.0, -2.0}});
    w.setBox(20.0, 20.0);
    w.step(0.01);
    EXPECT_EQ(w.size(), 10u);
    expectAllFiniteAndInside(w);
    for (int k = 0; k < 200; ++k)
        w.step(0.01);  // crowded into a small box: still finite and inside
    expectAllFiniteAndInside(w);
}

TEST(WorldArguments, ABoxSmallerThanAParticleHoldsItAtTheCentre) {
    World w(WorldDef{.width = 100.0, .height = 100.0});
    w.add({.position = {50.0, 50.0}, .velocity = {1.0, 1.0}, .radius = 10.0});
    w.setBox(5.0, 50.0);
    w.step(0.01);
    const Particle p = w.get(w.ids()[0]);
    EXPECT_EQ(p.position.x(), 2.5);
    EXPECT_EQ(p.velocity.x(), 0.0);
    EXPECT_TRUE(std::isfinite(p.position.y()));
}

TEST(WorldArguments, SwitchingWallsOnBringsParticlesOutsideBackIn) {
    World w(WorldDef{.width = 50.0, .height = 50.0, .walls = false});
    w.add({.position = {-30.0, 80.0}, .velocity = {-1.0, 1.0}});
    w.add({.position = {1e9, -1e9}});
    w.setWalls(true);
    w.step(0.01);
    expectAllFiniteAndInside(w);
}

}  // namespace
}  // namespace psb

namespace psb {
namespace {

TEST(Validate, AcceptsWhatWorldAcceptsAndListsEveryProblemWithoutThrowing) {
    EXPECT_TRUE(validate(WorldDef{}, SolverSettings{}).empty());
    WorldDef def;
    def.width = -1.0;
    def.restitution = std::numeric_limits<double>::quiet_NaN();
    def.gravity = {0.0, 9.81};                         // accepted in every mode
    def.obstacles = {Obstacle::peg({1.0, 1.0}, 0.5)};  // accepted in every mode too
    SolverSettings s;
    s.mode = StepMode::Exact;
    s.substeps = 0;
    s.broadphase = static_cast<BroadPhaseKind>(42);
    std::vector<SettingProblem> problems;
    EXPECT_NO_THROW(problems = validate(def, s));
    std::vector<std::string_view> settings;
    for (const SettingProblem& p : problems)
        settings.push_back(p.setting);
    const std::vector<std::string_view> want{"width", "restitution", "substeps", "broadphase"};
    EXPECT_EQ(settings, want);
    EXPECT_EQ(describe(problems.front()), "width must be finite and > 0 (got -1)");
    // The step length is not a setting: World::step refuses a bad one, makeWorld a scene's.
    EXPECT_EQ(messageOf([] { World().step(0.0); }),
              "World::step: dt must be finite and > 0 (got 0)");
    Scene scene;
    scene.dt = -1.0;
    EXPECT_EQ(messageOf([&] { (void)makeWorld(scene); }),
              "makeWorld: dt must be finite and > 0 (got -1)");
}

TEST(Validate, WorldThrowsTheFirstProblemWithTheSameWords) {
    WorldDef def{.width = 10.0, .height = 10.0, .gravity = {0.0, 1.0}, .friction = -1.0};
    def.obstacles = {Obstacle::peg({5.0, 5.0}, 1.0)};
    const SolverSettings s{.mode = StepMode::Exact};
    const std::vector<SettingProblem> problems = validate(def, s);
    ASSERT_EQ(problems.size(), 1u);
    try {
        World w(def, s);
        ADD_FAILURE() << "World accepted what validate refused";
    } catch (const InvalidArgument& e) {
        EXPECT_EQ(std::string(e.what()), "World: " + describe(problems.front()));
    }
}

}  // namespace
}  // namespace psb
