// The rough contacts of contact.hpp, one contact at a time: what they conserve, what they
// lose, and which way they turn a disc.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "contact/contact.hpp"

namespace psb {
namespace {

/// One disc as a rough contact sees it.
struct Disc {
    double x, y, vx, vy, omega, m, r, k;
    bool fixed = false;
    [[nodiscard]] double w() const { return 1.0 / m; }
    [[nodiscard]] double q() const { return fixed ? 0.0 : 1.0 / k; }
    [[nodiscard]] double inertia() const { return fixed ? 0.0 : k * m * r * r; }
    [[nodiscard]] double energy() const {
        return 0.5 * m * (vx * vx + vy * vy) + 0.5 * inertia() * omega * omega;
    }
    /// Angular momentum about (px, py): m (r − p) × v + I ω.
    [[nodiscard]] double angularMomentum(double px, double py) const {
        return m * ((x - px) * vy - (y - py) * vx) + inertia() * omega;
    }
};

/// Two touching discs with random masses, radii, inertia factors and motion, i's centre at
/// the origin and j's along a random normal.
struct Pair {
    Disc i, j;
    Normal n;
};

Pair randomPair(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const double angle = 2.0 * M_PI * u(rng);
    const Normal n{std::cos(angle), std::sin(angle)};
    auto disc = [&](double x, double y) {
        return Disc{x,
                    y,
                    4.0 * u(rng) - 2.0,
                    4.0 * u(rng) - 2.0,
                    20.0 * u(rng) - 10.0,
                    std::exp(4.0 * u(rng) - 2.0),
                    0.05 + u(rng),
                    0.05 + 0.95 * u(rng),
                    u(rng) < 0.15};
    };
    Disc i = disc(0.0, 0.0);
    Disc j = disc(0.0, 0.0);
    // A disc that never turns has no spin (World keeps its angular velocity at 0).
    if (i.fixed) i.omega = 0.0;
    if (j.fixed) j.omega = 0.0;
    j.x = (i.r + j.r) * n.x;
    j.y = (i.r + j.r) * n.y;
    return {i, j, n};
}

bool collide(Pair& c, const RoughLaws& laws) {
    return collideRoughDiscs(c.i.vx, c.i.vy, {c.i.omega, c.i.r, c.i.q()}, c.j.vx, c.j.vy,
                             {c.j.omega, c.j.r, c.j.q()}, c.i.w(), c.j.w(), c.i.m, c.j.m, c.n,
                             laws);
}

TEST(RoughContact, PairConservesMomentumAndAngularMomentumAboutAnyPoint) {
    std::mt19937_64 rng(25);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    int collided = 0, capped = 0, stuck = 0;
    for (int trial = 0; trial < 20000; ++trial) {
        Pair c = randomPair(rng);
        const RoughLaws laws{u(rng), trial % 3 == 0 ? 1e9 : 2.0 * u(rng), 2.0 * u(rng) - 1.0};
        const Pair before = c;
        if (!collide(c, laws)) continue;
        ++collided;
        const double px = 10.0 * u(rng) - 5.0, py = 10.0 * u(rng) - 5.0;
        const double scaleP = before.i.m * std::hypot(before.i.vx, before.i.vy) +
                              before.j.m * std::hypot(before.j.vx, before.j.vy);
        EXPECT_NEAR(c.i.m * c.i.vx + c.j.m * c.j.vx,
                    before.i.m * before.i.vx + before.j.m * before.j.vx, 1e-13 * scaleP);
        EXPECT_NEAR(c.i.m * c.i.vy + c.j.m * c.j.vy,
                    before.i.m * before.i.vy + before.j.m * before.j.vy, 1e-13 * scaleP);
        const double l0 = before.i.angularMomentum(px, py) + before.j.angularMomentum(px, py);
        const double l1 = c.i.angularMomentum(px, py) + c.j.angularMomentum(px, py);
        const double scaleL = 10.0 * scaleP + std::abs(before.i.inertia() * before.i.omega) +
                              std::abs(before.j.inertia() * before.j.omega);
        // (A fixed-rotation disc is held against turning: what holds it takes up a torque.)
        if (!c.i.fixed && !c.j.fixed) {
            EXPECT_NEAR(l1, l0, 1e-13 * scaleL) << "trial " << trial;
        }
        // A fixed-rotation disc keeps its spin.
        if (c.i.fixed) {
            EXPECT_EQ(c.i.omega, before.i.omega);
        }
        if (c.j.fixed) {
            EXPECT_EQ(c.j.omega, before.j.omega);
        }
        // Sticking or capped: the contact points' tangential relative velocity becomes −β
        // times what it was, or moves toward that by at most μ jn.
        auto slip = [&](const Pair& p) {
            return (p.j.vx - p.i.vx) * -p.n.y + (p.j.vy - p.i.vy) * p.n.x - p.j.omega * p.j.r -
                   p.i.omega * p.i.r;
        };
        Pair normalOnly = before;
        collideRoughDiscs(normalOnly.i.vx, normalOnly.i.vy, {normalOnly.i.omega, 1.0, 0.0},
                          normalOnly.j.vx, normalOnly.j.vy, {normalOnly.j.omega, 1.0, 0.0},
                          before.i.w(), before.j.w(), before.i.m, before.j.m, before.n,
                          {laws.e, 0.0, 0.0});
        const double vt = slip(normalOnly), after = slip(c);
        if (std::abs(after + laws.beta * vt) <= 1e-12 * (1.0 + std::abs(vt))) {
            ++stuck;
        } else {
            ++capped;
            EXPECT_LT(std::abs(after + laws.beta * vt), std::abs(vt + laws.beta * vt) + 1e-12);
        }
    }
    EXPECT_GT(collided, 5000);
    EXPECT_GT(stuck, 1000);
    EXPECT_GT(capped, 1000);
}

TEST(RoughContact, PairEnergyNeverGrowsForTangentialRestitutionUpToOne) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int trial = 0; trial < 20000; ++trial) {
        Pair c = randomPair(rng);
        const RoughLaws laws{u(rng), 3.0 * u(rng), 2.0 * u(rng) - 1.0};
        const double e0 = c.i.energy() + c.j.energy();
        if (!collide(c, laws)) continue;
        EXPECT_LE(c.i.energy() + c.j.energy(), e0 * (1.0 + 1e-13)) << "trial " << trial;
    }
}

