// The exact mode's discs that turn on a floor or a segment's face: slipping under kinetic
// friction, the slip-to-roll instant, rolling, against their closed forms (rolls.cpp).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include <particle_sandbox/diagnostics.hpp>
#include <particle_sandbox/world.hpp>

namespace psb {
namespace {

constexpr double kG = 9.81;
constexpr double kFrame = 1.0 / 60.0;

SolverSettings exactMode() {
    return {.mode = StepMode::Exact};
}

/// What the test reads of the disc, along the surface.
struct Along {
    double distance;  ///< metres from the start
    double speed;     ///< m/s
    double omega;     ///< rad/s
};

/// A disc on the floor of a 20 × 2 m box (the box's wall, or a floor segment across it when
/// `onSegment`), e = 0, launched along +x at v0 with spin omega0.
struct Floor {
    World world;
    ParticleId disc;
    Vec2 start;

    Floor(double mu, double k, double v0, double omega0, bool onSegment, bool fixed = false)
        : world(WorldDef{.width = 20.0,
                         .height = 2.0,
                         .gravity = {0.0, kG},
                         .restitution = 0.0,
                         .friction = mu},
                exactMode()) {
        const double r = 0.2, thickness = 0.05, top = onSegment ? 1.5 - 0.5 * thickness : 2.0;
        if (onSegment) world.addObstacle(Obstacle::segment({0.5, 1.5}, {19.5, 1.5}, thickness));
        start = Vec2(1.0, top - r);
        disc = world.add({.position = start,
                          .velocity = {v0, 0.0},
                          .radius = r,
                          .angularVelocity = omega0,
                          .inertiaFactor = k,
                          .fixedRotation = fixed});
    }

    [[nodiscard]] Along read() const {
        const Particle p = world.get(disc);
        return {p.position.x() - start.x(), p.velocity.x(), p.angularVelocity};
    }
};

/// A segment 2 cm thick tilted `degrees` down to the right in a 30 m box, e = 0, friction mu,
/// with a disc (r = 0.2 m, inertia factor k) placed at rest on it, touching, 1 m from its upper
/// end.
struct Slope {
    World world;
    ParticleId disc;
    Vec2 start, along;

    Slope(double degrees, double mu, double k, bool fixed = false)
        : world(WorldDef{.width = 30.0,
                         .height = 30.0,
                         .gravity = {0.0, kG},
                         .restitution = 0.0,
                         .friction = mu},
                exactMode()) {
        const double theta = degrees * M_PI / 180.0, r = 0.2, h = 0.01;  // h: half-thickness
        const Vec2 a(1.0, 5.0);
        along = Vec2(std::cos(theta), std::sin(theta));
        const Vec2 normal(along.y(), -along.x());  // up, off the segment
        world.addObstacle(Obstacle::segment(a, a + 25.0 * along, 2.0 * h));
        start = a + 1.0 * along + (r + h) * normal;
        disc =
            world.add({.position = start, .radius = r, .inertiaFactor = k, .fixedRotation = fixed});
    }

