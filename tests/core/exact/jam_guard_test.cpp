// The exact mode's jam guards (JamGuard): a run of kJamHits hits without time or room jams a
// particle, a hit with room ends the run; kJamLimit hits on held particles in a step let it
// pass through them until the next step.

#include <gtest/gtest.h>

#include <vector>

#include "exact/jam_guard.hpp"
#include "parts.hpp"

namespace psb::exact {
namespace {

TEST(ExactJamGuard, ARunOfHitsWithoutTimeOrRoomJamsAtkJamHits) {
    JamGuard guard;
    const std::vector<std::uint32_t> order{7};
    Body a = bodyAt(1.0, 1.0, 0.5, 1.0, 0.0);
    a.t = 2.0;
    for (std::uint32_t k = 1; k < kJamHits; ++k)
        ASSERT_FALSE(guard.jams(a, 0, order, 2.0)) << k;
    EXPECT_TRUE(guard.jams(a, 0, order, 2.0));
    EXPECT_TRUE(guard.jams(a, 0, order, 2.0 + 0.1 * kJamTime)) << "the run goes on";
}

TEST(ExactJamGuard, AHitWithRoomEndsTheRun) {
    JamGuard guard;
    const std::vector<std::uint32_t> order{7};
    Body a = bodyAt(1.0, 1.0, 0.5, 1.0, 0.0);
    for (std::uint32_t k = 1; k < kJamHits; ++k)
        ASSERT_FALSE(guard.jams(a, 0, order, 0.0));
    // A millisecond at 1 m/s: a millimetre, far more than kJamRoom of the radius.
    EXPECT_FALSE(guard.jams(a, 0, order, 1e-3));
    EXPECT_FALSE(guard.jams(a, 0, order, 0.0)) << "a new run starts from one";
}

TEST(ExactJamGuard, HeldHitsPastTheLimitLetAParticlePassUntilTheNextStep) {
    JamGuard guard;
    std::vector<Body> bodies{bodyAt(1.0, 1.0, 0.5)};
    std::vector<Cold> cold(1, Cold{});
    for (std::uint32_t k = 1; k < kJamLimit; ++k) {
        guard.countHeldHit(0, bodies[0], cold[0]);
        ASSERT_FALSE(bodies[0].flags & kJammed) << k;
    }
    guard.countHeldHit(0, bodies[0], cold[0]);
    EXPECT_TRUE(bodies[0].flags & kJammed);
    EXPECT_EQ(cold[0].heldHits, kJamLimit);
    guard.startStep(bodies, cold);
    EXPECT_FALSE(bodies[0].flags & kJammed);
    EXPECT_EQ(cold[0].heldHits, 0u);
}

}  // namespace
}  // namespace psb::exact