TEST(RoughContact, PerfectlyRoughElasticPairKeepsItsEnergy) {
    // e = 1, β = 1 and friction that never caps: normal and tangential relative velocities of
    // the contact points are both reversed, and kinetic energy (translation and rotation) is
    // kept.
    std::mt19937_64 rng(11);
    for (int trial = 0; trial < 5000; ++trial) {
        Pair c = randomPair(rng);
        const double e0 = c.i.energy() + c.j.energy();
        if (!collide(c, {1.0, 1e12, 1.0})) continue;
        EXPECT_NEAR(c.i.energy() + c.j.energy(), e0, 1e-13 * e0) << "trial " << trial;
    }
}

TEST(RoughContact, SmoothDiscsWithoutFrictionOrWithBetaMinusOne) {
    // μ = 0: no tangential impulse, whatever β; β = −1: a sticking contact keeps its slip, so
    // it gives none either. Both are collideDiscs<false>, and no spin changes.
    std::mt19937_64 rng(3);
    for (int trial = 0; trial < 2000; ++trial) {
        Pair c = randomPair(rng);
        Pair smooth = c;
        const bool hit = collideDiscs<false>(smooth.i.vx, smooth.i.vy, smooth.j.vx, smooth.j.vy,
                                             c.i.w(), c.j.w(), c.i.m, c.j.m, c.n, 0.7, 0.0);
        for (const RoughLaws laws : {RoughLaws{0.7, 0.0, 0.4}, RoughLaws{0.7, 5.0, -1.0}}) {
            Pair rough = c;
            EXPECT_EQ(collide(rough, laws), hit);
            EXPECT_NEAR(rough.i.vx, smooth.i.vx, 1e-14 * (1.0 + std::abs(smooth.i.vx)));
            EXPECT_NEAR(rough.i.vy, smooth.i.vy, 1e-14 * (1.0 + std::abs(smooth.i.vy)));
            EXPECT_NEAR(rough.j.vx, smooth.j.vx, 1e-14 * (1.0 + std::abs(smooth.j.vx)));
            EXPECT_NEAR(rough.j.vy, smooth.j.vy, 1e-14 * (1.0 + std::abs(smooth.j.vy)));
            EXPECT_NEAR(rough.i.omega, c.i.omega, 1e-14 * (1.0 + std::abs(c.i.omega)));
            EXPECT_NEAR(rough.j.omega, c.j.omega, 1e-14 * (1.0 + std::abs(c.j.omega)));
        }
    }
}

