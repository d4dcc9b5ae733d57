#include <gtest/gtest.h>

#include <random>

#include <particle_sandbox/diagnostics.hpp>
#include <particle_sandbox/world.hpp>

namespace psb {
namespace {

TEST(Diagnostics, KineticEnergyAndMomentumOfKnownParticles) {
    World w;
    const ParticleId a = w.add({.position = {10.0, 10.0}, .velocity = {3.0, 4.0}, .mass = 2.0});
    w.add({.position = {50.0, 10.0}, .velocity = {-1.0, 0.0}, .mass = 6.0});
    EXPECT_DOUBLE_EQ(kineticEnergy(w), 0.5 * 2.0 * 25.0 + 0.5 * 6.0 * 1.0);
    EXPECT_EQ(momentum(w), Vec2(0.0, 8.0));
    EXPECT_EQ(momentum(w, a), Vec2(6.0, 8.0));
    EXPECT_EQ(centreOfMass(w), Vec2(40.0, 10.0));
}

TEST(Diagnostics, EmptyWorldHasZeroTotalsAndCentreOfMassAtTheBoxCentre) {
    World w;
    EXPECT_EQ(kineticEnergy(w), 0.0);
    EXPECT_EQ(momentum(w), Vec2(0.0, 0.0));
    EXPECT_EQ(centreOfMass(w), Vec2(350.0, 350.0));
}

TEST(Diagnostics, CompensatedSumKeepsSmallTermsNextToAHugeOne) {
    World w(WorldDef{.walls = false});
    w.add({.velocity = {1e8, 0.0}, .mass = 1.0});  // 5e15 J
    for (int k = 0; k < 1000; ++k)
        w.add({.position = {1.0 * k, 0.0}, .velocity = {1.0, 0.0}});
    // 1000 terms of 0.5 J would each vanish into 5e15 with naive summation (ulp = 1).
    EXPECT_EQ(kineticEnergy(w) - 5e15, 500.0);
}

TEST(Diagnostics, MaxOverlapBruteForce) {
    World w;
    w.add({.position = {10.0, 10.0}, .radius = 2.0});
    w.add({.position = {13.0, 10.0}, .radius = 2.0});
    w.add({.position = {100.0, 10.0}, .radius = 2.0});
    EXPECT_DOUBLE_EQ(maxOverlapBruteForce(w), 1.0);
}

TEST(Diagnostics, MaxOverlapSeesAPairPlacedOverlapping) {
    for (const StepMode mode : {StepMode::Discrete, StepMode::Exact}) {
        World w(WorldDef{}, {.mode = mode});
        EXPECT_EQ(maxOverlap(w), 0.0);
        w.add({.position = {10.0, 10.0}, .radius = 2.0});
        w.add({.position = {100.0, 10.0}, .radius = 2.0});
        EXPECT_EQ(maxOverlap(w), 0.0);  // apart
        w.add({.position = {13.0, 10.0}, .radius = 2.0});
        EXPECT_DOUBLE_EQ(maxOverlap(w), 1.0);
        const ParticleId big = w.add({.position = {100.0, 40.0}, .radius = 28.0});
        EXPECT_DOUBLE_EQ(maxOverlap(w), 1.0);  // the big one touches (30 m = 28 + 2) only
        w.setRadius(big, 31.5);
        EXPECT_DOUBLE_EQ(maxOverlap(w), 3.5);  // an edited radius
    }
}

TEST(Diagnostics, MaxOverlapAgreesWithBruteForceOnMixedSizes) {
    // 3000 discs, radii from 0.5 to 20 m (the grid sets the large ones apart; with many of them
    // the quadtree is used): both answers must be the same number.
    for (const int large : {3, 400}) {
        World w(WorldDef{.width = 800.0, .height = 800.0});
        std::mt19937 rng(7u + static_cast<unsigned>(large));
        std::uniform_real_distribution<double> pos(0.0, 800.0), small(0.5, 1.5), big(5.0, 20.0);
        for (int k = 0; k < 3000; ++k) {
            w.add({.position = {pos(rng), pos(rng)}, .radius = k < large ? big(rng) : small(rng)});
        }
        const double brute = maxOverlapBruteForce(w);
        EXPECT_GT(brute, 1.0);
        EXPECT_EQ(maxOverlap(w), brute) << large << " large discs";
    }
}

}  // namespace
}  // namespace psb
