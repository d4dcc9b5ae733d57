// Discs that turn, in a world: the rotation API, conservation by rough contacts in every mode,
// and rolling against its closed forms.

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <particle_sandbox/diagnostics.hpp>
#include <particle_sandbox/error.hpp>
#include <particle_sandbox/world.hpp>

namespace psb {
namespace {

constexpr double kG = 9.81;

SolverSettings modeOf(StepMode mode) {
    return {.mode = mode, .substeps = mode == StepMode::Substep ? 4 : 1};
}

const char* nameOf(StepMode mode) {
    return mode == StepMode::Discrete  ? "discrete"
           : mode == StepMode::Substep ? "substep"
                                       : "exact";
}

// --- the API ------------------------------------------------------------------------------

TEST(Rotation, AWorldKeepsNoRotationUntilAParticleOrFrictionNeedsIt) {
    World w;
    const ParticleId a = w.add({.position = {10.0, 10.0}, .velocity = {1.0, 0.0}});
    EXPECT_FALSE(w.rotationInUse());
    EXPECT_TRUE(w.particles().omega.empty());
    // Defaults change nothing.
    w.setAngularVelocity(a, 0.0);
    w.setInertiaFactor(a, 0.5);
    w.setFixedRotation(a, false);
    w.setAngle(a, 0.0);
    EXPECT_FALSE(w.rotationInUse());
    const Particle p = w.get(a);
    EXPECT_EQ(p.angle, 0.0);
    EXPECT_EQ(p.angularVelocity, 0.0);
    EXPECT_EQ(p.inertiaFactor, kDefaultInertiaFactor);
    EXPECT_FALSE(p.fixedRotation);
    // Spin makes the arrays, every particle with the defaults but the one set.
    const ParticleId b = w.add({.position = {20.0, 10.0}});
    w.setAngularVelocity(b, 2.0);
    EXPECT_TRUE(w.rotationInUse());
    EXPECT_EQ(w.particles().omega.size(), 2u);
    EXPECT_EQ(w.get(a).angularVelocity, 0.0);
    EXPECT_EQ(w.get(b).angularVelocity, 2.0);
    // Friction does too, at the first step.
    World f;
    f.setFriction(0.3);
    f.add({.position = {10.0, 10.0}});
    EXPECT_FALSE(f.rotationInUse());
    f.step(0.01);
    EXPECT_TRUE(f.rotationInUse());
}

TEST(Rotation, SettersRefuseBadValuesNamingThem) {
    World w;
    const ParticleId a = w.add({.position = {10.0, 10.0}});
    auto message = [&](auto&& f) {
        try {
            f();
        } catch (const InvalidArgument& e) {
            return std::string(e.what());
        }
        return std::string("no throw");
    };
    EXPECT_NE(
        message([&] { w.setInertiaFactor(a, 0.0); }).find("inertia factor must be from 0.001 to 1"),
        std::string::npos);
    // A denormal k: every contact of the disc would divide by it (NaN spins).
    EXPECT_NE(message([&] { w.setInertiaFactor(a, 1e-320); }).find("must be from 0.001 to 1"),
              std::string::npos);
    EXPECT_NE(message([&] { w.setInertiaFactor(a, 1.5); }).find("(got 1.5)"), std::string::npos);
    EXPECT_NE(
        message([&] { w.setAngularVelocity(a, NAN); }).find("angular velocity must be finite"),
        std::string::npos);
    EXPECT_NE(message([&] { w.setAngle(a, INFINITY); }).find("angle must be finite"),
              std::string::npos);
    EXPECT_NE(message([&] {
                  w.setTangentialRestitution(1.5);
              }).find("tangential restitution must be in [-1, 1] (got 1.5)"),
              std::string::npos);
    EXPECT_THROW(w.setTangentialRestitution(-1.01), InvalidArgument);
    EXPECT_THROW(w.add({.inertiaFactor = -0.1}), InvalidArgument);
    EXPECT_THROW(w.add({.angularVelocity = 1.0, .fixedRotation = true}), InvalidArgument);
    // A fixed-rotation particle turns at no speed but 0.
    w.setAngularVelocity(a, 4.0);
    w.setFixedRotation(a, true);
    EXPECT_EQ(w.get(a).angularVelocity, 0.0);
    EXPECT_NE(message([&] { w.setAngularVelocity(a, 1.0); }).find("fixed-rotation"),
              std::string::npos);
    // Nothing was changed by a refused call.
    EXPECT_EQ(w.get(a).inertiaFactor, kDefaultInertiaFactor);
    EXPECT_EQ(w.def().tangentialRestitution, 0.0);
    w.setTangentialRestitution(-1.0);
    EXPECT_EQ(w.def().tangentialRestitution, -1.0);
}

TEST(Rotation, AFreeDiscTurnsAtItsAngularVelocityInEveryMode) {
    for (const StepMode mode : {StepMode::Discrete, StepMode::Substep, StepMode::Exact}) {
        World w(WorldDef{.width = 10.0, .height = 10.0}, modeOf(mode));
        const ParticleId a = w.add({.position = {5.0, 5.0},
                                    .velocity = {0.1, 0.0},
                                    .angle = 0.5,
                                    .angularVelocity = -3.0});
        for (int k = 0; k < 100; ++k)
            w.step(0.01);
        EXPECT_NEAR(w.get(a).angle, 0.5 - 3.0 * 1.0, 1e-12) << nameOf(mode);
        EXPECT_EQ(w.get(a).angularVelocity, -3.0) << nameOf(mode);
    }
}

TEST(Rotation, TheExactModeTurnsADiscAtItsWallImpactInstant) {
    // r = 1, ω = 2 rad/s, moving left at 1 m/s from x = 5: it meets the left wall (outward
    // normal +x, tangent +y) at t = 4 s. Its contact point slips at −ω r = −2 m/s; sticking
    // (μ large, β = 0) gives the impulse per unit mass 2 / (1 + 1/k) = 2/3 along +y, so
    // vy = 2/3 and ω = 2 − (2/3)(1/k)/r = 2/3: it leaves rolling up the wall. The angle at 5 s
    // is 2·4 + (2/3)·1.
    World w(WorldDef{.width = 10.0, .height = 10.0, .restitution = 1.0, .friction = 100.0},
            modeOf(StepMode::Exact));
    const ParticleId a =
        w.add({.position = {5.0, 5.0}, .velocity = {-1.0, 0.0}, .angularVelocity = 2.0});
    w.step(5.0);
    const Particle p = w.get(a);
    EXPECT_NEAR(p.velocity.x(), 1.0, 1e-15);
    EXPECT_NEAR(p.velocity.y(), 2.0 / 3.0, 1e-15);
    EXPECT_NEAR(p.angularVelocity, 2.0 / 3.0, 1e-15);
    EXPECT_NEAR(p.angle, 8.0 + 2.0 / 3.0, 1e-12);
    EXPECT_NEAR(p.position.y(), 5.0 + 2.0 / 3.0, 1e-12);
}

TEST(Rotation, RemoveAndReorderKeepEachParticlesRotation) {
    // 5000 discs: the discrete mode sorts its storage by cell; every particle keeps its own.
    World w(WorldDef{.width = 400.0, .height = 400.0, .friction = 0.0});
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<ParticleId> ids;
    for (int k = 0; k < 5000; ++k) {
        ids.push_back(w.add({.position = {400.0 * u(rng), 400.0 * u(rng)},
                             .velocity = {u(rng) - 0.5, u(rng) - 0.5},
                             .radius = 0.5,
                             .angularVelocity = static_cast<double>(k),
                             .inertiaFactor = 0.1 + 0.8 * u(rng)}));
    }
    w.remove(ids[17]);
    w.step(0.01);
    w.step(0.01);
    for (std::size_t k = 0; k < ids.size(); ++k) {
        if (k == 17) continue;
        ASSERT_EQ(w.get(ids[k]).angularVelocity, static_cast<double>(k));
        ASSERT_NEAR(w.get(ids[k]).angle, 0.02 * static_cast<double>(k), 1e-9);
    }
}

// --- conservation ---------------------------------------------------------------------------

/// A frictional, inelastic cluster in free space: discs of random sizes, masses, inertia
/// factors and spins converging on a point.
World cluster(StepMode mode, double e, double mu, double beta, std::uint64_t seed) {
    WorldDef def{.width = 100.0, .height = 100.0, .walls = false, .restitution = e, .friction = mu};
    def.tangentialRestitution = beta;
    World w(def, modeOf(mode));
    w.setThreads(1);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int i = 0; i < 6; ++i) {
        for (int j = 0; j < 6; ++j) {
            const double x = 40.0 + 4.0 * i + u(rng), y = 40.0 + 4.0 * j + u(rng);
            w.add({.position = {x, y},
                   .velocity = {50.0 - x + u(rng) - 0.5, 50.0 - y + u(rng) - 0.5},
                   .mass = 0.5 + u(rng),
                   .radius = 0.9 + 0.5 * u(rng),
                   .angularVelocity = 4.0 * u(rng) - 2.0,
                   .inertiaFactor = 0.2 + 0.8 * u(rng)});
        }
    }
    return w;
}

TEST(Rotation, RoughInelasticClusterKeepsItsAngularMomentumInTheExactMode) {
    // Orbital plus spin, about the origin and about a far point, to 1e-12 relative.
    World w = cluster(StepMode::Exact, 0.5, 0.6, 0.3, 42);
    const double l0 = angularMomentum(w), l0far = angularMomentum(w, Vec2(-300.0, 700.0));
    for (int k = 0; k < 60; ++k)
        w.step(1.0 / 60.0);
    EXPECT_GT(w.counters().collisions, 300u);
    EXPECT_NEAR(angularMomentum(w), l0, 1e-12 * std::abs(l0));
    EXPECT_NEAR(angularMomentum(w, Vec2(-300.0, 700.0)), l0far, 1e-12 * std::abs(l0far));
}

TEST(Rotation, DiscreteModesKeepAngularMomentumToFirstOrderInDt) {
    // Each rough pair contact keeps orbital plus spin angular momentum (contact_test.cpp), but
    // the discrete modes resolve pairs that overlap: the contact's lever arms r_i + r_j are
    // longer than the centres' distance, and the separate stage pushes the pair apart without
    // changing velocities. Both change the orbital part by amounts proportional to the overlap,
    // that is to dt (docs/physics.md). Measured over 0.5 s: the drift falls tenfold with dt.
    for (const StepMode mode : {StepMode::Discrete, StepMode::Substep}) {
        double drift[2];
        for (int c = 0; c < 2; ++c) {
            const double dt = c == 0 ? 1e-3 : 1e-4;
            World w = cluster(mode, 0.5, 0.6, 0.3, 42);
            const double l0 = angularMomentum(w);
            for (int k = 0; k < static_cast<int>(std::lround(0.5 / dt)); ++k)
                w.step(dt);
            EXPECT_GT(w.counters().collisions, 100u) << nameOf(mode);
            drift[c] = std::abs(angularMomentum(w) - l0) / std::abs(l0);
        }
        SCOPED_TRACE(nameOf(mode));
        EXPECT_LT(drift[0], 1e-3);
        EXPECT_LT(drift[1], 1e-4);
    }
}

TEST(Rotation, EnergyNeverGrowsForTangentialRestitutionUpToOneInEveryMode) {
    for (const StepMode mode : {StepMode::Discrete, StepMode::Substep, StepMode::Exact}) {
        for (const double beta : {-1.0, 0.0, 0.5, 1.0}) {
            World w = cluster(mode, 0.7, 0.4, beta, 9);
            double last = kineticEnergy(w) + rotationalEnergy(w);
            for (int k = 0; k < 120; ++k) {
                w.step(1.0 / 120.0);
                const double now = kineticEnergy(w) + rotationalEnergy(w);
                ASSERT_LE(now, last * (1.0 + 1e-12)) << nameOf(mode) << " beta " << beta;
                last = now;
            }
            EXPECT_GT(w.counters().collisions, 30u);
        }
    }
}

TEST(Rotation, PerfectlyRoughElasticGasKeepsItsEnergyInTheExactMode) {
    // e = 1, β = 1, friction that never caps: every contact (pair and wall) reverses both the
    // normal and the tangential velocity of the contact points and keeps kinetic energy,
    // translation plus rotation, which flows between the two.
    WorldDef def{.width = 20.0, .height = 20.0, .restitution = 1.0, .friction = 1e9};
    def.tangentialRestitution = 1.0;
    World w(def, modeOf(StepMode::Exact));
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int i = 0; i < 10; ++i)
        for (int j = 0; j < 10; ++j)
            w.add({.position = {1.0 + 2.0 * i, 1.0 + 2.0 * j},
                   .velocity = {4.0 * u(rng) - 2.0, 4.0 * u(rng) - 2.0},
                   .radius = 0.7});
    const double e0 = kineticEnergy(w) + rotationalEnergy(w);
    EXPECT_EQ(rotationalEnergy(w), 0.0);
    for (int k = 0; k < 300; ++k)
        w.step(1.0 / 60.0);
    EXPECT_GT(w.counters().collisions, 500u);
    EXPECT_GT(rotationalEnergy(w), 0.1 * e0);  // spin picked up
    EXPECT_NEAR(kineticEnergy(w) + rotationalEnergy(w), e0, 1e-9 * e0);
}

