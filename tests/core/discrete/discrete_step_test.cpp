// The discrete step's pipeline against the same stages run one by one in their plainest form:
// the shortcut the pipeline takes (particle bounds measured during move, for the broadphase)
// must not change a single bit of the result.

#include <gtest/gtest.h>

#include <cstring>
#include <random>

#include <particle_sandbox/world_def.hpp>

#include "discrete/discrete_step.hpp"

namespace psb {
namespace {

/// A crowded box whose particles hit the walls and each other every few steps.
ParticleArrays crowdedBox(const WorldDef& def, std::size_t n, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> ux(0.0, def.width), uy(0.0, def.height), uv(-40.0, 40.0),
        ur(0.3, 1.5), um(0.5, 5.0);
    ParticleArrays p;
    for (std::size_t i = 0; i < n; ++i) {
        const double m = um(rng);
        // Some start outside the box, as after a user drops one there.
        p.x.push_back(ux(rng) * 1.02 - 0.01 * def.width);
        p.y.push_back(uy(rng) * 1.02 - 0.01 * def.height);
        p.vx.push_back(uv(rng));
        p.vy.push_back(uv(rng));
        p.radius.push_back(ur(rng));
        p.mass.push_back(m);
        // A few kinematic (held) particles, which the wall stage treats apart.
        p.invMass.push_back(i % 97 == 0 ? 0.0 : 1.0 / m);
        p.color.push_back({});
        p.id.push_back({static_cast<std::uint32_t>(i), 0});
    }
    return p;
}

bool sameBits(const std::vector<double>& a, const std::vector<double>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

/// Two copies of one crowded box, with a grid step context each: `fast` goes through the
/// pipeline, `plain` through the stages one by one.
struct Twins {
    Twins(const WorldDef& def, std::uint64_t seed, int threads)
        : fast(crowdedBox(def, 20000, seed)), plain(fast) {
        // Enough particles for several parallel blocks, so that flags cross block boundaries.
        fastCtx.threads = plainCtx.threads = threads;
        fastCtx.broadPhase = plainCtx.broadPhase = BroadPhaseKind::Grid;
    }
    /// Positions and velocities of the two copies agree to the last bit.
    [[nodiscard]] bool same() const {
        return sameBits(fast.x, plain.x) && sameBits(fast.y, plain.y) &&
               sameBits(fast.vx, plain.vx) && sameBits(fast.vy, plain.vy);
    }
    ParticleArrays fast, plain;
    StepContext fastCtx, plainCtx;
    StepProfile profile;
    StepCounters fastCounters, plainCounters;
};

TEST(DiscreteStep, PipelineMatchesTheStagesRunOneByOneBitForBit) {
    WorldDef def;
    def.width = 120.0;
    def.height = 90.0;
    def.restitution = 0.9;
    def.gravity = Vec2(0.0, 9.81);
    for (const int threads : {1, 2}) {
        Twins t(def, 7, threads);
        auto& [fast, plain, fastCtx, plainCtx, profile, fastCounters, plainCounters] = t;
        std::uint64_t wallHits = 0;
        for (int s = 0; s < 40; ++s) {
            stages::discreteStep(fast, def, 0.01, fastCtx, profile, fastCounters);

            stages::applyGravity(plain, def.gravity, 0.01, threads);
            stages::move(plain, 0.01, threads);  // no bounds: the broadphase measures
            stages::findPairs(plain, plainCtx);
            stages::resolve(plain, def, plainCtx, plainCounters);
            stages::separate(plain, plainCtx);
            stages::walls(plain, def, plainCtx, plainCounters);

            ASSERT_TRUE(t.same()) << "step " << s << ", threads " << threads;
            ASSERT_EQ(fastCounters.wallCollisions, plainCounters.wallCollisions) << "step " << s;
            ASSERT_EQ(fastCounters.wallImpulse, plainCounters.wallImpulse) << "step " << s;
            ASSERT_EQ(fastCounters.collisions, plainCounters.collisions) << "step " << s;
            wallHits = fastCounters.wallCollisions;
        }
        // The scene did exercise the walls and the pairs.
        EXPECT_GT(wallHits, 100u);
        EXPECT_GT(fastCounters.collisions, 100u);
    }
}

// Walls off, so the cloud spreads and the grid has to give up its plan now and then; halfway the
// radii grow, which forces a new plan too. Between those, move writes the cells.
TEST(DiscreteStep, PipelineMatchesTheStagesWhileTheGridReplans) {
    WorldDef def;
    def.width = 120.0;
    def.height = 90.0;
    def.walls = false;
    for (const int threads : {1, 2}) {
        Twins t(def, 9, threads);
        auto& [fast, plain, fastCtx, plainCtx, profile, fastCounters, plainCounters] = t;
        int kept = 0, replanned = 0;
        for (int s = 0; s < 40; ++s) {
            if (s == 20) {
                for (double& r : fast.radius)
                    r *= 1.7;
                plain.radius = fast.radius;
            }
            stages::discreteStep(fast, def, 0.01, fastCtx, profile, fastCounters);
            (fastCtx.grid.keptPlan() ? kept : replanned) += 1;

            stages::move(plain, 0.01, threads);
            stages::findPairs(plain, plainCtx);
            stages::resolve(plain, def, plainCtx, plainCounters);
            stages::separate(plain, plainCtx);

            ASSERT_TRUE(t.same()) << "step " << s << ", threads " << threads;
            ASSERT_EQ(fastCounters.collisions, plainCounters.collisions) << "step " << s;
        }
        EXPECT_GT(kept, 10) << "move wrote the cells and the grid kept its plan";
        EXPECT_GT(replanned, 2) << "the spreading cloud and the radius change forced new plans";
        EXPECT_GT(fastCounters.collisions, 100u);
    }
}

}  // namespace
}  // namespace psb
