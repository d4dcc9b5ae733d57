// The last collision card (last_collision.hpp) through the session: a 1 kg / 3 kg head-on
// collision read off the card in every mode, the card following the selection, and going when
// the clock goes back before it.

#include <gtest/gtest.h>

#include "session/session_fixture.hpp"

namespace psb::app {
namespace {

constexpr double kFrame = 1.0 / 60.0;

/// 1 kg at 2 m/s from x = 3 and 3 kg at -1 m/s from x = 6, radii 0.5 m, no walls: they meet at
/// t = 2/3 s and leave at -2.5 m/s and 0.5 m/s (e = 1).
World twoBalls(StepMode mode) {
    WorldDef def;
    def.width = 10.0;
    def.height = 10.0;
    def.walls = false;
    World w(def, {.mode = mode, .substeps = mode == StepMode::Substep ? 4 : 1});
    w.add({.position = Vec2(3.0, 5.0), .velocity = Vec2(2.0, 0.0), .mass = 1.0, .radius = 0.5});
    w.add({.position = Vec2(6.0, 5.0), .velocity = Vec2(-1.0, 0.0), .mass = 3.0, .radius = 0.5});
    return w;
}

class LastCollisionCard : public SessionFixture, public ::testing::WithParamInterface<StepMode> {
  protected:
    LastCollisionCard() : SessionFixture("psb-last-collision", {}) {}

    [[nodiscard]] Session twoBallSession() const {
        return Session(twoBalls(GetParam()), SceneInfo{.name = "two balls", .dt = 1.0 / 60.0},
                       options());
    }

    void run(Session& s, int frames) {
        if (s.paused()) s.apply(cmd::TogglePause{});
        for (int k = 0; k < frames; ++k) {
            now_ += kFrame;
            s.update(kFrame, now_);
        }
        s.apply(cmd::TogglePause{});
    }