TEST(Rotation, PerfectlyRoughElasticGasSharesItsEnergyByEquipartition) {
    // e = 1, β = 1, friction that never caps, every disc without spin at the start: in
    // equilibrium each degree of freedom holds ½ kT, so the rotational energy (one degree per
    // disc in 2-D) settles at one half of the translational (two). 400 discs (r = 0.5 m, k = ½)
    // at packing 0.2, 10 s to settle (~2300 collisions), then the energies averaged over 200 s
    // sampled every 0.1 s, in 20 blocks of 10 s; the statistical error is the standard error of
    // the 20 block ratios. Measured: 0.498 ± 0.004 (seeds 1–5 over 50 s: 0.488–0.512, errors
    // 0.007–0.013).
    WorldDef def{.width = 40.0, .height = 40.0, .restitution = 1.0, .friction = 1e9};
    def.tangentialRestitution = 1.0;
    World w(def, modeOf(StepMode::Exact));
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int i = 0; i < 20; ++i)
        for (int j = 0; j < 20; ++j)
            w.add({.position = {1.0 + 2.0 * i, 1.0 + 2.0 * j},
                   .velocity = {4.0 * u(rng) - 2.0, 4.0 * u(rng) - 2.0},
                   .radius = 0.5});
    const double e0 = kineticEnergy(w);
    for (int k = 0; k < 100; ++k)
        w.step(0.1);
    constexpr int kBlocks = 20, kSamples = 100;
    std::vector<double> ratio;
    for (int b = 0; b < kBlocks; ++b) {
        double rotational = 0.0, translational = 0.0;
        for (int s = 0; s < kSamples; ++s) {
            w.step(0.1);
            rotational += rotationalEnergy(w);
            translational += kineticEnergy(w);
        }
        ratio.push_back(rotational / translational);
    }
    double mean = 0.0;
    for (const double r : ratio)
        mean += r / kBlocks;
    double variance = 0.0;
    for (const double r : ratio)
        variance += (r - mean) * (r - mean) / (kBlocks - 1);
    const double error = std::sqrt(variance / kBlocks);
    RecordProperty("rotational_over_translational", std::to_string(mean));
    RecordProperty("standard_error", std::to_string(error));
    EXPECT_GT(w.counters().collisions, 40000u);
    EXPECT_LT(error, 0.01);
    EXPECT_NEAR(mean, 0.5, 4.0 * error) << "standard error " << error;
    EXPECT_NEAR(kineticEnergy(w) + rotationalEnergy(w), e0, 1e-9 * e0);
}

