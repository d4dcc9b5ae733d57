// Every broadphase must find exactly the pairs all-pairs finds, in the same order: the resolve
// stage is order-dependent, so this is what makes results independent of the broadphase.

#include <gtest/gtest.h>

#include <particle_sandbox/solver_settings.hpp>
#include <particle_sandbox/world.hpp>

#include "broad_phase_scenes.hpp"
#include "broadphase/broad_phase_all_pairs.hpp"
#include "discrete/discrete_step.hpp"

namespace psb {
namespace {

std::vector<ContactPair> pairsWith(BroadPhaseKind kind, const ParticleArrays& p, int threads,
                                   StepContext& ctx) {
    ctx.broadPhase = kind;
    ctx.threads = threads;
    stages::findPairs(p, ctx);
    EXPECT_EQ(ctx.broadPhaseUsed, kind);
    return ctx.pairs;
}

void expectSamePairs(const std::vector<ContactPair>& want, const std::vector<ContactPair>& got,
                     const std::string& what) {
    ASSERT_EQ(got.size(), want.size()) << what;
    for (std::size_t k = 0; k < want.size(); ++k) {
        ASSERT_EQ(got[k], want[k]) << what << " at pair " << k << " (" << got[k].i << ", "
                                   << got[k].j << ") vs (" << want[k].i << ", " << want[k].j << ")";
    }
}

class Agreement : public ::testing::TestWithParam<test::Layout> {};

TEST_P(Agreement, GridAndQuadtreeFindExactlyTheAllPairsList) {
    StepContext ctx;  // reused across scenes, as a world reuses it across steps
    std::size_t seen = 0;
    for (std::uint32_t seed = 1; seed <= 12; ++seed) {
        const std::size_t n = 200 + 150 * seed;
        const ParticleArrays p = test::makeLayout(GetParam(), n, seed);
        std::vector<ContactPair> want;
        findPairsAllPairs(p, want);
        seen += want.size();
        const std::string where =
            std::string(test::name(GetParam())) + " seed " + std::to_string(seed);
        for (const BroadPhaseKind k : {BroadPhaseKind::Grid, BroadPhaseKind::Quadtree}) {
            expectSamePairs(want, pairsWith(k, p, 1, ctx), where + " " + std::string(toString(k)));
        }
    }
    EXPECT_GT(seen, 100u) << "the scenes must actually contain overlaps";
}

TEST_P(Agreement, TwoThreadsFindTheSameListAsOne) {
    // Large enough that the queries are split into two chunks.
    StepContext ctx;
    const ParticleArrays p = test::makeLayout(GetParam(), 20000, 99);
    std::vector<ContactPair> want;
    findPairsAllPairs(p, want);
    for (const BroadPhaseKind k : {BroadPhaseKind::Grid, BroadPhaseKind::Quadtree}) {
        for (const int threads : {1, 2, 3}) {
            expectSamePairs(want, pairsWith(k, p, threads, ctx),
                            std::string(toString(k)) + " threads " + std::to_string(threads));
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Layouts, Agreement, ::testing::ValuesIn(test::kAllLayouts),
                         [](const auto& param) {
                             std::string s = test::name(param.param);
                             for (char& c : s)
                                 if (c == '-') c = '_';
                             return s;
                         });

TEST(Agreement, PairsExactlyAtTheTouchingDistanceAreNotContacts) {
    ParticleArrays p;
    test::push(p, 0.0, 0.0, 1.0);
    test::push(p, 2.0, 0.0, 1.0);  // touches 0
    test::push(p, 1.0, 1.5, 1.0);  // overlaps 0 and 1
    for (int k = 0; k < 100; ++k)
        test::push(p, 50.0 + 3.0 * k, 50.0, 1.0);  // isolated
    StepContext ctx;
    for (const BroadPhaseKind k :
         {BroadPhaseKind::AllPairs, BroadPhaseKind::Grid, BroadPhaseKind::Quadtree}) {
        const auto pairs = pairsWith(k, p, 1, ctx);
        ASSERT_EQ(pairs.size(), 2u) << toString(k);
        EXPECT_EQ(pairs[0], (ContactPair{0, 2})) << toString(k);
        EXPECT_EQ(pairs[1], (ContactPair{1, 2})) << toString(k);
    }
}

}  // namespace
}  // namespace psb

namespace psb {
namespace {

TEST(Agreement, TinyAndDegenerateWorldsStepWithEveryBroadphase) {
    for (const BroadPhaseKind k :
         {BroadPhaseKind::AllPairs, BroadPhaseKind::Grid, BroadPhaseKind::Quadtree}) {
        for (std::size_t n = 0; n <= 3; ++n) {
            World w({}, {.broadphase = k});
            for (std::size_t i = 0; i < n; ++i) {
                // All on one point: zero-size bounds, one cell, coincident centres.
                w.add({.position = {5.0, 5.0}, .velocity = {1.0, 0.0}, .radius = 1.0});
            }
            w.step(0.01);
            w.step(0.01);
            EXPECT_EQ(w.counters().maxOverlap > 0.0, n >= 2) << toString(k) << " n = " << n;
        }
    }
}

}  // namespace
}  // namespace psb
