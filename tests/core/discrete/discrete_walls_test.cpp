// The wall stage: rebound, sign setting, restitution, and containment.

#include <gtest/gtest.h>

#include <random>

#include <particle_sandbox/diagnostics.hpp>
#include <particle_sandbox/world.hpp>

namespace psb {
namespace {

World box(double w, double h, double e = 1.0) {
    WorldDef def;
    def.width = w;
    def.height = h;
    def.restitution = e;
    return World(def);
}

TEST(Walls, ParticleCrossingTheRightWallIsClampedAndReflected) {
    World w = box(100.0, 100.0);
    const ParticleId p = w.add({.position = {98.0, 50.0}, .velocity = {10.0, 3.0}, .radius = 1.0});
    w.step(0.1);  // would reach x = 99 + ... : 98 + 1 = 99 -> exactly touching; go further
    w.step(0.1);
    const Particle q = w.get(p);
    EXPECT_LE(q.position.x(), 99.0);
    EXPECT_EQ(q.velocity.x(), -10.0);
    EXPECT_EQ(q.velocity.y(), 3.0);
    EXPECT_EQ(w.counters().wallCollisions, 1u);
    EXPECT_DOUBLE_EQ(w.counters().wallImpulse, 20.0);  // m |Δv| = 1 kg * 20 m/s
}

TEST(Walls, InwardMovingParticleOutsideIsNotFlippedOutward) {
    World w = box(100.0, 100.0);
    // Outside the left wall but already moving inward: the original negated this velocity.
    const ParticleId p = w.add({.position = {-5.0, 50.0}, .velocity = {4.0, 0.0}, .radius = 1.0});
    w.step(0.01);
    EXPECT_EQ(w.get(p).velocity.x(), 4.0);
    EXPECT_EQ(w.get(p).position.x(), 1.0);
    EXPECT_EQ(w.counters().wallCollisions, 0u);
}

TEST(Walls, RestitutionScalesTheReboundSpeed) {
    World w = box(100.0, 100.0, 0.5);
    const ParticleId p = w.add({.position = {50.0, 1.5}, .velocity = {0.0, -10.0}, .radius = 1.0});
    w.step(0.1);
    EXPECT_EQ(w.get(p).velocity.y(), 5.0);
    EXPECT_EQ(w.get(p).position.y(), 1.0);
}

TEST(Walls, ParticleLargerThanTheBoxIsCentredAndStopped) {
    World w = box(10.0, 10.0);
    const ParticleId p = w.add({.position = {2.0, 3.0}, .velocity = {1.0, -1.0}, .radius = 8.0});
    w.step(0.01);
    EXPECT_EQ(w.get(p).position, Vec2(5.0, 5.0));
    EXPECT_EQ(w.get(p).velocity.x(), 0.0);
    EXPECT_EQ(w.get(p).velocity.y(), 0.0);
}

TEST(Walls, OverlapPushNeverLeavesAParticleOutsideTheBox) {
    World w = box(10.0, 10.0);
    // A light particle pressed into the corner by a heavy one.
    w.add({.position = {1.0, 1.0}, .mass = 1.0, .radius = 1.0});
    w.add({.position = {2.0, 2.0}, .mass = 1000.0, .radius = 1.0});
    w.step(0.01);
    for (std::size_t i = 0; i < w.size(); ++i) {
        EXPECT_GE(w.particles().x[i], w.particles().radius[i]);
        EXPECT_GE(w.particles().y[i], w.particles().radius[i]);
    }
}

TEST(Walls, WallsOffLetParticlesLeave) {
    World w = box(10.0, 10.0);
    w.setWalls(false);
    const ParticleId p = w.add({.position = {9.0, 5.0}, .velocity = {100.0, 0.0}});
    w.step(1.0);
    EXPECT_EQ(w.get(p).position.x(), 109.0);
}

TEST(Walls, LongRandomRunKeepsEveryParticleInsideAndTheCountFixed) {
    World w = box(300.0, 200.0);
    std::mt19937_64 rng(12345);
    std::uniform_real_distribution<double> ux(20.0, 280.0), uy(20.0, 180.0), uv(-300.0, 300.0),
        ur(0.5, 8.0), um(0.1, 50.0);
    for (int k = 0; k < 150; ++k) {
        w.add({.position = {ux(rng), uy(rng)},
               .velocity = {uv(rng), uv(rng)},
               .mass = um(rng),
               .radius = ur(rng)});
    }
    const double k0 = kineticEnergy(w);
    for (int s = 0; s < 5000; ++s) {
        w.step(0.01);
        const ParticleArrays& p = w.particles();
        ASSERT_EQ(p.size(), 150u);
        for (std::size_t i = 0; i < p.size(); ++i) {
            ASSERT_GE(p.x[i], p.radius[i]) << "step " << s;
            ASSERT_LE(p.x[i], 300.0 - p.radius[i]) << "step " << s;
            ASSERT_GE(p.y[i], p.radius[i]) << "step " << s;
            ASSERT_LE(p.y[i], 200.0 - p.radius[i]) << "step " << s;
        }
    }
    // e = 1 everywhere and position pushes do no work: energy is conserved to rounding.
    EXPECT_NEAR(kineticEnergy(w), k0, 1e-9 * k0);
    EXPECT_GT(w.counters().collisions, 1000u);
}

}  // namespace
}  // namespace psb