// --- rolling --------------------------------------------------------------------------------

struct Roll {
    double distance;  ///< along the surface, metres
    double speed;     ///< along the surface, m/s
    double omega;     ///< rad/s
};

/// A disc (r = 0.2 m, k = 1/2) set at rest on a segment tilted `degrees` down to the right,
/// e = 0, friction mu: where it is after `seconds`.
Roll rollDownSegment(StepMode mode, int substeps, double dt, double degrees, double mu,
                     double seconds) {
    const double theta = degrees * M_PI / 180.0, r = 0.2, h = 0.02;
    WorldDef def{
        .width = 30.0, .height = 30.0, .gravity = {0.0, kG}, .restitution = 0.0, .friction = mu};
    const Vec2 a(1.0, 5.0), along(std::cos(theta), std::sin(theta));
    const Vec2 normal(along.y(), -along.x());  // up, off the segment
    def.obstacles = {Obstacle::segment(a, a + 25.0 * along, h)};
    World w(def, {.mode = mode, .substeps = substeps});
    const Vec2 start = a + 1.0 * along + (r + h) * normal;
    const ParticleId id = w.add({.position = start, .radius = r});
    const int steps = static_cast<int>(std::lround(seconds / dt));
    for (int k = 0; k < steps; ++k)
        w.step(dt);
    const Particle p = w.get(id);
    return {(p.position - start).dot(along), p.velocity.dot(along), p.angularVelocity};
}