    [[nodiscard]] Along read() const {
        const Particle p = world.get(disc);
        return {(p.position - start).dot(along), p.velocity.dot(along), p.angularVelocity};
    }
};

/// Steps `world` in frames up to `seconds` from its start, checking at every frame that the
/// energy (translational, rotational and potential) has not grown; returns the frames' energies.
std::vector<double> runFrames(World& world, double seconds) {
    std::vector<double> energy{mechanicalEnergy(world)};
    const int frames = static_cast<int>(std::lround(seconds / kFrame));
    for (int f = 0; f < frames; ++f) {
        world.step(kFrame);
        energy.push_back(mechanicalEnergy(world));
        EXPECT_LE(energy.back(), energy[energy.size() - 2] * (1.0 + 1e-12)) << "frame " << f;
    }
    return energy;
}

TEST(ExactRolling, ADiscLaunchedSlidingOnTheFloorRollsFromTStarAtV0OverOnePlusK) {
    // Slipping: v = v0 − μ g t, ω = μ g t / (k r); the slip v − ω r reaches 0 at
    // t* = k v0 / (μ g (1 + k)), and the disc rolls on at v0 / (1 + k), ω = v / r. On the box's
    // floor and on a floor segment alike, for a disc and a ball.
    const double v0 = 3.0, mu = 0.2, r = 0.2;
    for (const bool onSegment : {false, true}) {
        for (const double k : {0.5, 0.4}) {
            SCOPED_TRACE(testing::Message()
                         << (onSegment ? "segment" : "box floor") << ", k " << k);
            Floor f(mu, k, v0, 0.0, onSegment);
            const double tStar = k * v0 / (mu * kG * (1.0 + k));
            if (k == 0.5) {
                EXPECT_NEAR(tStar, 0.5097, 1e-4);
            }
            runFrames(f.world, 0.25);
            const double t = 0.25;
            Along s = f.read();
            EXPECT_NEAR(s.speed, v0 - mu * kG * t, 1e-9 * v0);
            EXPECT_NEAR(s.omega, mu * kG * t / (k * r), 1e-9 * v0 / r);
            EXPECT_NEAR(s.distance, v0 * t - 0.5 * mu * kG * t * t, 1e-9 * v0 * t);
            if (k == 0.5) {
                EXPECT_NEAR(s.speed, 2.5095, 1e-12);  // the figure
            }
            runFrames(f.world, 0.75);
            const std::vector<double> rolling = runFrames(f.world, 1.0);  // 1 s to 2 s
            s = f.read();
            const double vRoll = v0 / (1.0 + k);
            EXPECT_NEAR(s.speed, vRoll, 1e-9 * v0);
            EXPECT_NEAR(s.omega, vRoll / r, 1e-9 * v0 / r);
            const double sStar = v0 * tStar - 0.5 * mu * kG * tStar * tStar;
            EXPECT_NEAR(s.distance, sStar + vRoll * (2.0 - tStar), 1e-9 * s.distance);
            // Rolling keeps the energy: no friction work.
            EXPECT_NEAR(rolling.back(), rolling.front(), 1e-12 * rolling.front());
            // On the floor: the energy lost in the slip, ½ m v0² k / (1 + k).
            const double lost = 0.5 * v0 * v0 * k / (1.0 + k);
            EXPECT_NEAR(kineticEnergy(f.world) + rotationalEnergy(f.world), 0.5 * v0 * v0 - lost,
                        1e-9 * v0 * v0);
        }
    }
}

TEST(ExactRolling, RollingCostsNoEventsOfItsOwn) {
    // The landing (a contact event at once), the slip-to-roll instant, and nothing more in the
    // 2 s that follow but the cell moves of a disc crossing the grid.
    Floor f(0.2, 0.5, 3.0, 0.0, false);
    f.world.step(1.0);
    const StepCounters before = f.world.counters();
    EXPECT_EQ(before.events, 2u) << "the landing and the slip-to-roll instant";
    for (int k = 0; k < 120; ++k)
        f.world.step(kFrame);
    EXPECT_EQ(f.world.counters().events, before.events) << "rolling on the floor";
    // On a slope: rolling from rest, the only events are the landing's.
    Slope s(20.0, 0.2, 0.5);
    s.world.step(kFrame);
    const std::uint64_t landed = s.world.counters().events;
    EXPECT_LE(landed, 2u);
    for (int k = 0; k < 120; ++k)
        s.world.step(kFrame);
    EXPECT_EQ(s.world.counters().events, landed) << "rolling down the slope";
}

TEST(ExactRolling, ADiscWithBackspinSlowsTurnsBackAndRollsBack) {
    // v0 = 2 m/s with ω0 = −30 rad/s (r = 0.2, k = 1/2): the contact point slips forward at
    // v0 − ω0 r = 8 m/s, friction −μ g slows the centre through zero (no event there: the slip
    // keeps its sign) and spins ω up at μ g / (k r); the slip ends at t* = 8 / (μ g (1 + 1/k)),
    // where v = v0 − μ g t* < 0: it rolls back.
    const double v0 = 2.0, omega0 = -30.0, mu = 0.2, r = 0.2, k = 0.5;
    Floor f(mu, k, v0, omega0, false);
    const double slip0 = v0 - omega0 * r, tStar = slip0 / (mu * kG * (1.0 + 1.0 / k));
    const double vStar = v0 - mu * kG * tStar;
    EXPECT_LT(vStar, 0.0);
    EXPECT_NEAR(tStar, 1.359, 1e-3);
    runFrames(f.world, 1.0);
    Along s = f.read();
    EXPECT_NEAR(s.speed, v0 - mu * kG, 1e-9 * v0);
    EXPECT_NEAR(s.omega, omega0 + mu * kG / (k * r), 1e-9 * v0 / r);
    runFrames(f.world, 1.0);
    s = f.read();
    EXPECT_NEAR(s.speed, vStar, 1e-9 * v0);
    EXPECT_NEAR(s.omega, vStar / r, 1e-9 * v0 / r);
    const double sStar = v0 * tStar - 0.5 * mu * kG * tStar * tStar;
    EXPECT_NEAR(s.distance, sStar + vStar * (2.0 - tStar), 1e-9 * v0);
}

TEST(ExactRolling, DownASlopeAtGSinThetaOverOnePlusK) {
    // 20°, μ = 0.2 >= k tan θ / (1 + k) (0.121 for k = 1/2, 0.104 for 2/5): rolling from rest
    // without slipping, distance ½ g sin θ / (1 + k) t², ω = v / r, energy kept.
    const double theta = 20.0 * M_PI / 180.0, r = 0.2;
    for (const double k : {0.5, 0.4}) {
        SCOPED_TRACE(testing::Message() << "k " << k);
        Slope s(20.0, 0.2, k);
        const double a = kG * std::sin(theta) / (1.0 + k);
        const std::vector<double> energy = runFrames(s.world, 1.0);
        const Along roll = s.read();
        EXPECT_NEAR(roll.distance, 0.5 * a, 1e-9 * 0.5 * a);
        EXPECT_NEAR(roll.speed, a, 1e-9 * a);
        EXPECT_NEAR(roll.omega * r, roll.speed, 1e-9 * a);
        EXPECT_NEAR(energy.back(), energy.front(), 1e-12 * energy.front());
        // Measured at frames too, not only at the end.
        s.world.step(0.5);
        EXPECT_NEAR(s.read().distance, 0.5 * a * 1.5 * 1.5, 1e-9 * 0.5 * a * 1.5 * 1.5);
    }
}

TEST(ExactRolling, WithinTheFrictionAngleADiscThatTurnsStillRollsWhereABlockStays) {
    // 10°, μ = 0.2: the slope is inside the friction angle (11.3°), so static friction holds a
    // block there (asleep), but a disc that turns cannot be held on a single tilted face: it
    // rolls down at g sin θ / (1 + k) (μ >= k tan θ / (1 + k) = 0.059).
    const double theta = 10.0 * M_PI / 180.0, k = 0.5;
    Slope turns(10.0, 0.2, k), block(10.0, 0.2, k, true);
    runFrames(turns.world, 1.0);
    runFrames(block.world, 1.0);
    const double a = kG * std::sin(theta) / (1.0 + k);
    EXPECT_NEAR(turns.read().distance, 0.5 * a, 1e-9 * 0.5 * a);
    EXPECT_NEAR(turns.read().speed, a, 1e-9 * a);
    EXPECT_LT(std::abs(block.read().distance), 1e-9);
    const std::uint64_t events = block.world.counters().events;
    runFrames(block.world, 0.5);
    EXPECT_EQ(block.world.counters().events, events) << "asleep";
}

TEST(ExactRolling, TooLittleFrictionSlidesWithSpin) {
    // 20°, μ = 0.05 < k tan θ / (1 + k) = 0.121: the disc slips for good, at
    // a = g (sin θ − μ cos θ), while friction spins it up at α = μ g cos θ / (k r).
    const double theta = 20.0 * M_PI / 180.0, mu = 0.05, k = 0.5, r = 0.2;
    Slope s(20.0, mu, k);
    const double a = kG * (std::sin(theta) - mu * std::cos(theta));
    const double alpha = mu * kG * std::cos(theta) / (k * r);
    // Placed touching to rounding, the disc may start a hair above the face and land within
    // nanoseconds, picking up g sin θ instead of a for that while (2e-9 s measured): the closed
    // form is compared over the second after the first quarter.
    runFrames(s.world, 0.25);
    const Along early = s.read();
    EXPECT_NEAR(early.distance, 0.5 * a * 0.25 * 0.25, 1e-7);
    runFrames(s.world, 1.0);
    const Along slip = s.read();
    EXPECT_NEAR(slip.distance - early.distance, early.speed + 0.5 * a, 1e-9 * 0.5 * a);
    EXPECT_NEAR(slip.speed - early.speed, a, 1e-9 * a);
    EXPECT_NEAR(slip.omega - early.omega, alpha, 1e-9 * alpha);
    EXPECT_GT(slip.speed, slip.omega * r) << "still slipping";
}

TEST(ExactRolling, ADiscThatDoesNotTurnStillSlidesAsABlock) {
    // Fixed rotation: g (sin θ − μ cos θ) on the slope, ω stays 0.
    const double theta = 20.0 * M_PI / 180.0, mu = 0.2;
    Slope s(20.0, mu, 0.5, true);
    const double a = kG * (std::sin(theta) - mu * std::cos(theta));
    runFrames(s.world, 0.25);  // the landing, as above
    const Along early = s.read();
    EXPECT_NEAR(early.distance, 0.5 * a * 0.25 * 0.25, 1e-7);
    runFrames(s.world, 1.0);
    const Along slide = s.read();
    EXPECT_NEAR(slide.distance - early.distance, early.speed + 0.5 * a, 1e-9 * 0.5 * a);
    EXPECT_NEAR(slide.speed - early.speed, a, 1e-9 * a);
    EXPECT_EQ(slide.omega, 0.0);
}

TEST(ExactRolling, ADiscRollingIntoASideWallFallsBackToTheFloorAndRollsBack) {
    // In a 2 m box (e = 0.3, μ = 0.2) a disc launched at 3 m/s rolls into the right wall, whose
    // friction on its spin kicks it up the wall: it leaves the floor, falls back under gravity,
    // comes to rest on it again and rolls back. (It once kept the floor's rest after the kick
    // and rose for ever at a constant speed, without gravity.)
    World world(
        WorldDef{
            .width = 2.0, .height = 2.0, .gravity = {0.0, kG}, .restitution = 0.3, .friction = 0.2},
        exactMode());
    const double r = 0.2;
    const ParticleId id =
        world.add({.position = {1.0, 2.0 - r}, .velocity = {3.0, 0.0}, .radius = r});
    double highest = 2.0 - r;
    const int frames = static_cast<int>(std::lround(3.0 / kFrame));
    double energy = mechanicalEnergy(world);
    for (int f = 0; f < frames; ++f) {
        world.step(kFrame);
        const Particle p = world.get(id);
        highest = std::min(highest, p.position.y());
        EXPECT_LE(p.position.y(), 2.0 - r + 1e-12) << "frame " << f;
        const double now = mechanicalEnergy(world);
        EXPECT_LE(now, energy * (1.0 + 1e-12)) << "frame " << f;
        energy = now;
    }
    EXPECT_LT(highest, 2.0 - r - 1e-3) << "kicked up the wall";
    const Particle p = world.get(id);
    EXPECT_EQ(p.position.y(), 2.0 - r);
    EXPECT_EQ(p.velocity.y(), 0.0);
    EXPECT_LT(p.velocity.x(), -0.3);
    EXPECT_NEAR(p.angularVelocity * r, p.velocity.x(), 1e-9) << "rolling back";
}

/// Steps a disc that does not turn, launched at 3 m/s along the box's floor (μ = 0.2, r = 0.2,
/// e = 0), in `mode` at frames of dt for `seconds`: where it is then along the floor.
Along blockOnTheFloor(SolverSettings solver, double dt, double seconds) {
    World world(WorldDef{.width = 20.0,
                         .height = 2.0,
                         .gravity = {0.0, kG},
                         .restitution = 0.0,
                         .friction = 0.2},
                solver);
    const ParticleId id = world.add(
        {.position = {1.0, 1.8}, .velocity = {3.0, 0.0}, .radius = 0.2, .fixedRotation = true});
    const int steps = static_cast<int>(std::lround(seconds / dt));
    for (int k = 0; k < steps; ++k)
        world.step(dt);
    const Particle p = world.get(id);
    return {p.position.x() - 1.0, p.velocity.x(), p.angularVelocity};
}

TEST(ExactRolling, ABlockSlidingOnTheFloorSlowsAtMuGAndStopsAsleep) {
    // A disc that does not turn has nothing to roll with: it slides at v = v0 − μ g t until it
    // stops, at t = v0 / (μ g) = 1.529 s, after v0² / (2 μ g) = 2.294 m; on the box's floor as
    // on a floor segment (slides.cpp's block).
    const double v0 = 3.0, mu = 0.2, tStop = v0 / (mu * kG), sStop = v0 * v0 / (2.0 * mu * kG);
    for (const bool onSegment : {false, true}) {
        SCOPED_TRACE(onSegment ? "segment" : "box floor");
        Floor f(mu, 0.5, v0, 0.0, onSegment, true);
        runFrames(f.world, 0.25);
        Along s = f.read();
        EXPECT_NEAR(s.speed, v0 - mu * kG * 0.25, 1e-9 * v0);
        EXPECT_NEAR(s.speed, 2.5095, 1e-12);  // the figure
        EXPECT_NEAR(s.distance, v0 * 0.25 - 0.5 * mu * kG * 0.25 * 0.25, 1e-9 * v0 * 0.25);
        EXPECT_EQ(s.omega, 0.0);
        runFrames(f.world, 1.0);
        s = f.read();
        EXPECT_NEAR(s.speed, v0 - mu * kG * 1.25, 1e-9 * v0);
        EXPECT_NEAR(s.distance, v0 * 1.25 - 0.5 * mu * kG * 1.25 * 1.25, 1e-9 * sStop);
        runFrames(f.world, 0.75);  // past the stop at 1.529 s
        s = f.read();
        EXPECT_EQ(s.speed, 0.0);
        EXPECT_NEAR(s.distance, sStop, 1e-9 * sStop);
        EXPECT_GT(2.0, tStop);
        // Stopped, it sleeps: no events at all from there.
        const std::uint64_t events = f.world.counters().events;
        runFrames(f.world, 1.0);
        EXPECT_EQ(f.world.counters().events, events);
        EXPECT_EQ(f.read().distance, s.distance);
    }
}

TEST(ExactRolling, ABlockSlidingOnTheFloorCostsTheLandingAndTheStop) {
    Floor f(0.2, 0.5, 3.0, 0.0, false, true);
    f.world.step(1.0);
    EXPECT_EQ(f.world.counters().events, 1u) << "the landing";
    f.world.step(1.0);
    EXPECT_EQ(f.world.counters().events, 2u) << "the stop at 1.529 s";
}

TEST(ExactRolling, ABlockOnTheFloorAgreesWithTheSubstepModeToItsError) {
    // The substep mode gives the floor's friction μ g h a substep (h = dt / substeps): its
    // velocity is exact to rounding while the block slides, and its distance ahead by its first
    // order error μ g t h / 2 (measured 1.02 mm at 0.25 s, 4.09 mm at 1 s), v0 h / 2 = 6.25 mm
    // once stopped (2 s).
    const double mu = 0.2, v0 = 3.0, tStop = v0 / (mu * kG);
    const SolverSettings substep{.mode = StepMode::Substep, .substeps = 4};
    const double h = kFrame / 4.0;
    for (const double t : {0.25, 1.0, 2.0}) {
        SCOPED_TRACE(testing::Message() << "t " << t);
        const Along exact = blockOnTheFloor(exactMode(), kFrame, t);
        const Along stepped = blockOnTheFloor(substep, kFrame, t);
        EXPECT_NEAR(stepped.speed, exact.speed, 1e-12);
        EXPECT_NEAR(stepped.distance - exact.distance, 0.5 * mu * kG * std::min(t, tStop) * h,
                    1e-6);
        EXPECT_EQ(stepped.omega, 0.0);
        EXPECT_EQ(exact.omega, 0.0);
    }
}

TEST(ExactRolling, ABlockOnTheFloorUnderSlantedGravityStopsOrSlidesBack) {
    // Gravity (2, 9.81): g_t = 2 along the floor, g_n = 9.81 into it. Launched at −3 m/s (against
    // g_t) the block slows at g_t + μ g_n until it stops at t1; there static friction holds it
    // if g_t <= μ g_n (μ = 0.3: asleep, still) or it slides back at g_t − μ g_n (μ = 0.1).
    const double gt = 2.0, gn = kG, v0 = -3.0;
    for (const double mu : {0.3, 0.1}) {
        SCOPED_TRACE(testing::Message() << "mu " << mu);
        World world(WorldDef{.width = 40.0,
                             .height = 2.0,
                             .gravity = {gt, gn},
                             .restitution = 0.0,
                             .friction = mu},
                    exactMode());
        const ParticleId id = world.add(
            {.position = {30.0, 1.8}, .velocity = {v0, 0.0}, .radius = 0.2, .fixedRotation = true});
        const double a1 = gt + mu * gn, t1 = -v0 / a1, s1 = v0 * t1 + 0.5 * a1 * t1 * t1;
        runFrames(world, 0.5);
        Particle p = world.get(id);
        EXPECT_NEAR(p.velocity.x(), v0 + a1 * 0.5, 1e-9 * 3.0);
        EXPECT_NEAR(p.position.x() - 30.0, v0 * 0.5 + 0.5 * a1 * 0.25, 1e-9 * 3.0);
        EXPECT_EQ(p.velocity.y(), 0.0);
        world.step(2.0 - 0.5);
        p = world.get(id);
        const double back = 2.0 - t1;
        if (gt <= mu * gn) {
            EXPECT_EQ(p.velocity.x(), 0.0);
            EXPECT_NEAR(p.position.x() - 30.0, s1, 1e-9 * 3.0);
        } else {
            const double a2 = gt - mu * gn;
            EXPECT_NEAR(p.velocity.x(), a2 * back, 1e-9 * 3.0);
            EXPECT_NEAR(p.position.x() - 30.0, s1 + 0.5 * a2 * back * back, 1e-9 * 3.0);
        }
        EXPECT_NEAR(p.position.y(), 1.8, 1e-12);
    }
}

}  // namespace
}  // namespace psb
