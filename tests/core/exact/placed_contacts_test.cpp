// The exact mode's pairs placed overlapping (PlacedContacts): each keeps the distance it was
// placed at until it is found apart; held pairs pass through each other and are left out.

#include <gtest/gtest.h>

#include <vector>

#include "exact/placed_contacts.hpp"
#include "parts.hpp"

namespace psb::exact {
namespace {

struct Placed {
    WorldDef def;
    std::vector<Body> bodies;
    std::vector<Cold> cold;
    std::vector<std::uint32_t> order{5, 9, 2};  // storage indices, not the stepper's
    Grid grid;
    PlacedContacts placed;

    // Discs of 1 m: 0 and 1 placed 1.5 m apart (0.5 m inside contact), 2 far off.
    explicit Placed(std::uint32_t flags) {
        def.width = def.height = 20.0;
        bodies = {bodyAt(5.0, 5.0, 1.0, 0.0, 0.0, flags), bodyAt(6.5, 5.0, 1.0, 0.0, 0.0, flags),
                  bodyAt(15.0, 15.0, 1.0)};
        cold.assign(bodies.size(), Cold{});
        grid.setUp(def, bodies, cold);
        for (std::uint32_t i = 0; i < bodies.size(); ++i)
            grid.insert(i, cold[i]);
        placed.record(bodies, cold, order, grid);
    }
};

TEST(ExactPlacedContacts, APairPlacedOverlappingKeepsItsDistanceUntilItIsApart) {
    Placed p(0);
    EXPECT_TRUE(p.bodies[0].flags & kPlacedOverlapping);
    EXPECT_TRUE(p.bodies[1].flags & kPlacedOverlapping);
    EXPECT_FALSE(p.bodies[2].flags & kPlacedOverlapping);
    EXPECT_DOUBLE_EQ(p.placed.deepest(), 0.5);
    // Keyed by storage indices, either way round.
    EXPECT_DOUBLE_EQ(p.placed.contactDistance(5, 9, 1.5, 0.0, 2.0), 1.5);
    EXPECT_DOUBLE_EQ(p.placed.contactDistance(9, 5, 0.0, 1.9, 2.0), 1.5);
    EXPECT_DOUBLE_EQ(p.placed.contactDistance(5, 2, 1.5, 0.0, 2.0), 2.0);
    // Found apart: an ordinary pair from then on, even if it comes back inside.
    EXPECT_DOUBLE_EQ(p.placed.contactDistance(5, 9, 2.0, 0.0, 2.0), 2.0);
    EXPECT_DOUBLE_EQ(p.placed.contactDistance(5, 9, 1.5, 0.0, 2.0), 2.0);
    EXPECT_EQ(p.placed.deepest(), 0.0);
}

TEST(ExactPlacedContacts, HeldPairsAreLeftOut) {
    Placed p(kHeld);
    EXPECT_FALSE(p.bodies[0].flags & kPlacedOverlapping);
    EXPECT_EQ(p.placed.deepest(), 0.0);
}

}  // namespace
}  // namespace psb::exact
