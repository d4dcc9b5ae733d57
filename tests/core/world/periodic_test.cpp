// Periodic boxes in every step mode: centres wrap into the box, pairs meet across its edges and
// corners, and the unwrapped positions follow the motion however often a particle wraps.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <particle_sandbox/error.hpp>
#include <particle_sandbox/world.hpp>

namespace psb {
namespace {

World periodicWorld(StepMode mode, double width = 10.0, double height = 10.0) {
    WorldDef def;
    def.width = width;
    def.height = height;
    def.periodic = true;
    SolverSettings solver;
    solver.mode = mode;
    solver.substeps = mode == StepMode::Substep ? 4 : 1;
    World w(def, solver);
    w.setThreads(1);
    return w;
}

ParticleDef disc(Vec2 position, Vec2 velocity, double radius = 0.5) {
    ParticleDef d;
    d.position = position;
    d.velocity = velocity;
    d.radius = radius;
    return d;
}

class PeriodicModes : public ::testing::TestWithParam<StepMode> {};

TEST_P(PeriodicModes, AParticleLeavingByOneEdgeComesBackByTheOpposite) {
    World w = periodicWorld(GetParam());
    const ParticleId a = w.add(disc({9.5, 1.5}, {3.0, -2.0}));
    for (int k = 0; k < 100; ++k)
        w.step(0.01);  // 3 m right, 2 m up: across the right edge and the top one
    const Particle p = w.get(a);
    EXPECT_NEAR(p.position.x(), 2.5, 1e-9);
    EXPECT_NEAR(p.position.y(), 9.5, 1e-9);
    // The unwrapped centre moved continuously: 3 m right and 2 m up.
    const Vec2 u = w.unwrappedPosition(a);
    EXPECT_NEAR(u.x(), 12.5, 1e-9);
    EXPECT_NEAR(u.y(), -0.5, 1e-9);
    EXPECT_EQ(w.counters().wallCollisions, 0u);
}

TEST_P(PeriodicModes, APairMeetsAcrossAnEdge) {
    // Head on through the left/right edge: equal masses exchange velocities.
    World w = periodicWorld(GetParam());
    const ParticleId a = w.add(disc({0.8, 5.0}, {-1.0, 0.0}));
    const ParticleId b = w.add(disc({9.2, 5.0}, {1.0, 0.0}));
    for (int k = 0; k < 50; ++k)
        w.step(0.01);  // they touch after 0.3 s
    EXPECT_NEAR(w.get(a).velocity.x(), 1.0, 1e-9);
    EXPECT_NEAR(w.get(b).velocity.x(), -1.0, 1e-9);
    EXPECT_GE(w.counters().collisions, 1u);
    // Bounced back, each on its own side of the edge again.
    EXPECT_GT(w.get(a).position.x(), 0.5);
    EXPECT_LT(w.get(b).position.x(), 9.5);
}

TEST_P(PeriodicModes, APairMeetsAcrossACorner) {
    // Along the diagonal through the corner (0, 0) = (10, 10): a head-on hit along it.
    World w = periodicWorld(GetParam());
    const double s = 0.6, v = 1.0 / std::sqrt(2.0);
    const ParticleId a = w.add(disc({s, s}, {-v, -v}));
    const ParticleId b = w.add(disc({10.0 - s, 10.0 - s}, {v, v}));
    for (int k = 0; k < 60; ++k)
        w.step(0.01);
    EXPECT_NEAR(w.get(a).velocity.x(), v, 1e-6);
    EXPECT_NEAR(w.get(a).velocity.y(), v, 1e-6);
    EXPECT_NEAR(w.get(b).velocity.x(), -v, 1e-6);
    EXPECT_NEAR(w.get(b).velocity.y(), -v, 1e-6);
}

TEST_P(PeriodicModes, TheUnwrappedPositionIsTheIntegratedMotionAndSurvivesACopy) {
    World w = periodicWorld(GetParam(), 7.0, 5.0);
    const Vec2 start(3.0, 1.0), v(41.0, -23.0);
    const ParticleId a = w.add(disc(start, v, 0.25));
    for (int k = 0; k < 250; ++k)
        w.step(0.004);     // about 6 widths and 4.6 heights
    const World copy = w;  // in the exact mode, with the state the step still owes the arrays
    const Vec2 want = start + v * w.time();
    EXPECT_NEAR(w.unwrappedPosition(a).x(), want.x(), 1e-9);
    EXPECT_NEAR(w.unwrappedPosition(a).y(), want.y(), 1e-9);
    EXPECT_EQ(copy.unwrappedPosition(a), w.unwrappedPosition(a));
    const Particle p = w.get(a);
    EXPECT_GE(p.position.x(), 0.0);
    EXPECT_LT(p.position.x(), 7.0);
    EXPECT_GE(p.position.y(), 0.0);
    EXPECT_LT(p.position.y(), 5.0);
}

TEST_P(PeriodicModes, MomentumIsConservedInAGasWithoutWalls) {
    // Without walls nothing outside the gas pushes it: total momentum stays what it was.
    World w = periodicWorld(GetParam(), 20.0, 20.0);
    std::uint64_t seed = 12345;
    const auto uniform = [&seed] {
        seed = seed * 6364136223846793005ull + 1442695040888963407ull;
        return static_cast<double>(seed >> 11) * 0x1.0p-53;
    };
    for (int i = 0; i < 10; ++i) {
        for (int j = 0; j < 10; ++j) {
            w.add(disc({1.0 + 2.0 * i, 1.0 + 2.0 * j},
                       {4.0 * uniform() - 2.0, 4.0 * uniform() - 2.0}, 0.6));
        }
    }
    const auto momentum = [&w] {
        const ParticleArrays& p = w.particles();
        Vec2 m = Vec2::Zero();
        for (std::size_t i = 0; i < p.size(); ++i)
            m += p.mass[i] * Vec2(p.vx[i], p.vy[i]);
        return m;
    };
    const Vec2 before = momentum();
    for (int k = 0; k < 200; ++k)
        w.step(0.02);
    EXPECT_GT(w.counters().collisions, 300u);
    EXPECT_NEAR(momentum().x(), before.x(), 1e-12);
    EXPECT_NEAR(momentum().y(), before.y(), 1e-12);
}

TEST_P(PeriodicModes, DiscsAmongPegsCrossTheEdgesAndNeverEndAStepInAPeg) {
    // A Lorentz gas of many discs: in the discrete modes the move stage wraps a centre as it
    // moves it, and the obstacles stage's sweep must start from where the centre started,
    // moved with it across the edge.
    WorldDef def;
    def.width = def.height = 8.0;
    def.periodic = true;
    Obstacles pegs;
    for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 4; ++j)
            pegs.push_back(Obstacle::peg({1.0 + 2.0 * i, 1.0 + 2.0 * j}, 0.6));
    }
    def.obstacles = pegs;
    SolverSettings solver;
    solver.mode = GetParam();
    solver.substeps = GetParam() == StepMode::Substep ? 4 : 1;
    solver.broadphase = BroadPhaseKind::Grid;
    World w(def, solver);
    w.setThreads(1);
    std::uint64_t seed = 7;
    const auto uniform = [&seed] {
        seed = seed * 6364136223846793005ull + 1442695040888963407ull;
        return static_cast<double>(seed >> 11) * 0x1.0p-53;
    };
    for (int k = 0; k < 300; ++k) {
        // On the lines between the pegs' rows and columns, clear of them.
        const double along = 8.0 * uniform();
        const Vec2 at = k % 2 == 0 ? Vec2(along, 2.0 * (k % 4 == 0 ? 0.0 : 1.0))
                                   : Vec2(2.0 * ((k / 2) % 4), along);
        w.add(disc(at, {6.0 * uniform() - 3.0, 6.0 * uniform() - 3.0}, 0.04));
    }
    double closest = INFINITY, travelled = 0.0;
    for (int step = 0; step < 200; ++step) {
        w.step(0.02);
        const ParticleArrays& p = w.particles();
        for (std::size_t i = 0; i < p.size(); ++i) {
            ASSERT_GE(p.x[i], 0.0);
            ASSERT_LT(p.x[i], def.width);
            ASSERT_GE(p.y[i], 0.0);
            ASSERT_LT(p.y[i], def.height);
            for (const Obstacle& o : pegs) {
                closest = std::min(closest, std::hypot(p.x[i] - o.a.x(), p.y[i] - o.a.y()) -
                                                o.radius - p.radius[i]);
            }
        }
    }
    const ParticleArrays& p = w.particles();
    for (std::size_t i = 0; i < p.size(); ++i)
        travelled = std::max(travelled, std::hypot(p.unwrapX[i], p.unwrapY[i]));
    EXPECT_GT(w.counters().obstacleCollisions, 300u);
    EXPECT_GT(closest, -1e-9);
    EXPECT_GT(travelled, 8.0) << "discs crossed the edges";
}