    double now_ = 0.0;
};

TEST_P(LastCollisionCard, AHeadOnCollisionReadsOffTheCardOpenedAfterIt) {
    Session s = twoBallSession();
    run(s, 20);
    EXPECT_FALSE(s.lastCollision()) << "no collision yet";
    // The card hidden through the collision: a scene of two balls is followed all along, so J
    // pressed afterwards shows it.
    run(s, 60);
    s.apply(cmd::SetShow{cmd::ShowOption::Collision, true});
    ASSERT_TRUE(s.lastCollision());
    const CollisionCard& c = *s.lastCollision();
    ASSERT_TRUE(c.pair());
    EXPECT_EQ(c.follows, 0u);
    EXPECT_EQ(c.massA + c.massB, 4.0);
    // Particle 1 (1 kg) is a or b; read it by number.
    const bool oneFirst = c.numberA == 1;
    const Vec2 v1Before = oneFirst ? c.collision.aBefore : c.collision.bBefore;
    const Vec2 v1After = oneFirst ? c.collision.aAfter : c.collision.bAfter;
    const Vec2 v2After = oneFirst ? c.collision.bAfter : c.collision.aAfter;
    EXPECT_NEAR(v1Before.x(), 2.0, 1e-12);
    EXPECT_NEAR(v1After.x(), -2.5, 1e-12);
    EXPECT_NEAR(v2After.x(), 0.5, 1e-12);
    EXPECT_NEAR(c.momentumBefore().x(), -1.0, 1e-12);
    EXPECT_NEAR(c.momentumAfter().x(), -1.0, 1e-12);
    EXPECT_NEAR(c.energyBefore(), 3.5, 1e-12);
    EXPECT_NEAR(c.energyAfter(), 3.5, 1e-12);
    if (GetParam() == StepMode::Exact) {
        EXPECT_NEAR(c.collision.time, 2.0 / 3.0, 1e-12);
    }
}

TEST_P(LastCollisionCard, TheCardFollowsTheSelectionAndGoesWhenTheClockGoesBackBeforeIt) {
    Session s = twoBallSession();
    s.apply(cmd::SetShow{cmd::ShowOption::Collision, true});
    run(s, 60);
    ASSERT_TRUE(s.lastCollision());
    // Selecting the 3 kg ball puts it first.
    const ParticleId heavy = s.world().particles().id[1];
    s.apply(cmd::PointerDown{s.camera().worldToScreen(s.world().get(heavy).position), now_});
    s.apply(cmd::PointerUp{s.camera().worldToScreen(s.world().get(heavy).position), now_ + 0.05});
    ASSERT_EQ(s.selected()->id, heavy);
    s.update(0.0, now_);
    ASSERT_TRUE(s.lastCollision());
    EXPECT_EQ(s.lastCollision()->numberA, particleNumber(heavy));
    EXPECT_EQ(s.lastCollision()->massA, 3.0);
    EXPECT_NEAR(s.lastCollision()->collision.impulse.x(), 4.5, 1e-12) << "3 kg x (0.5 - -1)";
    // Hidden and shown again, a small scene's card is still there.
    s.apply(cmd::SetShow{cmd::ShowOption::Collision, false});
    s.apply(cmd::SetShow{cmd::ShowOption::Collision, true});
    EXPECT_TRUE(s.lastCollision());
}

TEST_P(LastCollisionCard, ALargeScenesCardListensOnlyWhileShown) {
    World w = twoBalls(GetParam());
    // Beyond the card's small-scene limit, the rest far from the two balls.
    for (std::size_t k = 0; k < LastCollision::kListensHiddenUpTo; ++k) {
        w.add({.position = Vec2(0.3 + 0.15 * static_cast<double>(k % 60), 9.7), .radius = 0.05});
    }
    Session s(std::move(w), SceneInfo{.name = "crowd", .dt = 1.0 / 60.0}, options());
    run(s, 60);
    s.apply(cmd::SetShow{cmd::ShowOption::Collision, true});
    EXPECT_FALSE(s.lastCollision()) << "hidden in a large scene: nothing recorded for it";
    s.apply(cmd::Restart{});
    s.update(0.0, now_);
    run(s, 60);
    EXPECT_TRUE(s.lastCollision()) << "shown: the collision is kept";
    s.apply(cmd::SetShow{cmd::ShowOption::Collision, false});
    EXPECT_FALSE(s.lastCollision()) << "hidden again: it stops listening and lets it go";
}

TEST_P(LastCollisionCard, AStepBackBeforeTheCollisionClearsTheCard) {
    Session s = twoBallSession();
    s.apply(cmd::SetShow{cmd::ShowOption::Collision, true});
    run(s, 60);
    ASSERT_TRUE(s.lastCollision());
    s.apply(cmd::Restart{});
    s.update(0.0, now_);
    EXPECT_FALSE(s.lastCollision());
}

TEST_P(LastCollisionCard, SteppingBackThroughTheFramesBeforeTheCollisionKeepsTheCard) {
    // The lesson steps back frame by frame to read the moment of impact: one frame before it
    // the card went (and the panel's layout jumped under the pointer on the step buttons). The
    // recorded frames shown are the card's history: it stays through them, back and forth.
    Session s = twoBallSession();
    s.apply(cmd::SetShow{cmd::ShowOption::Collision, true});
    run(s, 60);  // to 1 s; the collision at 2/3 s
    ASSERT_TRUE(s.lastCollision());
    const double at = s.lastCollision()->collision.time;
    while (s.world().time() > at - 2.5 * kFrame) {
        s.apply(cmd::StepBack{});
        s.update(0.0, now_);
        ASSERT_TRUE(s.lastCollision()) << "at " << s.world().time() << " s, stepping back";
        EXPECT_EQ(s.lastCollision()->collision.time, at);
    }
    s.apply(cmd::Seek{0.2});
    s.update(0.0, now_);
    EXPECT_TRUE(s.lastCollision()) << "the slider far back: the same history";
    s.apply(cmd::Seek{0.9});
    s.update(0.0, now_);
    ASSERT_TRUE(s.lastCollision()) << "forward past it again: the same collision, shown";
    EXPECT_EQ(s.lastCollision()->collision.time, at);
    // Back before it, then the world runs on from there: a new history, found afresh.
    s.apply(cmd::Seek{0.5});
    s.update(0.0, now_);
    run(s, 1);
    EXPECT_FALSE(s.lastCollision()) << "carried on from 0.5 s: not happened in this history yet";
    run(s, 30);
    ASSERT_TRUE(s.lastCollision());
    EXPECT_NEAR(s.lastCollision()->collision.time, at, 1e-9);
}

INSTANTIATE_TEST_SUITE_P(Modes, LastCollisionCard,
                         ::testing::Values(StepMode::Discrete, StepMode::Substep, StepMode::Exact),
                         [](const auto& mode) {
                             return std::string(mode.param == StepMode::Discrete  ? "Discrete"
                                                : mode.param == StepMode::Substep ? "Substep"
                                                                                  : "Exact");
                         });

}  // namespace
}  // namespace psb::app
