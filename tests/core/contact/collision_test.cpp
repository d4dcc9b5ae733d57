// Pair collisions: the normal/tangent resolution, restitution, friction, and the fixes to the
// original program's defects.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <particle_sandbox/diagnostics.hpp>
#include <particle_sandbox/world.hpp>

#include "contact/contact.hpp"
#include "test_util.hpp"

namespace psb {
namespace {

using test::openWorld;
using test::relErr;

TEST(Collision, FormulaWithUnitRestitutionIsTheOriginalsOperationForOperation) {
    const double m1 = 3.0, m2 = 17.0, v1 = 4.25, v2 = -1.5;
    const NormalVelocities after = collideNormal(m1, m2, v1, v2, 1.0);
    EXPECT_EQ(after.v1n, ((m1 - m2) * v1 + 2 * m2 * v2) / (m1 + m2));
    EXPECT_EQ(after.v2n, ((m2 - m1) * v2 + 2 * m1 * v1) / (m1 + m2));
}

TEST(Collision, HeadOnEqualMassesExchangeVelocities) {
    World w = openWorld();
    const ParticleId a =
        w.add({.position = {0.0, 0.0}, .velocity = {2.0, 0.0}, .mass = 5.0, .radius = 1.0});
    const ParticleId b =
        w.add({.position = {1.99, 0.0}, .velocity = {-3.0, 0.0}, .mass = 5.0, .radius = 1.0});
    w.step(1e-3);
    EXPECT_NEAR(w.get(a).velocity.x(), -3.0, 1e-15);
    EXPECT_NEAR(w.get(b).velocity.x(), 2.0, 1e-15);
    EXPECT_EQ(w.get(a).velocity.y(), 0.0);
    EXPECT_EQ(w.get(b).velocity.y(), 0.0);
    EXPECT_EQ(w.counters().collisions, 1u);
}

TEST(Collision, EqualMassGlancingCollisionWithTargetAtRestLeavesAtRightAngles) {
    for (double offset : {0.3, 0.9, 1.5, 1.9}) {
        World w = openWorld();
        // Place the pair just overlapping along a normal at the given impact parameter.
        const double b = offset;  // impact parameter, radii 1 so contact distance 2
        const double along = std::sqrt(4.0 - b * b) - 1e-9;
        const ParticleId p = w.add({.position = {-along, -b}, .velocity = {10.0, 0.0}});
        const ParticleId q = w.add({.position = {0.0, 0.0}});
        w.step(1e-12);
        const Vec2 v1 = w.get(p).velocity, v2 = w.get(q).velocity;
        ASSERT_GT(v2.norm(), 0.0) << "offset " << offset;
        ASSERT_GT(v1.norm(), 0.0) << "offset " << offset;
        const double cosAngle = v1.dot(v2) / (v1.norm() * v2.norm());
        EXPECT_NEAR(cosAngle, 0.0, 1e-9) << "offset " << offset;
        EXPECT_NEAR(v1.squaredNorm() + v2.squaredNorm(), 100.0, 1e-9);
    }
}

TEST(Collision, ConservesMomentumAndEnergyAcrossMassRatios) {
    for (double ratio : {1e-6, 1e-4, 1e-2, 0.5, 1.0, 3.0, 1e2, 1e4, 1e6}) {
        World w = openWorld();
        w.add({.position = {0.0, 0.0}, .velocity = {3.0, 1.0}, .mass = 1.0, .radius = 1.0});
        w.add({.position = {1.5, 0.7}, .velocity = {-2.0, 0.5}, .mass = ratio, .radius = 1.0});
        const Vec2 p0 = momentum(w);
        const double k0 = kineticEnergy(w);
        w.step(1e-6);
        ASSERT_EQ(w.counters().collisions, 1u) << "ratio " << ratio;
        const Vec2 p1 = momentum(w);
        EXPECT_LE((p1 - p0).norm() / p0.norm(), 1e-12) << "ratio " << ratio;
        EXPECT_LE(relErr(kineticEnergy(w), k0), 1e-12) << "ratio " << ratio;
    }
}

TEST(Collision, RestitutionLosesExactlyOneMinusESquaredOfNormalRelativeEnergy) {
    for (double e : {0.0, 0.25, 0.5, 0.9}) {
        World w = openWorld(e);
        const double m1 = 2.0, m2 = 7.0;
        const ParticleId a =
            w.add({.position = {0.0, 0.0}, .velocity = {4.0, 1.0}, .mass = m1, .radius = 1.0});
        const ParticleId b =
            w.add({.position = {1.2, 1.2}, .velocity = {-1.0, -0.5}, .mass = m2, .radius = 1.0});
        const Vec2 n = Vec2(1.2, 1.2).normalized();
        const double vrel = (w.get(b).velocity - w.get(a).velocity).dot(n);
        const double reduced = m1 * m2 / (m1 + m2);
        const double normalEnergy = 0.5 * reduced * vrel * vrel;  // centre-of-mass frame
        const double k0 = kineticEnergy(w);
        w.step(1e-14);  // short enough that the move does not turn the normal measurably
        ASSERT_EQ(w.counters().collisions, 1u);
        const double lost = k0 - kineticEnergy(w);
        EXPECT_NEAR(lost, (1.0 - e * e) * normalEnergy, 1e-12 * k0) << "e " << e;
        const double vrelAfter = (w.get(b).velocity - w.get(a).velocity).dot(n);
        EXPECT_NEAR(vrelAfter, -e * vrel, 1e-12) << "e " << e;
    }
}

TEST(Collision, SeparatingOverlappingPairIsNotCollidedAgain) {
    World w = openWorld();
    const ParticleId a = w.add({.position = {0.0, 0.0}, .velocity = {-1.0, 0.0}});
    const ParticleId b = w.add({.position = {1.0, 0.0}, .velocity = {1.0, 0.0}});
    w.step(1e-3);
    EXPECT_EQ(w.counters().collisions, 0u);
    EXPECT_EQ(w.get(a).velocity, Vec2(-1.0, 0.0));
    EXPECT_EQ(w.get(b).velocity, Vec2(1.0, 0.0));
    // The overlap was pushed apart, equally for equal masses.
    EXPECT_NEAR(w.get(b).position.x() - w.get(a).position.x(), 2.0, 1e-12);
}

TEST(Collision, OverlapPushIsSplitByInverseMass) {
    World w = openWorld();
    const ParticleId heavy = w.add({.position = {0.0, 0.0}, .mass = 9.0});
    const ParticleId light = w.add({.position = {1.0, 0.0}, .mass = 1.0});
    const Vec2 com0 = centreOfMass(w);
    w.step(1e-9);
    EXPECT_NEAR(w.get(heavy).position.x(), -0.1, 1e-12);
    EXPECT_NEAR(w.get(light).position.x(), 1.9, 1e-12);
    EXPECT_NEAR((centreOfMass(w) - com0).norm(), 0.0, 1e-12);
}

TEST(Collision, CoincidentCentresGetADefinedOppositeNormal) {
    const Normal ab = coincidentNormal({3, 0}, {8, 2});
    const Normal ba = coincidentNormal({8, 2}, {3, 0});
    EXPECT_NEAR(std::hypot(ab.x, ab.y), 1.0, 1e-15);
    EXPECT_EQ(ab.x, -ba.x);
    EXPECT_EQ(ab.y, -ba.y);

    World w = openWorld();
    const ParticleId a = w.add({.position = {5.0, 5.0}});
    const ParticleId b = w.add({.position = {5.0, 5.0}});
    w.step(1e-3);
    const Vec2 d = w.get(b).position - w.get(a).position;
    EXPECT_NEAR(d.norm(), 2.0, 1e-12);
    EXPECT_TRUE(std::isfinite(d.x()) && std::isfinite(d.y()));
}

TEST(Collision, ThousandCoincidentParticlesSpreadWithoutNaN) {
    WorldDef def;
    def.width = def.height = 200.0;
    World w(def);
    for (int k = 0; k < 1000; ++k)
        w.add({.position = {100.0, 100.0}, .radius = 1.0});
    for (int s = 0; s < 200; ++s)
        w.step(0.01);
    const ParticleArrays& p = w.particles();
    ASSERT_EQ(w.size(), 1000u);
    for (std::size_t i = 0; i < p.size(); ++i) {
        ASSERT_TRUE(std::isfinite(p.x[i]) && std::isfinite(p.y[i]));
        ASSERT_GE(p.x[i], 1.0 - 1e-9);
        ASSERT_LE(p.x[i], 199.0 + 1e-9);
    }
    // Particles moved off the spawn point in all four quadrants, not along one line.
    int quadrant[4] = {0, 0, 0, 0};
    for (std::size_t i = 0; i < p.size(); ++i) {
        quadrant[(p.x[i] > 100.0 ? 1 : 0) + (p.y[i] > 100.0 ? 2 : 0)]++;
    }
    for (int q : quadrant)
        EXPECT_GT(q, 100);
}

TEST(Collision, FrictionReducesTangentialSlipWithoutAddingEnergy) {
    World w = openWorld(1.0, 0.3);
    const ParticleId a = w.add({.position = {0.0, 0.0}, .velocity = {1.0, 5.0}});
    const ParticleId b = w.add({.position = {1.9, 0.0}, .velocity = {-1.0, -5.0}});
    const double k0 = kineticEnergy(w);
    const Vec2 p0 = momentum(w);
    w.step(1e-14);
    // Normal impulse per unit mass is 2 (speed 1 reversed); the tangential speed of 5 is far
    // from sticking, so Coulomb caps the change at mu * 2 = 0.6.
    EXPECT_NEAR(w.get(a).velocity.x(), -1.0, 1e-12);
    EXPECT_NEAR(w.get(a).velocity.y(), 5.0 - 0.6, 1e-12);
    EXPECT_NEAR(w.get(b).velocity.y(), -5.0 + 0.6, 1e-12);
    EXPECT_LT(kineticEnergy(w), k0);
    EXPECT_LE((momentum(w) - p0).norm(), 1e-12);
}

TEST(Collision, KinematicParticlePushesOthersAndIsNotPushed) {
    World w = openWorld();
    const ParticleId held = w.add({.position = {0.0, 0.0}, .velocity = {2.0, 0.0}});
    const ParticleId other = w.add({.position = {1.8, 0.0}, .velocity = {0.0, 0.0}});
    w.setKinematic(held, true);
    w.step(1e-6);
    EXPECT_NEAR(w.get(held).velocity.x(), 2.0, 0.0);
    EXPECT_NEAR(w.get(other).velocity.x(), 4.0, 1e-12);  // rebound off an infinite mass
    EXPECT_NEAR(w.get(held).position.x(), 2e-6, 1e-15);  // moved only by its own velocity
    EXPECT_GE(w.get(other).position.x() - w.get(held).position.x(), 2.0 - 1e-12);
}

}  // namespace
}  // namespace psb
