// The exact mode in a periodic box loses no event: an elastic gas keeps its energy and its
// momentum to rounding (a walled box cannot show the momentum), and no pair ever overlaps, in
// the bulk or across an edge, over a long run at packing fraction 0.5; a disc among fixed pegs
// (the Lorentz gas) never enters one.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include <particle_sandbox/world.hpp>

#include "support/periodic_box.hpp"

namespace psb {
namespace {

struct Lcg {
    std::uint64_t s;
    double next() {
        s = s * 6364136223846793005ull + 1442695040888963407ull;
        return static_cast<double>(s >> 11) * 0x1.0p-53;
    }
};

/// n discs of radius r on a square lattice filling a periodic box at packing fraction phi, with
/// random velocities of zero total momentum.
World latticeGas(int side, double r, double phi, std::uint64_t seed) {
    const double n = static_cast<double>(side) * side;
    const double box = std::sqrt(n * std::numbers::pi * r * r / phi);
    WorldDef def;
    def.width = def.height = box;
    def.periodic = true;
    SolverSettings solver;
    solver.mode = StepMode::Exact;
    World w(def, solver);
    w.setThreads(1);
    Lcg rng{seed};
    const double a = box / side;
    std::vector<Vec2> v;
    Vec2 mean = Vec2::Zero();
    for (int k = 0; k < side * side; ++k) {
        v.emplace_back(10.0 * (rng.next() - 0.5), 10.0 * (rng.next() - 0.5));
        mean += v.back() / n;
    }
    for (int i = 0; i < side; ++i) {
        for (int j = 0; j < side; ++j) {
            ParticleDef d;
            // Offset by a quarter cell, so that a row of discs straddles the edges.
            d.position = {(i + 0.25) * a, (j + 0.9) * a};
            d.velocity = v[static_cast<std::size_t>(i * side + j)] - mean;
            d.radius = r;
            w.add(d);
        }
    }
    return w;
}

double kinetic(const World& w) {
    const ParticleArrays& p = w.particles();
    double e = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i)
        e += 0.5 * p.mass[i] * (p.vx[i] * p.vx[i] + p.vy[i] * p.vy[i]);
    return e;
}

Vec2 momentum(const World& w) {
    const ParticleArrays& p = w.particles();
    Vec2 m = Vec2::Zero();
    for (std::size_t i = 0; i < p.size(); ++i)
        m += p.mass[i] * Vec2(p.vx[i], p.vy[i]);
    return m;
}

/// The deepest overlap of any pair, measured between nearest images (all pairs).
double deepestOverlap(const World& w) {
    const ParticleArrays& p = w.particles();
    const periodic::Box box{w.def().width, w.def().height};
    double deepest = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        for (std::size_t j = i + 1; j < p.size(); ++j) {
            const double dx = box.imageX(p.x[j] - p.x[i]), dy = box.imageY(p.y[j] - p.y[i]);
            deepest = std::max(deepest, p.radius[i] + p.radius[j] - std::hypot(dx, dy));
        }
    }
    return deepest;
}

TEST(ExactPeriodicGas, AnElasticGasKeepsItsEnergyAndMomentumAndNeverOverlaps) {
    World w = latticeGas(20, 0.5, 0.5, 7);  // 400 discs, phi 0.5
    const double e0 = kinetic(w);
    const Vec2 m0 = momentum(w);
    double deepest = 0.0;
    for (int k = 0; k < 200; ++k) {
        w.step(0.05);
        deepest = std::max(deepest, deepestOverlap(w));
    }
    // About a hundred collisions per particle.
    EXPECT_GT(w.counters().collisions, 30000u);
    EXPECT_EQ(w.counters().wallCollisions, 0u);
    EXPECT_NEAR(kinetic(w) / e0, 1.0, 1e-12);
    EXPECT_NEAR(momentum(w).x(), m0.x(), 1e-12);
    EXPECT_NEAR(momentum(w).y(), m0.y(), 1e-12);
    EXPECT_LT(deepest, 1e-9);
    // And every centre is in the box.
    const ParticleArrays& p = w.particles();
    for (std::size_t i = 0; i < p.size(); ++i) {
        ASSERT_GE(p.x[i], 0.0);
        ASSERT_LT(p.x[i], w.def().width);
        ASSERT_GE(p.y[i], 0.0);
        ASSERT_LT(p.y[i], w.def().height);
    }
}

TEST(ExactPeriodicGas, TheUnwrappedDisplacementsAddUpToTheMomentum) {
    // Equal masses and zero total momentum: the centre of mass does not move, so the unwrapped
    // displacements sum to zero, though particles cross the edges many times.
    World w = latticeGas(12, 0.5, 0.3, 11);
    std::vector<Vec2> start;
    for (const ParticleId id : w.ids())
        start.push_back(w.unwrappedPosition(id));
    for (int k = 0; k < 100; ++k)
        w.step(0.1);
    Vec2 sum = Vec2::Zero();
    double travelled = 0.0;
    std::size_t k = 0;
    for (const ParticleId id : w.ids()) {
        const Vec2 d = w.unwrappedPosition(id) - start[k++];
        sum += d;
        travelled = std::max(travelled, d.norm());
    }
    EXPECT_GT(travelled, 0.5 * w.def().width);
    const ParticleArrays& p = w.particles();
    EXPECT_GT(std::count_if(p.unwrapX.begin(), p.unwrapX.end(), [](double u) { return u != 0.0; }),
              10)
        << "particles must have crossed the edges";
    EXPECT_LT(sum.norm(), 1e-9);
}

TEST(ExactPeriodicGas, ABoxThreeCellsAcrossOrLessLosesNothing) {
    // So few cells that a cell's neighbours across both edges are the same cells: each is
    // searched as every image it is.
    World w = latticeGas(3, 0.5, 0.45, 3);
    const double e0 = kinetic(w);
    double deepest = 0.0;
    for (int k = 0; k < 400; ++k) {
        w.step(0.05);
        deepest = std::max(deepest, deepestOverlap(w));
    }
    EXPECT_GT(w.counters().collisions, 500u);
    EXPECT_NEAR(kinetic(w) / e0, 1.0, 1e-12);
    EXPECT_LT(deepest, 1e-9);
}

TEST(ExactPeriodicGas, ALorentzGasDiscNeverEntersAPeg) {
    // One disc among a square lattice of fixed pegs, each peg a lattice cell from its images.
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
    solver.mode = StepMode::Exact;
    World w(def, solver);
    ParticleDef d;
    d.position = {2.0, 0.05};
    d.velocity = {1.3, 0.7};
    d.radius = 0.05;
    const ParticleId id = w.add(d);
    double closest = INFINITY;
    for (int k = 0; k < 2000; ++k) {
        w.step(0.05);
        const Particle p = w.get(id);
        for (const Obstacle& o : pegs)
            closest = std::min(closest, (p.position - o.a).norm() - o.radius - d.radius);
    }
    EXPECT_GT(w.counters().obstacleCollisions, 50u);
    EXPECT_GT(closest, -1e-9);
    EXPECT_NEAR(w.get(id).velocity.norm(), d.velocity.norm(), 1e-12);
    // It wandered across the edges.
    EXPECT_GT((w.unwrappedPosition(id) - d.position).norm(), 8.0);
}

}  // namespace
}  // namespace psb
