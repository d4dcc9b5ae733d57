#include <gtest/gtest.h>

#include <particle_sandbox/detail/id_table.hpp>

namespace psb::detail {
namespace {

TEST(IdTable, AllocateFindRelocateRelease) {
    IdTable t;
    const ParticleId a = t.allocate(0);
    const ParticleId b = t.allocate(1);
    EXPECT_EQ(t.find(a), 0u);
    EXPECT_EQ(t.find(b), 1u);
    t.relocate(b, 0);
    t.release(a);
    EXPECT_FALSE(t.find(a).has_value());
    EXPECT_EQ(t.find(b), 0u);
    const ParticleId c = t.allocate(1);
    EXPECT_EQ(c.slot, a.slot);
    EXPECT_NE(c.generation, a.generation);
    EXPECT_FALSE(t.find(a).has_value());
    EXPECT_EQ(t.find(c), 1u);
}

TEST(IdTable, UnknownAndNullIdsAreNotFound) {
    IdTable t;
    EXPECT_FALSE(t.find(kNullParticle).has_value());
    EXPECT_FALSE(t.find(ParticleId{7, 0}).has_value());
}

}  // namespace
}  // namespace psb::detail