INSTANTIATE_TEST_SUITE_P(AllModes, PeriodicModes,
                         ::testing::Values(StepMode::Discrete, StepMode::Substep, StepMode::Exact),
                         [](const auto& p) { return std::string(toString(p.param)); });

std::string refusal(auto&& f) {
    try {
        f();
    } catch (const InvalidArgument& e) {
        return e.what();
    }
    return "(accepted)";
}

TEST(PeriodicWorld, APointOnADiscsImageAcrossAnEdgePicksIt) {
    // A disc over the right edge of a 10 m box is seen again over the left edge: a point on
    // that part, inside the box or outside it, picks the disc. A point where the image of a disc
    // that crosses no edge would be (nothing is drawn there) picks nothing.
    World w = periodicWorld(StepMode::Discrete, 10.0, 8.0);
    const ParticleId over = w.add(disc({9.7, 4.0}, {0.0, 0.0}, 0.8));
    const ParticleId inside = w.add(disc({3.0, 6.0}, {0.0, 0.0}, 0.5));
    EXPECT_EQ(w.pick({9.7, 4.0}), over);
    EXPECT_EQ(w.pick({0.3, 4.0}), over);   // the image's part inside the box
    EXPECT_EQ(w.pick({-0.2, 4.0}), over);  // the image itself, outside the box
    EXPECT_EQ(w.pick({10.3, 4.0}), over);  // the disc's own part over the edge
    EXPECT_EQ(w.pick({3.0, 6.0}), inside);
    EXPECT_FALSE(w.pick({13.0, 6.0}).has_value());  // inside's image would be here: not drawn
    EXPECT_FALSE(w.pick({5.0, 2.0}).has_value());
}

