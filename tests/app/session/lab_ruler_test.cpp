// The ruler (lab_ruler.hpp): alone, and through the session's pointer commands, where its ends
// and edge come before any tool, it changes nothing the undo history keeps, and a scene opened
// lays it across the new box.

#include <gtest/gtest.h>

#include <cmath>

#include "session/lab_ruler.hpp"
#include "session/session_fixture.hpp"

namespace psb::app {
namespace {

TEST(LabRuler, ItReadsLengthSlopeAndItsEndsAndEdgeAreTaken) {
    Camera camera;
    camera.setViewport(800, 600);
    camera.set(100.0, Vec2(0.0, 0.0));  // 100 pixels a metre
    LabRuler r;
    r.place(4.0, 2.0);
    EXPECT_EQ(r.a(), Vec2(1.0, 1.0));
    EXPECT_EQ(r.b(), Vec2(3.0, 1.0));
    EXPECT_EQ(r.partAt(Vec2(105.0, 103.0), camera), LabRuler::Part::EndA);
    EXPECT_EQ(r.partAt(Vec2(296.0, 100.0), camera), LabRuler::Part::EndB);
    EXPECT_EQ(r.partAt(Vec2(200.0, 104.0), camera), LabRuler::Part::Edge);
    EXPECT_FALSE(r.partAt(Vec2(200.0, 120.0), camera).has_value());
    // An end keeps the grab's offset: taken 0.05 m off its centre, it goes where the hand goes.
    r.take(LabRuler::Part::EndB, Vec2(3.05, 1.0));
    r.moveTo(Vec2(4.05, 5.0));
    r.letGo();
    EXPECT_TRUE(r.b().isApprox(Vec2(4.0, 5.0)));
    EXPECT_NEAR(r.length(), 5.0, 1e-12);
    EXPECT_NEAR(r.slopeDegrees(), std::atan2(4.0, 3.0) * 180.0 / M_PI, 1e-9);
    // The edge moves it whole.
    r.take(LabRuler::Part::Edge, Vec2(2.0, 2.0));
    r.moveTo(Vec2(2.5, 1.0));
    EXPECT_TRUE(r.a().isApprox(Vec2(1.5, 0.0)));
    EXPECT_TRUE(r.b().isApprox(Vec2(4.5, 4.0)));
    // A move to a point that is not a number moves nothing.
    r.moveTo(Vec2(std::nan(""), 1.0));
    EXPECT_TRUE(r.a().isApprox(Vec2(1.5, 0.0)));
    r.letGo();
    EXPECT_FALSE(r.held());
}

class SessionRuler : public SessionFixture {
  protected:
    SessionRuler() : SessionFixture("psb-session-ruler", {}) {}
};

TEST_F(SessionRuler, ItsEndsComeBeforeTheToolAndLeaveNothingToUndo) {
    Session s = session();
    const Vec2 a = s.ruler().a();
    const auto before = s.userActions();
    // Hidden, its end is no target: the press launches or flings as ever (a user action).
    drag(s, a, a + Vec2(0.0, -1.0), 0.0);
    EXPECT_EQ(s.ruler().a(), a);
    EXPECT_EQ(s.userActions(), before + 1) << "the drag launched or flung";
    const std::size_t now = s.world().size();
    const auto actions = s.userActions();
    s.apply(cmd::SetShow{cmd::ShowOption::Ruler, true});
    EXPECT_TRUE(said(s.takeNotices(), "Ruler on"));
    drag(s, a, Vec2(2.0, 1.0), 1.0);
    EXPECT_TRUE(s.ruler().a().isApprox(Vec2(2.0, 1.0), 1e-9)) << s.ruler().a().transpose();
    EXPECT_FALSE(s.ruler().held());
    EXPECT_EQ(s.world().size(), now) << "no launch";
    EXPECT_EQ(s.userActions(), actions) << "a ruler is not part of the scene";
    // Hidden while held, it lets go.
    s.apply(cmd::PointerDown{s.camera().worldToScreen(s.ruler().b()), 2.0});
    EXPECT_TRUE(s.ruler().held());
    s.apply(cmd::SetShow{cmd::ShowOption::Ruler, false});
    EXPECT_FALSE(s.ruler().held());
    s.apply(cmd::PointerUp{s.camera().worldToScreen(s.ruler().b()), 2.1});
    // A scene opened lays it across the new box, even one of the same size.
    WorldDef big = s.world().def();
    big.width = 700.0;
    big.height = 700.0;
    s.setWorld(World(big), SceneInfo{.name = "big", .dt = Scene{}.dt});
    EXPECT_EQ(s.ruler().a(), Vec2(175.0, 350.0));
    EXPECT_EQ(s.ruler().b(), Vec2(525.0, 350.0));
}

TEST_F(SessionRuler, RestartRevertAndUndoKeepItsReading) {
    // A student measures a distance, then runs the experiment again with R: the reading stays.
    Session s = session();
    s.apply(cmd::SetShow{cmd::ShowOption::Ruler, true});
    drag(s, s.ruler().a(), Vec2(2.0, 1.0), 0.0);
    drag(s, s.ruler().b(), Vec2(5.0, 5.0), 1.0);
    const Vec2 a = s.ruler().a(), b = s.ruler().b();
    ASSERT_TRUE(a.isApprox(Vec2(2.0, 1.0), 1e-9)) << a.transpose();
    s.apply(cmd::TogglePause{});
    for (int k = 1; k <= 30; ++k)
        s.update(1.0 / 60.0, 2.0 + k / 60.0);
    s.apply(cmd::Restart{});
    EXPECT_TRUE(said(s.takeNotices(), "Restarted"));
    EXPECT_EQ(s.ruler().a(), a);
    EXPECT_EQ(s.ruler().b(), b);
    s.apply(cmd::Revert{});
    EXPECT_EQ(s.ruler().a(), a);
    EXPECT_EQ(s.ruler().b(), b);
    s.apply(cmd::Undo{});
    EXPECT_EQ(s.ruler().a(), a);
    // A box of another size brought back (the undo of a new scene) lays it across that box.
    s.apply(cmd::NewScene{20.0, 10.0, 0.0, true});
    EXPECT_EQ(s.ruler().a(), Vec2(5.0, 5.0));
    s.apply(cmd::SetShow{cmd::ShowOption::Ruler, true});
    drag(s, s.ruler().a(), Vec2(1.0, 1.0), 3.0);
    s.apply(cmd::Undo{});
    const WorldDef def = s.world().def();
    EXPECT_EQ(s.ruler().a(), Vec2(0.25 * def.width, 0.5 * def.height));
}

}  // namespace
}  // namespace psb::app
