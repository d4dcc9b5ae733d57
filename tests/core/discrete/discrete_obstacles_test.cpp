// The obstacles stage of the discrete step, through World: rebounds, no tunnelling at any
// speed, resting, wedging, the box, threads, and a world without obstacles paying nothing.

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <particle_sandbox/world.hpp>

#include "obstacles/obstacle_geometry.hpp"

namespace psb {
namespace {

World box(double size, double e = 1.0, double mu = 0.0, Vec2 g = Vec2::Zero()) {
    WorldDef def;
    def.width = def.height = size;
    def.restitution = e;
    def.friction = mu;
    def.gravity = g;
    World w(def);
    w.setThreads(1);
    return w;
}

double coreDistance(const Obstacle& o, const Vec2& p) {
    double qx, qy;
    nearestCorePoint(o, p.x(), p.y(), qx, qy);
    return std::hypot(p.x() - qx, p.y() - qy);
}

TEST(ObstacleContacts, HeadOnReboundOffAPegReversesTheVelocity) {
    World w = box(100.0);
    w.addObstacle(Obstacle::peg(Vec2(50.0, 50.0), 1.0));
    const ParticleId id =
        w.add({.position = {40.0, 50.0}, .velocity = {10.0, 0.0}, .mass = 2.0, .radius = 1.0});
    for (int k = 0; k < 200; ++k)
        w.step(0.01);
    const Particle p = w.get(id);
    EXPECT_DOUBLE_EQ(p.velocity.x(), -10.0);
    EXPECT_EQ(p.velocity.y(), 0.0);
    EXPECT_EQ(w.counters().obstacleCollisions, 1u);
    EXPECT_LT(p.position.x(), 48.0);
}

TEST(ObstacleContacts, RestitutionAndFrictionActAsOnTheWalls) {
    // Hitting a horizontal segment at 45°: the normal part is scaled by e, the tangential part
    // reduced by at most mu times the normal change, exactly as reboundOffWall does for walls.
    World w = box(100.0, 0.5, 0.1);
    w.addObstacle(Obstacle::segment(Vec2(10.0, 60.0), Vec2(90.0, 60.0), 1.0));
    const ParticleId id =
        w.add({.position = {40.0, 50.0}, .velocity = {4.0, 4.0}, .mass = 1.0, .radius = 1.0});
    for (int k = 0; k < 300 && w.counters().obstacleCollisions == 0; ++k)
        w.step(0.01);
    ASSERT_EQ(w.counters().obstacleCollisions, 1u);
    const Particle p = w.get(id);
    EXPECT_DOUBLE_EQ(p.velocity.y(), -2.0);             // −e · 4
    EXPECT_DOUBLE_EQ(p.velocity.x(), 4.0 - 0.1 * 6.0);  // 4 − mu · (1 + e) · 4
}

TEST(ObstacleContacts, NoSpeedTunnelsThroughAThinSegment) {
    // A wall 1 mm thick; particles of 1 cm radius flying at it so fast that one step carries
    // them 100 diameters. Every one must end on the side it started.
    World w = box(100.0);
    const Obstacle wall = Obstacle::segment(Vec2(50.0, 0.0), Vec2(50.0, 100.0), 0.001);
    w.addObstacle(wall);
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> y(5.0, 95.0), x(5.0, 45.0), angle(-1.2, 1.2);
    for (int k = 0; k < 500; ++k) {
        const double a = angle(rng);
        w.add({.position = {x(rng), y(rng)},
               .velocity = {200.0 * std::cos(a), 200.0 * std::sin(a)},
               .mass = 1.0,
               .radius = 0.01});
    }
    for (int k = 0; k < 100; ++k) {
        w.step(0.01);
        const ParticleArrays& p = w.particles();
        for (std::size_t i = 0; i < p.size(); ++i)
            ASSERT_LT(p.x[i], 50.0) << "particle " << i << " went through at step " << k;
    }
    EXPECT_GT(w.counters().obstacleCollisions, 500u);
}

TEST(ObstacleContacts, NoSpeedTunnelsThroughAPeg) {
    World w = box(100.0);
    w.addObstacle(Obstacle::peg(Vec2(50.0, 50.0), 0.5));
    const ParticleId id =
        w.add({.position = {10.0, 50.0}, .velocity = {5000.0, 0.0}, .mass = 1.0, .radius = 0.1});
    w.step(0.01);  // one step would carry it 50 m, across the peg
    EXPECT_LT(w.get(id).position.x(), 50.0);
    EXPECT_DOUBLE_EQ(w.get(id).velocity.x(), -5000.0);
}

TEST(ObstacleContacts, ElasticBouncesAmongPegsKeepTheEnergy) {
    World w = box(20.0);
    for (int i = 1; i < 10; ++i)
        for (int j = 1; j < 10; ++j)
            w.addObstacle(Obstacle::peg(Vec2(2.0 * i, 2.0 * j), 0.3));
    const ParticleId id =
        w.add({.position = {1.0, 1.0}, .velocity = {7.3, 3.1}, .mass = 1.0, .radius = 0.2});
    const double speed = std::hypot(7.3, 3.1);
    for (int k = 0; k < 5000; ++k)
        w.step(0.01);
    EXPECT_NEAR(w.get(id).velocity.norm(), speed, 1e-12 * speed);
    EXPECT_GT(w.counters().obstacleCollisions, 50u);
    for (const Obstacle& o : w.obstacles())
        EXPECT_GE(coreDistance(o, w.get(id).position), 0.5 - 1e-9);
}

TEST(ObstacleContacts, ABallSettlesOnARampAndStaysAboveIt) {
    // e = 0, high friction, gravity: a disc that does not turn (a block) comes to rest on a 20°
    // ramp, never sinking into it. (One that turns rolls down it.)
    World w = box(10.0, 0.0, 1.0, Vec2(0.0, 9.81));
    const Obstacle ramp =
        Obstacle::segment(Vec2(1.0, 5.0), Vec2(9.0, 5.0 + 8.0 * std::tan(0.35)), 0.05);
    w.addObstacle(ramp);
    const ParticleId id =
        w.add({.position = {3.0, 4.0}, .mass = 1.0, .radius = 0.2, .fixedRotation = true});
    for (int k = 0; k < 600; ++k) {
        w.step(1.0 / 120.0);
        EXPECT_GE(coreDistance(ramp, w.get(id).position), 0.225 - 1e-9) << "step " << k;
        EXPECT_LT(sideOf(ramp, w.get(id).position.x(), w.get(id).position.y()), 0.0);
    }
    EXPECT_LT(w.get(id).velocity.norm(), 0.2);  // nearly at rest: friction holds it (mu > tan 20°)
}

TEST(ObstacleContacts, ABallSlidesDownAFrictionlessRampAsOnAnInclinedPlane) {
    // e = 0, no friction, a 30° ramp: pressed onto it every step, the ball slides down it,
    // covering ½ g sin30° t² and gaining the kinetic energy of the height it loses. (A ball
    // whose move stopped at each contact stayed where it was while its speed grew.)
    const double g = 9.81, angle = std::acos(-1.0) / 6.0, r = 0.1, h = 0.05;
    World w = box(10.0, 0.0, 0.0, Vec2(0.0, g));
    const Vec2 a(1.0, 2.0), b = a + 8.0 * Vec2(std::cos(angle), std::sin(angle));
    w.addObstacle(Obstacle::segment(a, b, 2.0 * h));
    const Vec2 normal(std::sin(angle), -std::cos(angle));  // up, out of the ramp
    const Vec2 start = a + 1.0 * (b - a).normalized() + (r + h) * normal;
    const ParticleId id = w.add({.position = start, .mass = 1.0, .radius = r});
    const double t = 1.0;
    for (int k = 0; k < 120; ++k)
        w.step(t / 120.0);
    const Particle p = w.get(id);
    const double along = (p.position - start).dot((b - a).normalized());
    EXPECT_NEAR(along, 0.5 * g * std::sin(angle) * t * t, 0.03 * 0.5 * g * std::sin(angle));
    const double drop = p.position.y() - start.y();
    EXPECT_NEAR(0.5 * p.velocity.squaredNorm(), g * drop, 0.02 * g * drop);
    EXPECT_NEAR((p.position - start).dot(normal), 0.0, 1e-3);  // on the ramp, not above it
}

TEST(ObstacleContacts, FrictionSlowsASlideWithoutStoppingIt) {
    // mu = 0.2 on a 30° ramp (tan 30° = 0.58 > mu): slower than without friction, still sliding.
    auto slid = [](double mu) {
        const double angle = std::acos(-1.0) / 6.0;
        World w = box(10.0, 0.0, mu, Vec2(0.0, 9.81));
        const Vec2 a(1.0, 2.0), b = a + 8.0 * Vec2(std::cos(angle), std::sin(angle));
        w.addObstacle(Obstacle::segment(a, b, 0.1));
        const Vec2 normal(std::sin(angle), -std::cos(angle));
        const Vec2 start = a + 1.0 * (b - a).normalized() + 0.15 * normal;
        const ParticleId id = w.add({.position = start, .mass = 1.0, .radius = 0.1});
        for (int k = 0; k < 120; ++k)
            w.step(1.0 / 120.0);
        return (w.get(id).position - start).norm();
    };
    const double free = slid(0.0), rubbed = slid(0.2);
    EXPECT_LT(rubbed, 0.9 * free);
    EXPECT_GT(rubbed, 0.3 * free);
}

TEST(ObstacleContacts, ABallWedgedInANarrowVNeverCrossesEitherSide) {
    // A V whose gap at the bottom is a fifth of the ball's diameter; gravity drives it in.
    World w = box(10.0, 0.3, 0.0, Vec2(0.0, 50.0));
    const Obstacle left = Obstacle::segment(Vec2(2.0, 2.0), Vec2(4.9, 8.0), 0.02);
    const Obstacle right = Obstacle::segment(Vec2(8.0, 2.0), Vec2(5.1, 8.0), 0.02);
    w.setObstacles({left, right});
    const ParticleId id = w.add({.position = {5.0, 3.0}, .mass = 1.0, .radius = 0.5});
    Vec2 before = w.get(id).position;
    for (int k = 0; k < 1000; ++k) {
        w.step(0.01);
        const Vec2 p = w.get(id).position;
        // It may leave over the top of the V, but never through either side.
        ASSERT_FALSE(crossesCore(left, before.x(), before.y(), p.x(), p.y())) << "step " << k;
        ASSERT_FALSE(crossesCore(right, before.x(), before.y(), p.x(), p.y())) << "step " << k;
        before = p;
    }
}

TEST(ObstacleContacts, ASegmentAgainstTheWallNeverPushesAParticleOutOfTheBox) {
    // A segment from the floor's corner up the right wall at a steep angle: particles pushed off
    // it toward the wall stay inside the box.
    World w = box(10.0, 0.8, 0.0, Vec2(9.81, 9.81));
    w.addObstacle(Obstacle::segment(Vec2(9.7, 10.0), Vec2(10.0, 0.0), 0.1));
    std::mt19937_64 rng(2);
    std::uniform_real_distribution<double> u(0.5, 9.5);
    for (int k = 0; k < 200; ++k)
        w.add({.position = {u(rng), u(rng)}, .mass = 1.0, .radius = 0.1});
    for (int k = 0; k < 400; ++k) {
        w.step(0.01);
        const ParticleArrays& p = w.particles();
        for (std::size_t i = 0; i < p.size(); ++i) {
            ASSERT_GE(p.x[i], p.radius[i]);
            ASSERT_LE(p.x[i], 10.0 - p.radius[i]);
            ASSERT_GE(p.y[i], p.radius[i]);
            ASSERT_LE(p.y[i], 10.0 - p.radius[i]);
        }
    }
}

TEST(ObstacleContacts, ABallPressedPastTheFloorBesideAWallStandingOnItEndsOutOfTheWall) {
    // Its move ends below the floor, beside the wall's lower end but clear of it; the wall
    // stage's clamp back onto the floor would put it into the wall. The obstacles stage judges
    // it where the clamp will put it, pushes it out, and makes the floor's rebound itself.
    World w = box(1.0);
    const Obstacle wall = Obstacle::segment(Vec2(0.5, 0.5), Vec2(0.5, 1.0), 0.002);
    w.addObstacle(wall);
    const ParticleId id = w.add(
        {.position = {0.504, 0.9975}, .velocity = {-0.02, 0.3}, .mass = 1.0, .radius = 0.0025});
    w.step(0.032);
    const Particle p = w.get(id);
    EXPECT_GE(coreDistance(wall, p.position), 0.0035 - 1e-12);
    EXPECT_LE(p.position.y(), 1.0 - 0.0025);
    EXPECT_LT(p.velocity.y(), 0.0);  // the floor turned it around
    EXPECT_EQ(w.counters().wallCollisions, 1u);
}

TEST(ObstacleContacts, HeldParticleIsPushedOutButKeepsItsVelocity) {
    World w = box(10.0);
    w.addObstacle(Obstacle::peg(Vec2(5.0, 5.0), 1.0));
    const ParticleId id = w.add({.position = {5.5, 5.0}, .mass = 1.0, .radius = 0.5});
    w.setKinematic(id, true);
    w.setVelocity(id, Vec2(0.0, 0.0));
    w.step(0.01);
    EXPECT_NEAR(w.get(id).position.x(), 6.5, 1e-12);
    EXPECT_EQ(w.get(id).velocity, Vec2(0.0, 0.0));
}

TEST(ObstacleContacts, ResultDoesNotDependOnTheThreadCount) {
    auto run = [](int threads) {
        World w = box(200.0, 0.9, 0.2, Vec2(0.0, 9.81));
        for (int i = 0; i < 40; ++i)
            for (int j = 0; j < 20; ++j)
                w.addObstacle(Obstacle::peg(Vec2(5.0 + 5.0 * i, 50.0 + 5.0 * j), 0.5));
        w.addObstacle(Obstacle::segment(Vec2(0.0, 180.0), Vec2(200.0, 150.0), 1.0));
        std::mt19937_64 rng(4);
        std::uniform_real_distribution<double> x(1.0, 199.0), y(1.0, 45.0), v(-20.0, 20.0);
        for (int k = 0; k < 9000; ++k) {
            w.add({.position = {x(rng), y(rng)},
                   .velocity = {v(rng), v(rng)},
                   .mass = 1.0,
                   .radius = 0.2});
        }
        w.setThreads(threads);
        for (int k = 0; k < 60; ++k)
            w.step(0.02);
        return w;
    };
    const World a = run(1), b = run(2);
    EXPECT_EQ(a.particles().x, b.particles().x);
    EXPECT_EQ(a.particles().vy, b.particles().vy);
    EXPECT_EQ(a.counters().obstacleCollisions, b.counters().obstacleCollisions);
    EXPECT_GT(a.counters().obstacleCollisions, 300u);
}

// The stage passes over a particle whose whole move stays inside a disc it knows to be free of
// obstacles (and walls) from an earlier step. These check that what is done to the world between
// steps does not leave such a disc standing where it no longer holds.

TEST(ObstacleContacts, AParticleMovedBetweenStepsIsSweptFromWhereItWasPut) {
    // It runs beside a thin wall for a while, is then put on the wall's other side and thrown
    // back to where it was: its move ends inside the disc of its earlier steps, but it starts
    // outside it, across the wall.
    World w = box(100.0);
    w.addObstacle(Obstacle::segment(Vec2(50.0, 5.0), Vec2(50.0, 95.0), 0.05));
    const ParticleId id =
        w.add({.position = {60.0, 50.0}, .velocity = {0.0, 0.5}, .mass = 1.0, .radius = 0.5});
    for (int k = 0; k < 20; ++k)
        w.step(0.01);
    w.setPosition(id, Vec2(45.0, 50.1));
    w.setVelocity(id, Vec2(1500.0, 0.0));  // 15 m in the step: back to x = 60
    w.step(0.01);
    EXPECT_LT(w.get(id).position.x(), 50.0);
    EXPECT_LT(w.get(id).velocity.x(), 0.0);
    EXPECT_EQ(w.counters().obstacleCollisions, 1u);
}

TEST(ObstacleContacts, NewObstaclesClearWhatTheStageKnewOfTheOldOnes) {
    // A peg added right in the path of a particle that had been moving through empty space.
    World w = box(100.0);
    w.addObstacle(Obstacle::peg(Vec2(10.0, 10.0), 1.0));
    const ParticleId id =
        w.add({.position = {50.0, 50.0}, .velocity = {1.0, 0.0}, .mass = 1.0, .radius = 0.5});
    for (int k = 0; k < 20; ++k)
        w.step(0.01);
    w.addObstacle(Obstacle::peg(Vec2(51.8, 50.0), 1.0));
    for (int k = 0; k < 100; ++k)
        w.step(0.01);
    EXPECT_LT(w.get(id).velocity.x(), 0.0);
    EXPECT_EQ(w.counters().obstacleCollisions, 1u);
}

TEST(ObstacleContacts, AWorldWithoutObstaclesSkipsTheStage) {
    World w = box(10.0);
    w.add({.position = {5.0, 5.0}, .velocity = {1.0, 0.0}, .mass = 1.0, .radius = 0.5});
    w.step(0.01);
    EXPECT_EQ(w.profile().ms("obstacles"), 0.0);
    w.addObstacle(Obstacle::peg(Vec2(8.0, 8.0), 0.5));
    w.step(0.01);
    EXPECT_GT(w.profile().ms("obstacles"), 0.0);
}

TEST(ObstacleContacts, SubstepModeUsesTheStageToo) {
    World w = box(100.0);
    w.setSolver({.mode = StepMode::Substep, .substeps = 4});
    w.addObstacle(Obstacle::segment(Vec2(50.0, 1.0), Vec2(50.0, 99.0), 0.01));
    const ParticleId id =
        w.add({.position = {40.0, 50.0}, .velocity = {2000.0, 0.0}, .mass = 1.0, .radius = 0.1});
    w.step(0.01);
    EXPECT_LT(w.get(id).position.x(), 50.0);
    EXPECT_EQ(w.counters().obstacleCollisions, 1u);
}

}  // namespace
}  // namespace psb
