// The last collision card as text (collision_card_lines.hpp): signed components with units,
// before and after, and what was kept and lost.

#include <gtest/gtest.h>

#include <algorithm>

#include "view/collision_card_lines.hpp"
#include "view/head_on_card.hpp"

namespace psb::app {
namespace {

bool has(const std::vector<std::string>& lines, const std::string& s) {
    return std::any_of(lines.begin(), lines.end(),
                       [&](const std::string& l) { return l.find(s) != std::string::npos; });
}

TEST(CollisionCardLines, AnElasticHeadOnCollisionKeepsMomentumAndEnergy) {
    const CollisionCardText t = collisionCardText(headOnCard(1.0));
    EXPECT_EQ(t.title, "Particles 1 and 2 at t = 667 ms");
    const auto lines = collisionCardLines(t);
    EXPECT_TRUE(has(lines, "v 1: (2.00, 0) m/s -> (-2.50, 0) m/s"));
    EXPECT_TRUE(has(lines, "v 2: (-1.00, 0) m/s -> (0.500, 0) m/s"));
    EXPECT_TRUE(has(lines, "p 2: (-3.00, 0) kg m/s -> (1.50, 0) kg m/s"));
    EXPECT_TRUE(has(lines, "total p: (-1.00, 0) kg m/s -> (-1.00, 0) kg m/s"));
    EXPECT_TRUE(has(lines, "kinetic energy: 3.50 J -> 3.50 J"));
    EXPECT_TRUE(has(lines, "Impulse on 1: (-4.50, 0) N s (on 2: the opposite)"));
    EXPECT_TRUE(has(lines, "Total momentum kept"));
    EXPECT_TRUE(has(lines, "Kinetic energy kept (elastic"));
}

TEST(CollisionCardLines, AnInelasticOneSaysTheShareOfEnergyLost) {
    // e = 0.5: the relative motion's energy (3.375 J of the 3.5 J) is cut to a quarter.
    const auto lines = collisionCardLines(collisionCardText(headOnCard(0.5)));
    EXPECT_TRUE(has(lines, "Kinetic energy lost: 72.3 % of it")) << lines.back();
    EXPECT_TRUE(has(lines, "Total momentum kept"));
}

TEST(CollisionCardLines, AWallNamesItsSideAndShowsOneParticle) {
    CollisionCard card;
    card.collision.with = Collision::With::Wall;
    card.collision.where = static_cast<std::uint32_t>(WallSide::Right);
    card.collision.aBefore = Vec2(3.0, 1.0);
    card.collision.aAfter = Vec2(-3.0, 1.0);
    card.collision.impulse = Vec2(-12.0, 0.0);
    card.massA = 2.0;
    card.numberA = 4;
    const CollisionCardText t = collisionCardText(card);
    EXPECT_EQ(t.title.rfind("Particle 4 and the right wall", 0), 0u) << t.title;
    EXPECT_EQ(t.rows.size(), 3u) << "v, p and the energy: no second particle";
    const auto lines = collisionCardLines(t);
    EXPECT_TRUE(has(lines, "p 4: (6.00, 2.00) kg m/s -> (-6.00, 2.00) kg m/s"));
    EXPECT_FALSE(has(lines, "Total momentum"));
}

TEST(CollisionCardText, AFrameShownBeforeTheCollisionSaysHowLongBefore) {
    const CollisionCard card = headOnCard();  // at t = 2/3 s
    EXPECT_EQ(cardAhead(card, 0.5), "The frame shown is 167 ms before it");
    EXPECT_EQ(cardAhead(card, 2.0 / 3.0), "") << "its own frame";
    EXPECT_EQ(cardAhead(card, 0.9), "") << "after it";
}

}  // namespace
}  // namespace psb::app
