// In a periodic box every broadphase finds exactly the pairs a brute-force nearest-image test
// finds, across the edges and the corners too, in the same ascending order.

#include <algorithm>

#include <gtest/gtest.h>

#include <particle_sandbox/solver_settings.hpp>

#include "broadphase/broad_phase_all_pairs.hpp"
#include "discrete/discrete_step.hpp"

namespace psb {
namespace {

struct Lcg {
    std::uint64_t s;
    double next() {
        s = s * 6364136223846793005ull + 1442695040888963407ull;
        return static_cast<double>(s >> 11) * 0x1.0p-53;
    }
};

/// n discs in a box, their centres up to `spill` outside it (as between the move and wrap
/// stages), radii from r to 2r.
ParticleArrays scatter(std::size_t n, double w, double h, double r, double spill,
                       std::uint64_t seed) {
    ParticleArrays p;
    Lcg rng{seed};
    for (std::size_t i = 0; i < n; ++i) {
        p.x.push_back(-spill + (w + 2.0 * spill) * rng.next());
        p.y.push_back(-spill + (h + 2.0 * spill) * rng.next());
        p.radius.push_back(r * (1.0 + rng.next()));
    }
    return p;
}

std::vector<ContactPair> bruteForce(const ParticleArrays& p, const periodic::Box& box) {
    std::vector<ContactPair> out;
    for (std::uint32_t i = 0; i < p.size(); ++i) {
        for (std::uint32_t j = i + 1; j < p.size(); ++j) {
            double dx = p.x[j] - p.x[i], dy = p.y[j] - p.y[i];
            // Every image within one box, not only the formula's nearest one.
            double best = INFINITY;
            for (int sx = -2; sx <= 2; ++sx) {
                for (int sy = -2; sy <= 2; ++sy)
                    best = std::min(best, std::hypot(dx + sx * box.width, dy + sy * box.height));
            }
            if (best < p.radius[i] + p.radius[j]) out.push_back({i, j});
        }
    }
    return out;
}

std::vector<ContactPair> found(BroadPhaseKind kind, const ParticleArrays& p,
                               const periodic::Box& box, int threads) {
    StepContext ctx;
    ctx.periodic = true;
    ctx.box = box;
    ctx.broadPhase = kind;
    ctx.threads = threads;
    stages::findPairs(p, ctx);
    return ctx.pairs;
}

TEST(PeriodicPairs, EveryBroadphaseFindsTheNearestImagePairs) {
    // Centres inside the box, as the move stage leaves them (the grid reads them in place), and
    // up to 0.3 m outside it (the grid measures a wrapped copy).
    std::size_t across = 0, total = 0;
    for (std::uint64_t seed = 1; seed <= 8; ++seed) {
        const periodic::Box box{40.0 + seed, 30.0};
        const double spill = seed % 2 == 0 ? 0.0 : 0.3;
        const ParticleArrays p = scatter(300 + 40 * seed, box.width, box.height, 0.7, spill, seed);
        const std::vector<ContactPair> want = bruteForce(p, box);
        total += want.size();
        for (const ContactPair& c : want)
            across += std::abs(p.x[c.j] - p.x[c.i]) > box.width / 2 ||
                      std::abs(p.y[c.j] - p.y[c.i]) > box.height / 2;
        for (const BroadPhaseKind k :
             {BroadPhaseKind::AllPairs, BroadPhaseKind::Grid, BroadPhaseKind::Quadtree}) {
            EXPECT_EQ(found(k, p, box, 1), want) << toString(k) << " seed " << seed;
        }
        EXPECT_EQ(found(BroadPhaseKind::Grid, p, box, 2), want) << "two threads, seed " << seed;
    }
    EXPECT_GT(total, 200u);
    EXPECT_GT(across, 10u) << "the scenes must have pairs across the edges";
}

TEST(PeriodicPairs, ABoxOneOrTwoCellsAcrossFindsEachPairOnce) {
    // Discs of radius 1 in boxes 4 to 7 m across: the grid's neighbours repeat.
    for (const double side : {4.0, 5.0, 7.0}) {
        const periodic::Box box{side, side + 1.0};
        const ParticleArrays p = scatter(12, box.width, box.height, 0.5, 0.0, 5);
        const std::vector<ContactPair> want = bruteForce(p, box);
        for (const BroadPhaseKind k :
             {BroadPhaseKind::AllPairs, BroadPhaseKind::Grid, BroadPhaseKind::Quadtree}) {
            EXPECT_EQ(found(k, p, box, 1), want) << toString(k) << " side " << side;
        }
    }
}

TEST(PeriodicPairs, APairAcrossACornerIsFound) {
    ParticleArrays p;
    p.x = {0.2, 9.9};
    p.y = {0.1, 9.8};
    p.radius = {0.3, 0.3};
    const periodic::Box box{10.0, 10.0};
    for (const BroadPhaseKind k :
         {BroadPhaseKind::AllPairs, BroadPhaseKind::Grid, BroadPhaseKind::Quadtree}) {
        const std::vector<ContactPair> pairs = found(k, p, box, 1);
        ASSERT_EQ(pairs.size(), 1u) << toString(k);
        EXPECT_EQ(pairs[0], (ContactPair{0, 1}));
    }
}

TEST(PeriodicPairs, LargeDiscsAndTheirImagesAcrossTheEdges) {
    // The grid queries the box grid over the particles and strips along the edges; discs more
    // than twice the mean radius stay out of the box grid's cells and are tested apart, and
    // widen the strips. A few of 3 m among 400 of 0.4 to 0.8 m, some of them over an edge or a
    // corner.
    for (std::uint64_t seed = 11; seed <= 14; ++seed) {
        const periodic::Box box{36.0, 28.0 + static_cast<double>(seed)};
        ParticleArrays p = scatter(400, box.width, box.height, 0.4, seed % 2 ? 0.2 : 0.0, seed);
        for (const double at : {0.5, 1.0, 2.0, 35.5}) {
            p.x.push_back(at);
            p.y.push_back(box.height - at * 0.5);
            p.radius.push_back(3.0);
        }
        const std::vector<ContactPair> want = bruteForce(p, box);
        EXPECT_EQ(found(BroadPhaseKind::Grid, p, box, 1), want) << "seed " << seed;
        EXPECT_EQ(found(BroadPhaseKind::Grid, p, box, 2), want) << "two threads, seed " << seed;
    }
}

TEST(PeriodicPairs, AfterTheMoveStageWrapsTheCentresTheGridFindsEveryPair) {
    // As in the discrete step: move wraps each centre and writes its cell under the grid's last
    // plan, and the grid reads the particles in place. The discs fly through one another (no
    // resolve), so pairs form and break across every edge and corner, step after step.
    const periodic::Box box{30.0, 24.0};
    for (const int threads : {1, 2}) {
        ParticleArrays p = scatter(700, box.width, box.height, 0.4, 0.0, 21);
        Lcg rng{99};
        for (std::size_t i = 0; i < p.size(); ++i) {
            p.vx.push_back(40.0 * rng.next() - 20.0);
            p.vy.push_back(40.0 * rng.next() - 20.0);
        }
        p.periodic = true;
        p.unwrapX.assign(p.size(), 0.0);
        p.unwrapY.assign(p.size(), 0.0);
        StepContext ctx;
        ctx.periodic = true;
        ctx.box = box;
        ctx.broadPhase = BroadPhaseKind::Grid;
        ctx.threads = threads;
        std::size_t across = 0, reused = 0;
        const stages::MoveWrap wrap{box.width, box.height};
        for (int step = 0; step < 60; ++step) {
            const auto cells = ctx.periodicGrid.cellsForMove(p.size());
            stages::move(p, 0.01, threads, &ctx.statsScratch, cells ? &*cells : nullptr, &wrap);
            ctx.statsFresh = true;
            ctx.cellsFresh = cells.has_value();
            reused += cells.has_value();
            for (std::size_t i = 0; i < p.size(); ++i) {
                ASSERT_GE(p.x[i], 0.0);
                ASSERT_LT(p.x[i], box.width);
                ASSERT_GE(p.y[i], 0.0);
                ASSERT_LT(p.y[i], box.height);
            }
            stages::findPairs(p, ctx);
            const std::vector<ContactPair> want = bruteForce(p, box);
            ASSERT_EQ(ctx.pairs, want) << "step " << step << ", " << threads << " threads";
            for (const ContactPair& c : want)
                across += std::abs(p.x[c.j] - p.x[c.i]) > box.width / 2 ||
                          std::abs(p.y[c.j] - p.y[c.i]) > box.height / 2;
        }
        EXPECT_GT(across, 30u) << "pairs across the edges";
        EXPECT_GT(reused, 50u) << "the move stage wrote the cells";
        // The unwrapped position is the integrated motion.
        EXPECT_GT(*std::max_element(p.unwrapX.begin(), p.unwrapX.end()), 0.0);
    }
}

}  // namespace
}  // namespace psb