TEST(PeriodicWorld, HasNoWallsAndRefusesToBeGivenThem) {
    World w = periodicWorld(StepMode::Exact);
    EXPECT_FALSE(w.def().walls);
    EXPECT_NE(refusal([&] { w.setWalls(true); }).find("periodic"), std::string::npos);
    w.setPeriodic(false);
    w.setWalls(true);
    EXPECT_TRUE(w.def().walls);
    EXPECT_TRUE(w.particles().unwrapX.empty());
}

TEST(PeriodicWorld, RefusesAParticleWiderThanHalfTheBox) {
    World w = periodicWorld(StepMode::Discrete, 10.0, 8.0);
    w.add(disc({1.0, 1.0}, {0.0, 0.0}, 2.0));  // 4 m across: two fit in 8 m
    const std::string m = refusal([&] { w.add(disc({5.0, 5.0}, {0.0, 0.0}, 2.01)); });
    EXPECT_NE(m.find("World::add: radius"), std::string::npos) << m;
    EXPECT_NE(m.find("two diameters"), std::string::npos) << m;
    EXPECT_EQ(w.size(), 1u);
    EXPECT_NE(refusal([&] { w.setBox(7.9, 20.0); }).find("World::setBox"), std::string::npos);
    EXPECT_EQ(w.def().width, 10.0);
}

TEST(PeriodicWorld, SetPeriodicRefusesWhatWouldNotFitAndChangesNothing) {
    WorldDef def;
    def.width = 10.0;
    def.height = 10.0;
    World w(def);
    w.add(disc({5.0, 5.0}, {0.0, 0.0}, 3.0));
    const std::string m = refusal([&] { w.setPeriodic(true); });
    EXPECT_NE(m.find("World::setPeriodic: largest radius"), std::string::npos) << m;
    EXPECT_FALSE(w.def().periodic);
    EXPECT_TRUE(w.def().walls);
}

TEST(PeriodicWorld, RefusesAnObstacleWithinADiameterOfAnEdge) {
    World w = periodicWorld(StepMode::Exact);
    w.add(disc({5.0, 5.0}, {0.0, 0.0}, 0.5));
    // Its disc reaches to 0.8 m from the left edge: one diameter (1 m) is needed.
    const std::string m = refusal([&] { w.addObstacle(Obstacle::peg({1.0, 5.0}, 0.2)); });
    EXPECT_NE(m.find("obstacle 0 (peg)"), std::string::npos) << m;
    EXPECT_NE(m.find("inside every edge"), std::string::npos) << m;
    EXPECT_TRUE(w.obstacles().empty());
    w.addObstacle(Obstacle::peg({1.3, 5.0}, 0.2));
    EXPECT_EQ(w.obstacles().size(), 1u);
    // A bigger particle would need more room from that peg.
    EXPECT_NE(refusal([&] {
                  w.add(disc({7.0, 7.0}, {0.0, 0.0}, 0.8));
              }).find("World::add"),
              std::string::npos);
}

}  // namespace
}  // namespace psb