TEST(Rolling, DownASlopeAtGSinThetaOverOnePlusKInTheDiscreteModes) {
    // 20°, μ = 0.2 >= k tan θ / (1 + k) = 0.121: rolling without slipping, a = g sin θ / 1.5,
    // distance ½ a t² and ω = v / r after 1 s. Errors against dt (docs/accuracy.md).
    const double theta = 20.0 * M_PI / 180.0, a = kG * std::sin(theta) / 1.5, t = 1.0;
    struct Case {
        StepMode mode;
        int substeps;
        double dt, tolerance;
    };
    // The velocity is exact to rounding (a constant acceleration, integrated by the step's
    // v += a dt then x += v dt); the distance is ahead by about a t dt / 2 and the first
    // step's contact (measured: 3.4e-2 at dt = 1/60, 9.3e-3 at 1/240, 3.2e-3 at 1/960).
    for (const Case c : {Case{StepMode::Discrete, 1, 1.0 / 60.0, 0.04},
                         Case{StepMode::Discrete, 1, 1.0 / 240.0, 0.01},
                         Case{StepMode::Discrete, 1, 1.0 / 960.0, 0.0035},
                         Case{StepMode::Substep, 4, 1.0 / 60.0, 0.01}}) {
        const Roll roll = rollDownSegment(c.mode, c.substeps, c.dt, 20.0, 0.2, t);
        SCOPED_TRACE(testing::Message() << nameOf(c.mode) << " dt " << c.dt);
        EXPECT_NEAR(roll.distance, 0.5 * a * t * t, c.tolerance * 0.5 * a * t * t);
        EXPECT_GT(roll.distance, 0.5 * a * t * t);
        EXPECT_NEAR(roll.speed, a * t, 1e-12 * a * t);
        EXPECT_NEAR(roll.omega * 0.2, roll.speed, 1e-12 * a * t);
    }
}