TEST(RoughContact, ASpinningDiscDroppedOnTheFloorIsThrownTheWayItsBottomDoesNotGo) {
    // Positive ω turns +x toward +y: on a screen (y down) clockwise, so the bottom of the disc
    // moves toward −x and the floor's friction pushes the disc toward +x, slowing its spin.
    // Floor: outward normal (0, −1). Sticking (β = 0, μ large): the contact point stops,
    // vx − ω r = 0, and angular momentum about the contact point is kept:
    // m vx r + I ω = I ω0, so vx = k ω0 r / (1 + k).
    double vx = 0.0, vy = 2.0, omega = 10.0;
    const double r = 0.2, k = 0.5;
    const double dv =
        roughReboundOffSurface(vx, vy, {omega, r, 1.0 / k}, 0.0, -1.0, {0.0, 100.0, 0.0});
    EXPECT_DOUBLE_EQ(dv, 2.0);
    EXPECT_DOUBLE_EQ(vy, 0.0);
    EXPECT_NEAR(vx, k * 10.0 * r / (1.0 + k), 1e-15);
    EXPECT_NEAR(vx - omega * r, 0.0, 1e-15);
    // Capped (μ = 0.1): the impulse per unit mass is μ·dv = 0.2 m/s.
    vx = 0.0;
    vy = 2.0;
    omega = 10.0;
    roughReboundOffSurface(vx, vy, {omega, r, 1.0 / k}, 0.0, -1.0, {0.0, 0.1, 0.0});
    EXPECT_NEAR(vx, 0.2, 1e-15);
    EXPECT_NEAR(omega, 10.0 - 0.2 / (k * r), 1e-13);
}

TEST(RoughContact, SurfaceEnergyNeverGrowsAndStickingReversesTheSlipByBeta) {
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int trial = 0; trial < 20000; ++trial) {
        const double angle = 2.0 * M_PI * u(rng);
        const double nx = std::cos(angle), ny = std::sin(angle);
        double vx = 4.0 * u(rng) - 2.0, vy = 4.0 * u(rng) - 2.0, omega = 20.0 * u(rng) - 10.0;
        const double r = 0.05 + u(rng), k = 0.05 + 0.95 * u(rng), e = u(rng);
        const double beta = 2.0 * u(rng) - 1.0, mu = trial % 2 ? 1e9 : u(rng);
        const auto energy = [&] {
            return 0.5 * (vx * vx + vy * vy) + 0.5 * k * r * r * omega * omega;
        };
        const double e0 = energy();
        const double slip0 = vx * -ny + vy * nx - omega * r;
        const double dv =
            roughReboundOffSurface(vx, vy, {omega, r, 1.0 / k}, nx, ny, {e, mu, beta});
        if (dv == 0.0) continue;
        EXPECT_LE(energy(), e0 * (1.0 + 1e-13));
        if (mu == 1e9) {
            EXPECT_NEAR(vx * -ny + vy * nx - omega * r, -beta * slip0, 1e-12);
        }
    }
}

}  // namespace
}  // namespace psb
