// The selection follows a particle by id and forgets it once it is gone.

#include <gtest/gtest.h>

#include "session/selection.hpp"

namespace psb::app {
namespace {

TEST(Selection, FollowsTheParticleThroughOtherRemovals) {
    World w;
    ParticleDef d;
    d.position = {100, 100};
    const ParticleId a = w.add(d);
    d.position = {200, 100};
    const ParticleId b = w.add(d);
    Selection s;
    s.select(b);
    w.remove(a);  // b moves in storage; its id stays
    EXPECT_FALSE(s.forgetIfGone(w));
    ASSERT_TRUE(s.id().has_value());
    EXPECT_EQ(w.get(*s.id()).position, Vec2(200, 100));
}

TEST(Selection, ForgetsARemovedParticleOnce) {
    World w;
    const ParticleId a = w.add(ParticleDef{});
    Selection s;
    s.select(a);
    w.remove(a);
    EXPECT_TRUE(s.forgetIfGone(w));
    EXPECT_FALSE(s.id().has_value());
    EXPECT_FALSE(s.forgetIfGone(w));
    // A new particle reusing the slot is not the selected one.
    w.add(ParticleDef{});
    EXPECT_FALSE(s.id().has_value());
}

TEST(Selection, LogLineNamesStateWithUnitsAndTheParticlesNumber) {
    Particle p;
    p.id = {3, 0};
    p.position = {520, 160};
    p.velocity = {-60, 240};
    p.mass = 18;
    p.radius = 45;
    EXPECT_EQ(selectionLogLine(p, Axes{}),
              "[I] Selected particle 4 at [520.00, 160.00] m with velocity [-60.00, 240.00] m/s, "
              "mass 18 kg, radius 45 m");
    // y up in a 700 m box: the height from the floor and vy upward, as the panel shows them.
    EXPECT_EQ(selectionLogLine(p, Axes{true, 700.0}),
              "[I] Selected particle 4 at [520.00, 540.00] m with velocity [-60.00, -240.00] m/s, "
              "mass 18 kg, radius 45 m");
}

}  // namespace
}  // namespace psb::app
