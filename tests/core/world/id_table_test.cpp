#include <gtest/gtest.h>

#include <vector>

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

TEST(IdTable, ANewIdTakesTheLowestFreeSlot) {
    // Slots are what particle numbers are made of (particleNumber): 0, 1, 2 ... for a world
    // built without removals, and a freed slot is taken again lowest first, whatever order
    // the slots were freed in.
    IdTable t;
    std::vector<ParticleId> ids;
    for (std::uint32_t k = 0; k < 6; ++k)
        ids.push_back(t.allocate(k));
    for (std::uint32_t k = 0; k < 6; ++k)
        EXPECT_EQ(ids[k].slot, k);
    t.release(ids[4]);
    t.release(ids[1]);
    t.release(ids[3]);
    EXPECT_EQ(t.allocate(3).slot, 1u);
    EXPECT_EQ(t.allocate(4).slot, 3u);
    EXPECT_EQ(t.allocate(5).slot, 4u);
    EXPECT_EQ(t.allocate(6).slot, 6u);
    t.clear();
    EXPECT_EQ(t.allocate(0).slot, 0u);
    EXPECT_EQ(t.allocate(1).slot, 1u);
}

TEST(IdTable, UnknownAndNullIdsAreNotFound) {
    IdTable t;
    EXPECT_FALSE(t.find(kNullParticle).has_value());
    EXPECT_FALSE(t.find(ParticleId{7, 0}).has_value());
}

}  // namespace
}  // namespace psb::detail
