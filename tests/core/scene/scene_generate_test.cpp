// Generate blocks: deterministic, inside the region, no overlaps, the asked-for statistics.

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <tuple>

#include <particle_sandbox/scene.hpp>

#include "broadphase/overlap_check.hpp"
#include "scene/scene_generate.hpp"

namespace psb {
namespace {

detail::GenerateSpec spec(std::uint64_t count, double radius) {
    detail::GenerateSpec s;
    s.count = count;
    s.radius = radius;
    s.x0 = 0.0;
    s.y0 = 0.0;
    s.x1 = 700.0;
    s.y1 = 700.0;
    return s;
}

TEST(SceneGenerate, TheSameSeedGivesTheSameParticlesAndAnotherSeedDifferentOnes) {
    auto s = spec(500, 3.0);
    s.temperature = 10.0;
    const auto a = detail::generateParticles(s);
    const auto b = detail::generateParticles(s);
    ASSERT_EQ(a.size(), 500u);
    for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a[i].position, b[i].position);
        EXPECT_EQ(a[i].velocity, b[i].velocity);
        EXPECT_EQ(a[i].color, b[i].color);
    }
    s.seed = 2;
    const auto c = detail::generateParticles(s);
    EXPECT_NE(a[0].position, c[0].position);
}

TEST(SceneGenerate, ParticlesAreInsideTheRegionAndNeverOverlapEvenAtTheDensestPacking) {
    for (const auto& [x0, y0, x1, y1, r] :
         {std::tuple{0.0, 0.0, 700.0, 700.0, 5.0}, std::tuple{10.0, 20.0, 30.5, 400.0, 1.0},
          std::tuple{0.0, 0.0, 1.0, 1.0, 0.01}}) {
        auto s = spec(0, r);
        s.x0 = x0;
        s.y0 = y0;
        s.x1 = x1;
        s.y1 = y1;
        s.count = detail::latticeCapacity(s);  // every site taken: square packing, ~π/4
        ASSERT_GT(s.count, 0u);
        const auto ps = detail::generateParticles(s);
        ASSERT_EQ(ps.size(), s.count);
        for (const auto& p : ps) {
            ASSERT_GE(p.position.x(), x0 + r);
            ASSERT_LE(p.position.x(), x1 - r);
            ASSERT_GE(p.position.y(), y0 + r);
            ASSERT_LE(p.position.y(), y1 - r);
        }
        EXPECT_FALSE(detail::findOverlap(ps).has_value());
    }
}

TEST(SceneGenerate, PackingFractionSetsTheCount) {
    // φ · area / (π r²) = 0.2 · 490000 / (π · 4) = 7798.4 → 7798 particles.
    const Scene s = parseScene(R"({"version": 1, "generate": {"packing": 0.2, "radius": 2}})", "g");
    EXPECT_EQ(s.particles.size(), 7798u);
}

TEST(SceneGenerate, TemperatureGivesMeanKineticEnergyKTPerParticle) {
    // 2-D equipartition: <½ m |v|²> = kT. With 20000 samples the relative standard error of
    // the mean of an exponential variable is 1/sqrt(20000) ≈ 0.7 %; allow 3 %.
    auto s = spec(20000, 1.0);
    s.mass = 2.0;
    s.temperature = 50.0;
    const auto ps = detail::generateParticles(s);
    double ke = 0.0, px = 0.0;
    for (const auto& p : ps) {
        ke += 0.5 * p.mass * p.velocity.squaredNorm();
        px += p.mass * p.velocity.x();
    }
    EXPECT_NEAR(ke / ps.size(), 50.0, 1.5);
    // Momentum per particle is ~ sqrt(m kT) / sqrt(N) = 10 / 141 = 0.07 kg·m/s; allow 5 σ.
    EXPECT_LT(std::abs(px / ps.size()), 0.35);
}

TEST(SceneGenerate, SpeedGivesEveryParticleThatSpeed) {
    auto s = spec(1000, 1.0);
    s.speed = 7.5;
    for (const auto& p : detail::generateParticles(s)) {
        EXPECT_NEAR(p.velocity.norm(), 7.5, 1e-12);
    }
}

TEST(SceneGenerate, ColoursAreFixedWhenGivenAndLikeTheOriginalsOtherwise) {
    auto s = spec(200, 1.0);
    std::set<int> reds;
    for (const auto& p : detail::generateParticles(s)) {
        EXPECT_GE(p.color.r, 100);
        EXPECT_GE(p.color.g, 100);
        EXPECT_GE(p.color.b, 100);
        reds.insert(p.color.r);
    }
    EXPECT_GT(reds.size(), 50u);
    s.color = Color{1, 2, 3};
    for (const auto& p : detail::generateParticles(s))
        EXPECT_EQ(p.color, (Color{1, 2, 3}));
}

TEST(SceneGenerate, AFewParticlesInAHugeSparseLatticeAreCheap) {
    // 1e-3 m discs in a 1e6 m box: ~2.5e17 sites, far too many to list.
    auto s = spec(1000, 1e-3);
    s.x1 = 1e6;
    s.y1 = 1e6;
    const auto ps = detail::generateParticles(s);
    EXPECT_EQ(ps.size(), 1000u);
    EXPECT_FALSE(detail::findOverlap(ps).has_value());
}

TEST(SceneGenerate, ALongThinRegionStillGetsItsParticles) {
    auto s = spec(10, 1.0);
    s.x1 = 1000.0;
    s.y1 = 2.5;
    EXPECT_EQ(detail::generateParticles(s).size(), 10u);
}

TEST(OverlapCheck, FindsTheLowestOverlappingPairAndIgnoresTouchingOnes) {
    std::vector<ParticleDef> ps;
    for (int k = 0; k < 10; ++k)
        ps.push_back({.position = {2.0 * k, 0.0}, .radius = 1.0});
    EXPECT_FALSE(detail::findOverlap(ps).has_value());  // each touches its neighbours
    ps.push_back({.position = {7.5, 0.5}, .radius = 0.1});
    ps.push_back({.position = {3.1, 0.0}, .radius = 0.2});
    const auto pair = detail::findOverlap(ps);
    ASSERT_TRUE(pair.has_value());
    EXPECT_EQ(pair->first, 1u);  // (1, 11): 2.0 and 3.1 are 1.1 apart < 1.2
    EXPECT_EQ(pair->second, 11u);
}

TEST(OverlapCheck, HandlesOneHugeDiscAmongSmallOnesAndFarApartPoints) {
    std::vector<ParticleDef> ps;
    ps.push_back({.position = {0.0, 0.0}, .radius = 1e-3});
    ps.push_back({.position = {1e15, -1e15}, .radius = 1e-3});
    ps.push_back({.position = {-1e15, 1e15}, .radius = 1e-3});
    EXPECT_FALSE(detail::findOverlap(ps).has_value());
    ps.push_back({.position = {0.5e15, 0.0}, .radius = 0.6e15});
    const auto pair = detail::findOverlap(ps);
    ASSERT_TRUE(pair.has_value());
    EXPECT_EQ(pair->first, 0u);
    EXPECT_EQ(pair->second, 3u);
}

}  // namespace
}  // namespace psb
