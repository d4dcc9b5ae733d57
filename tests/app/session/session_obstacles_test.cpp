// The obstacle tools through the session, as the mouse, keys and panel drive them: a peg placed,
// a wall drawn, an obstacle selected and removed, each undone and redone, and what is refused.

#include <gtest/gtest.h>

#include <algorithm>

#include <particle_sandbox/scene.hpp>

#include "session/session.hpp"
#include "session/session_fixture.hpp"

namespace psb::app {
namespace {

namespace fs = std::filesystem;

class SessionObstacles : public TempDirTest {
  protected:
    SessionObstacles() : TempDirTest("psb-session-obstacles") {}

    /// A 7 m box with one particle of radius 0.2 m at (6, 6).
    [[nodiscard]] static Session session() {
        WorldDef d;
        d.width = d.height = 7.0;
        World w(d);
        ParticleDef p;
        p.position = Vec2(6.0, 6.0);
        p.radius = 0.2;
        p.mass = 1.0;
        w.add(p);
        SessionOptions o;
        o.paused = true;
        return Session(std::move(w), SceneInfo{.name = "test", .dt = Scene{}.dt}, o);
    }
    /// Press at world point `from`, five moves, release at `to`.
    static void drag(Session& s, Vec2 from, Vec2 to, double t0 = 1.0) {
        psb::app::drag(s, from, to, t0, 5, 0.01);
    }
    static void click(Session& s, Vec2 at, double t = 1.0) {
        s.apply(cmd::PointerDown{s.camera().worldToScreen(at), t});
        s.apply(cmd::PointerUp{s.camera().worldToScreen(at), t + 0.05});
    }
    static void expectNear(const Vec2& a, const Vec2& b) {
        EXPECT_NEAR(a.x(), b.x(), 1e-9);
        EXPECT_NEAR(a.y(), b.y(), 1e-9);
    }
};

TEST_F(SessionObstacles, SizesFollowTheScenesTypicalParticle) {
    Session s = session();
    EXPECT_DOUBLE_EQ(s.obstacleSizes().pegRadius, s.spawn().typicalRadius);
    EXPECT_DOUBLE_EQ(s.obstacleSizes().wallThickness, s.spawn().typicalRadius);
    s.apply(cmd::SetObstacleSizes{0.3, 0.1});
    EXPECT_DOUBLE_EQ(s.obstacleSizes().pegRadius, 0.3);
    EXPECT_DOUBLE_EQ(s.obstacleSizes().wallThickness, 0.1);
    EXPECT_EQ(s.userActions(), 0u);  // a tool's setting, not an edit of the world
    EXPECT_FALSE(s.canUndo());
}

TEST_F(SessionObstacles, NoPegShadeStaysWhereTheFingerLifted) {
    // A tablet: the Peg tool's shade of the peg a tap would place stayed where the finger
    // lifted (a hover with no pointer). A lifted finger, or a mouse that left the window, is a
    // pointer gone.
    Session s = session();
    s.apply(cmd::SetTool{cmd::Tool::Peg});
    const Vec2 at = s.camera().worldToScreen(Vec2(2.0, 3.0));
    s.apply(cmd::PointerMove{at, 0.5});
    ASSERT_TRUE(s.obstaclePreview()) << "a mouse over the box shows where the peg would go";
    s.apply(cmd::PointerLeave{});
    EXPECT_FALSE(s.obstaclePreview()) << "the mouse left the window";
    s.apply(cmd::PointerDown{at, 1.0});
    s.apply(cmd::PointerUp{at, 1.05});
    s.apply(cmd::PointerLeave{});  // the finger lifted (platform/input.cpp sends both)
    ASSERT_EQ(s.world().obstacles().size(), 1u);
    EXPECT_FALSE(s.obstaclePreview()) << "a shade stayed where the finger lifted";
    EXPECT_EQ(s.userActions(), 1u) << "leaving is no edit";
    s.apply(cmd::PointerMove{at, 1.5});
    EXPECT_TRUE(s.obstaclePreview()) << "back with the pointer";
}

TEST_F(SessionObstacles, APegToolClickPlacesAPegUndoneAndRedone) {
    Session s = session();
    s.apply(cmd::SetObstacleSizes{0.3, 0.1});
    s.apply(cmd::SetTool{cmd::Tool::Peg});
    EXPECT_FALSE(s.obstaclePreview());  // the pointer is not over the box yet
    s.apply(cmd::PointerMove{s.camera().worldToScreen(Vec2(2.0, 3.0)), 0.5});
    ASSERT_TRUE(s.obstaclePreview());  // the peg under the pointer, before any press
    expectNear(s.obstaclePreview()->a, Vec2(2.0, 3.0));
    click(s, Vec2(2.0, 3.0));
    ASSERT_EQ(s.world().obstacles().size(), 1u);
    const Obstacle peg = s.world().obstacles()[0];
    EXPECT_TRUE(peg.isPeg());
    expectNear(peg.a, Vec2(2.0, 3.0));
    EXPECT_DOUBLE_EQ(peg.radius, 0.3);
    EXPECT_EQ(s.lastAction(), "place peg");
    EXPECT_TRUE(s.unsavedChanges());
    EXPECT_TRUE(said(s.takeNotices(), "Peg placed"));
    EXPECT_EQ(s.world().size(), 1u);  // no particle launched

    s.apply(cmd::Undo{});
    EXPECT_TRUE(s.world().obstacles().empty());
    EXPECT_FALSE(s.unsavedChanges());
    EXPECT_TRUE(said(s.takeNotices(), "Undone: place peg"));
    s.apply(cmd::Redo{});
    ASSERT_EQ(s.world().obstacles().size(), 1u);
    EXPECT_EQ(s.world().obstacles()[0], peg);
}

TEST_F(SessionObstacles, AWallToolDragDrawsAWallWithAPreviewUndoneAndRedone) {
    Session s = session();
    s.apply(cmd::SetTool{cmd::Tool::Wall});
    EXPECT_FALSE(s.obstaclePreview());  // nothing before a press
    const Camera& c = s.camera();
    s.apply(cmd::PointerDown{c.worldToScreen(Vec2(1.0, 5.0)), 1.0});
    s.apply(cmd::PointerMove{c.worldToScreen(Vec2(3.0, 4.0)), 1.05});
    ASSERT_TRUE(s.obstaclePreview());
    expectNear(s.obstaclePreview()->b, Vec2(3.0, 4.0));
    EXPECT_TRUE(s.world().obstacles().empty());  // not yet: the release draws it
    s.apply(cmd::PointerUp{c.worldToScreen(Vec2(5.0, 3.0)), 1.1});
    EXPECT_FALSE(s.obstaclePreview());
    ASSERT_EQ(s.world().obstacles().size(), 1u);
    const Obstacle wall = s.world().obstacles()[0];
    EXPECT_FALSE(wall.isPeg());
    expectNear(wall.a, Vec2(1.0, 5.0));
    expectNear(wall.b, Vec2(5.0, 3.0));
    EXPECT_DOUBLE_EQ(wall.thickness(), s.obstacleSizes().wallThickness);
    EXPECT_EQ(s.lastAction(), "draw wall");
    EXPECT_EQ(s.undoLabel(), "draw wall");

    s.apply(cmd::Undo{});
    EXPECT_TRUE(s.world().obstacles().empty());
    s.apply(cmd::Redo{});
    ASSERT_EQ(s.world().obstacles().size(), 1u);
    EXPECT_EQ(s.world().obstacles()[0], wall);
}

TEST_F(SessionObstacles, InvalidGesturesAndSizesAreRefusedWithANoticeAndNoUndoEntry) {
    Session s = session();
    s.apply(cmd::SetTool{cmd::Tool::Wall});
    click(s, Vec2(2.0, 2.0));  // zero length
    EXPECT_TRUE(said(s.takeNotices(), "No wall drawn: drag from one end"));
    drag(s, Vec2(-1.0, 2.0), Vec2(3.0, 2.0));  // started outside the box
    EXPECT_TRUE(said(s.takeNotices(), "start the drag inside the box"));
    s.apply(cmd::SetTool{cmd::Tool::Peg});
    click(s, Vec2(3.0, 8.0));
    EXPECT_TRUE(said(s.takeNotices(), "No peg placed: click inside the box"));
    EXPECT_TRUE(s.world().obstacles().empty());
    EXPECT_FALSE(s.canUndo());
    EXPECT_FALSE(s.unsavedChanges());

    const ObstacleSizes before = s.obstacleSizes();
    s.apply(cmd::SetObstacleSizes{0.0, 0.1});
    EXPECT_TRUE(said(s.takeNotices(), "peg radius must be a number above 0"));
    s.apply(cmd::SetObstacleSizes{0.3, 10.0});
    EXPECT_TRUE(said(s.takeNotices(), "wall thickness can be at most"));
    EXPECT_DOUBLE_EQ(s.obstacleSizes().pegRadius, before.pegRadius);
    EXPECT_DOUBLE_EQ(s.obstacleSizes().wallThickness, before.wallThickness);

    s.apply(cmd::RemoveObstacle{3});
    EXPECT_TRUE(said(s.takeNotices(), "No obstacle 3 to remove (there are 0)"));
}

TEST_F(SessionObstacles, AnObstacleOverAParticleIsRefusedWithAMessage) {
    // A teacher placed a peg on a particle; run, the particle passed out through the peg.
    Session s = session();
    (void)s.takeNotices();
    s.apply(cmd::SetTool{cmd::Tool::Peg});
    click(s, Vec2(6.1, 6.0));  // on the particle at (6, 6)
    EXPECT_TRUE(said(s.takeNotices(),
                     "Not placed: the peg would overlap a particle; put it where no particle is"));
    EXPECT_TRUE(s.world().obstacles().empty());
    s.apply(cmd::SetTool{cmd::Tool::Wall});
    drag(s, Vec2(5.0, 6.0), Vec2(6.9, 6.0));  // through it
    EXPECT_TRUE(said(s.takeNotices(),
                     "Not placed: the wall would overlap a particle; put it where no particle is"));
    EXPECT_TRUE(s.world().obstacles().empty());
    EXPECT_FALSE(s.canUndo());
    // Beside it, clear by a hair: placed.
    const double clear = 0.2 + 0.5 * s.obstacleSizes().wallThickness + 1e-6;
    drag(s, Vec2(5.0, 6.0 - clear), Vec2(6.9, 6.0 - clear));
    ASSERT_EQ(s.world().obstacles().size(), 1u);
    // Moved onto it: refused, nothing moved, no new undo entry.
    const Obstacle wall = s.world().obstacles()[0];
    const std::size_t entries = s.undoHistory().undoCount();
    s.apply(cmd::SetTool{cmd::Tool::Select});
    (void)s.takeNotices();
    drag(s, Vec2(5.5, 6.0 - clear), Vec2(5.5, 6.0));
    EXPECT_TRUE(said(s.takeNotices(),
                     "Not moved: the wall would overlap a particle; put it where no particle is"));
    EXPECT_EQ(s.world().obstacles()[0], wall);
    EXPECT_EQ(s.undoHistory().undoCount(), entries);
    EXPECT_EQ(s.world().size(), 1u);
}

TEST_F(SessionObstacles, AClickSelectsAnObstacleAndDeleteRemovesItUndoably) {
    Session s = session();
    s.apply(cmd::SetTool{cmd::Tool::Peg});
    click(s, Vec2(2.0, 2.0));
    s.apply(cmd::SetTool{cmd::Tool::Wall});
    drag(s, Vec2(1.0, 5.0), Vec2(5.0, 5.0));
    ASSERT_EQ(s.world().obstacles().size(), 2u);
    const Obstacles both = s.world().obstacles();

    s.apply(cmd::SetTool{cmd::Tool::Select});
    click(s, Vec2(3.0, 5.0));  // on the wall
    EXPECT_EQ(s.selectedObstacle(), 1u);
    EXPECT_TRUE(said(s.takeNotices(), "Selected a wall"));
    s.apply(cmd::DeleteHeld{});  // Backspace / Delete
    ASSERT_EQ(s.world().obstacles().size(), 1u);
    EXPECT_TRUE(s.world().obstacles()[0].isPeg());
    EXPECT_FALSE(s.selectedObstacle());
    EXPECT_EQ(s.lastAction(), "remove wall");
    s.apply(cmd::Undo{});
    EXPECT_EQ(s.world().obstacles(), both);
    EXPECT_EQ(s.selectedObstacle(), 1u);  // selected again, as it was when deleted
    s.apply(cmd::Redo{});
    EXPECT_EQ(s.world().obstacles().size(), 1u);
    EXPECT_FALSE(s.selectedObstacle());
    s.apply(cmd::Undo{});

    // The panel's button; the Fling tool's click selects too.
    s.apply(cmd::SetTool{cmd::Tool::Fling});
    click(s, Vec2(2.0, 2.0));
    EXPECT_EQ(s.selectedObstacle(), 0u);
    EXPECT_EQ(s.world().size(), 1u);  // the click launched nothing
    s.apply(cmd::RemoveObstacle{0});
    ASSERT_EQ(s.world().obstacles().size(), 1u);
    EXPECT_FALSE(s.world().obstacles()[0].isPeg());
    EXPECT_EQ(s.undoLabel(), "remove peg");

    s.apply(cmd::SetTool{cmd::Tool::Launch});  // a click launches nothing, and selects
    click(s, Vec2(3.0, 5.0));
    EXPECT_EQ(s.selectedObstacle(), 0u);
    EXPECT_EQ(s.world().size(), 1u);
    s.apply(cmd::SetTool{cmd::Tool::Fling});

    // A click on empty space clears the selection; one on a particle selects it instead.
    click(s, Vec2(3.0, 5.0));
    EXPECT_EQ(s.selectedObstacle(), 0u);
    click(s, Vec2(3.0, 1.0));
    EXPECT_FALSE(s.selectedObstacle());
    click(s, Vec2(3.0, 5.0));
    click(s, Vec2(6.0, 6.0));
    EXPECT_FALSE(s.selectedObstacle());
    EXPECT_TRUE(s.selected());
}

TEST_F(SessionObstacles, TheSelectToolDragsAnObstacleToMoveItUndoably) {
    Session s = session();
    s.apply(cmd::SetTool{cmd::Tool::Wall});
    drag(s, Vec2(1.0, 5.0), Vec2(3.0, 5.0));
    const Obstacle drawn = s.world().obstacles().at(0);
    s.apply(cmd::SetTool{cmd::Tool::Select});
    const Camera& c = s.camera();
    s.apply(cmd::PointerDown{c.worldToScreen(Vec2(2.0, 5.0)), 2.0});
    s.apply(cmd::PointerMove{c.worldToScreen(Vec2(3.0, 4.0)), 2.05});
    ASSERT_TRUE(s.obstaclePreview());     // where it will go
    EXPECT_EQ(s.selectedObstacle(), 0u);  // highlighted while dragged
    expectNear(s.obstaclePreview()->a, drawn.a + Vec2(1.0, -1.0));
    EXPECT_EQ(s.world().obstacles()[0], drawn);  // not yet
    s.apply(cmd::PointerUp{c.worldToScreen(Vec2(3.0, 4.0)), 2.1});
    const Obstacle moved = s.world().obstacles().at(0);
    expectNear(moved.a, drawn.a + Vec2(1.0, -1.0));
    expectNear(moved.b, drawn.b + Vec2(1.0, -1.0));
    EXPECT_EQ(s.selectedObstacle(), 0u);
    EXPECT_EQ(s.lastAction(), "move wall");
    s.apply(cmd::Undo{});
    EXPECT_EQ(s.world().obstacles().at(0), drawn);
    EXPECT_FALSE(s.selectedObstacle());  // as before the press that grabbed it
    s.apply(cmd::Redo{});
    EXPECT_EQ(s.selectedObstacle(), 0u);
    EXPECT_EQ(s.world().obstacles().at(0), moved);

    // Out of the box: refused, nothing moved, no undo entry.
    const std::size_t entries = s.undoHistory().undoCount();
    (void)s.takeNotices();
    drag(s, Vec2(3.0, 4.0), Vec2(3.0, 9.0));
    EXPECT_TRUE(said(s.takeNotices(), "Not moved: the wall would leave the box"));
    EXPECT_EQ(s.world().obstacles().at(0), moved);
    EXPECT_EQ(s.undoHistory().undoCount(), entries);
}

TEST_F(SessionObstacles, OnATouchScreenTheMessagesNameThePanelsUndoAndDeleteNotKeys) {
    Session s = session();
    s.apply(cmd::SetTool{cmd::Tool::Peg});
    click(s, Vec2(2.0, 2.0));
    EXPECT_TRUE(said(s.takeNotices(), "Peg placed (Ctrl+Z undoes it)"));
    s.apply(cmd::Undo{});

    // A finger: the same gestures, the panel's controls named.
    s.apply(cmd::SetTouch{true});
    click(s, Vec2(2.0, 2.0));
    std::vector<Notice> n = s.takeNotices();
    EXPECT_TRUE(said(n, "Peg placed (Time: Undo undoes it)"));
    s.apply(cmd::SetTool{cmd::Tool::Select});
    drag(s, Vec2(2.0, 2.0), Vec2(3.0, 2.0));
    const std::vector<Notice> moved = s.takeNotices();
    EXPECT_TRUE(said(moved, "Moved the peg (Time: Undo puts it back)"));
    n.insert(n.end(), moved.begin(), moved.end());
    click(s, Vec2(3.0, 2.0));
    const std::vector<Notice> selected = s.takeNotices();
    EXPECT_TRUE(said(selected, "Selected a peg: Tools: Delete peg removes it"));
    n.insert(n.end(), selected.begin(), selected.end());
    s.apply(cmd::RemoveObstacle{0});
    const std::vector<Notice> removed = s.takeNotices();
    EXPECT_TRUE(said(removed, "Removed the peg (Time: Undo brings it back)"));
    n.insert(n.end(), removed.begin(), removed.end());
    for (const Notice& notice : n) {
        for (const char* key : {"Ctrl+", "Delete or", "Backspace"})
            EXPECT_EQ(notice.text.find(key), std::string::npos) << notice.text;
    }
}

TEST_F(SessionObstacles, ObstaclesDrawnInTheExactModeAreHitAndUndoneWhileItRuns) {
    Session s = session();
    s.apply(cmd::SetMode{StepMode::Exact});
    ASSERT_EQ(s.world().solver().mode, StepMode::Exact);
    s.apply(cmd::TogglePause{});
    s.update(0.1, 0.1);
    s.apply(cmd::SetTool{cmd::Tool::Wall});
    drag(s, Vec2(0.5, 6.7), Vec2(6.5, 6.7), 1.0);  // under the particle, which falls on it
    ASSERT_EQ(s.world().obstacles().size(), 1u);
    s.apply(cmd::SetGravity{true, 9.81});
    for (int k = 0; k < 60; ++k)
        s.update(1.0 / 60.0, 1.2 + k / 60.0);
    const Particle p = s.world().get(s.world().ids().front());
    EXPECT_LT(p.position.y(), 6.7 - 0.2);  // resting on the wall (or bounced), not through it
    s.apply(cmd::Undo{});                  // gravity
    s.apply(cmd::Undo{});                  // the wall
    EXPECT_TRUE(s.world().obstacles().empty());
    s.update(1.0 / 60.0, 3.0);
    EXPECT_EQ(s.world().solver().mode, StepMode::Exact);
}

TEST_F(SessionObstacles, TheKeysToggleTheTools) {
    Session s = session();
    s.apply(cmd::SetTool{cmd::Tool::Wall, true});
    EXPECT_EQ(s.tool(), cmd::Tool::Wall);
    s.apply(cmd::SetTool{cmd::Tool::Peg, true});
    EXPECT_EQ(s.tool(), cmd::Tool::Peg);
    s.apply(cmd::SetTool{cmd::Tool::Peg, true});
    EXPECT_EQ(s.tool(), cmd::Tool::Fling);
}

TEST_F(SessionObstacles, SavedScenesKeepTheObstaclesDrawn) {
    Session s = session();
    s.apply(cmd::SetTool{cmd::Tool::Peg});
    click(s, Vec2(2.0, 2.0));
    s.apply(cmd::SetTool{cmd::Tool::Wall});
    drag(s, Vec2(1.0, 5.0), Vec2(5.0, 4.0));
    const fs::path file = dir_ / "obstacles.json";
    s.apply(cmd::SaveAs{file});
    ASSERT_TRUE(fs::exists(file));
    const Scene scene = loadScene(file);
    EXPECT_EQ(scene.world.obstacles, s.world().obstacles());
    EXPECT_FALSE(s.unsavedChanges());
}

}  // namespace
}  // namespace psb::app