/// A disc (r = 0.2 m, k = 1/2, μ = 0.2) launched sliding at v0 = 3 m/s along the floor
/// without spin: velocity and angular velocity after `seconds`.
Roll slideOnTheFloor(StepMode mode, int substeps, double dt, double seconds) {
    const double r = 0.2;
    World w(WorldDef{.width = 20.0,
                     .height = 2.0,
                     .gravity = {0.0, kG},
                     .restitution = 0.0,
                     .friction = 0.2},
            {.mode = mode, .substeps = substeps});
    const ParticleId id = w.add({.position = {1.0, 2.0 - r}, .velocity = {3.0, 0.0}, .radius = r});
    const int steps = static_cast<int>(std::lround(seconds / dt));
    for (int k = 0; k < steps; ++k)
        w.step(dt);
    const Particle p = w.get(id);
    return {p.position.x() - 1.0, p.velocity.x(), p.angularVelocity};
}

TEST(Rolling, ADiscLaunchedSlidingOnTheFloorRollsFromTStarAtTwoThirdsV0) {
    // Sliding: v = v0 − μ g t, ω = μ g t (1/k) / r; from t* = k v0 / (μ g (1 + k)) = 0.5097 s
    // it rolls at v0 / (1 + k) = 2 m/s, ω = 10 rad/s.
    const double v0 = 3.0, mu = 0.2, r = 0.2, k = 0.5;
    const double tStar = k * v0 / (mu * kG * (1.0 + k));
    EXPECT_NEAR(tStar, 0.5097, 1e-4);
    struct Case {
        StepMode mode;
        int substeps;
        double dt, tolerance;
    };
    // v and ω are exact to rounding (1e-12): the floor's contact gives μ g dt of friction a
    // step, and sticking stops the slip exactly. The distance is first order in dt: measured
    // 8.4e-3 m at dt = 1/60, 2.1e-3 at 1/240, 5.2e-4 at 1/960 after 2 s.
    for (const Case c : {Case{StepMode::Discrete, 1, 1.0 / 60.0, 9e-3},
                         Case{StepMode::Discrete, 1, 1.0 / 240.0, 2.2e-3},
                         Case{StepMode::Discrete, 1, 1.0 / 960.0, 5.5e-4},
                         Case{StepMode::Substep, 4, 1.0 / 60.0, 2.2e-3}}) {
        SCOPED_TRACE(testing::Message() << nameOf(c.mode) << " dt " << c.dt);
        const Roll sliding = slideOnTheFloor(c.mode, c.substeps, c.dt, 0.25);
        EXPECT_NEAR(sliding.speed, v0 - mu * kG * 0.25, 1e-12 * v0);
        EXPECT_NEAR(sliding.omega, mu * kG * 0.25 / (k * r), 1e-12 * v0 / r);
        const Roll rolling = slideOnTheFloor(c.mode, c.substeps, c.dt, 2.0);
        EXPECT_NEAR(rolling.speed, v0 / (1.0 + k), 1e-12 * v0);
        EXPECT_NEAR(rolling.omega, v0 / ((1.0 + k) * r), 1e-12 * v0 / r);
        // Distance: sliding to t*, then rolling.
        const double sStar = v0 * tStar - 0.5 * mu * kG * tStar * tStar;
        EXPECT_NEAR(rolling.distance, sStar + v0 / (1.0 + k) * (2.0 - tStar), c.tolerance);
    }
}

}  // namespace
}  // namespace psb
