// One collision log, several instruments (collision_feed.hpp): what they want merged, the world
// made to record it, and a world put back with a log of its own emptied.

#include <gtest/gtest.h>

#include "session/collision_feed.hpp"

namespace psb::app {
namespace {

TEST(CollisionFeed, MergingKeepsEveryCollisionIfEitherWantsAllElseTheUnionOfIds) {
    const ParticleId a{1, 0}, b{2, 0}, c{3, 1};
    EXPECT_FALSE(mergeWanted(std::nullopt, std::nullopt));
    EXPECT_EQ(mergeWanted(CollisionLog({a}), std::nullopt)->chosen(), std::vector<ParticleId>{a});
    EXPECT_EQ(mergeWanted(std::nullopt, CollisionLog({b}))->chosen(), std::vector<ParticleId>{b});
    EXPECT_TRUE(mergeWanted(CollisionLog({a}), CollisionLog())->keepsAll());
    const auto both = mergeWanted(CollisionLog({c, a}), CollisionLog({a, b}));
    ASSERT_TRUE(both);
    EXPECT_FALSE(both->keepsAll());
    EXPECT_EQ(both->chosen(), (std::vector<ParticleId>{a, b, c}));
}

TEST(CollisionFeed, ListeningEmptiesWhatAWorldPutBackRecordedAndStopsWhenNoneWants) {
    WorldDef def;
    def.width = def.height = 10.0;
    World w(def);
    const ParticleId p = w.add({.position = Vec2(9.0, 5.0), .velocity = Vec2(3.0, 0.0)});
    listen(w, CollisionLog({p}));
    for (int k = 0; k < 50; ++k)
        w.step(0.01);
    ASSERT_FALSE(w.collisionLog()->records().empty()) << "it hit the right wall";
    // The same wish again: the log is kept, emptied of what nobody heard being made.
    const CollisionLog* before = w.collisionLog();
    listen(w, CollisionLog({p}));
    EXPECT_EQ(w.collisionLog(), before);
    EXPECT_TRUE(w.collisionLog()->records().empty());
    listen(w, CollisionLog());
    EXPECT_TRUE(w.collisionLog()->keepsAll());
    EXPECT_TRUE(heard(w).empty());
    listen(w, std::nullopt);
    EXPECT_FALSE(w.recordingCollisions());
    EXPECT_TRUE(heard(w).empty());
}

}  // namespace
}  // namespace psb::app
