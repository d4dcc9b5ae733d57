// World's checks on obstacles: each bad obstacle is refused with a message that names it and
// what is wrong, and the world is left unchanged.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <particle_sandbox/error.hpp>
#include <particle_sandbox/world.hpp>

namespace psb {
namespace {

std::string refusal(const Obstacle& o) {
    World w(WorldDef{.width = 10.0, .height = 10.0});
    w.addObstacle(Obstacle::peg(Vec2(1.0, 1.0), 0.5));
    try {
        w.addObstacle(o);
    } catch (const InvalidArgument& e) {
        EXPECT_EQ(w.obstacles().size(), 1u) << "a refused obstacle changed the world";
        return e.what();
    }
    return "accepted";
}

TEST(ObstacleValidate, RefusesEachBadObstacleWithAClearMessage) {
    EXPECT_EQ(refusal(Obstacle::segment(Vec2(2.0, 3.0), Vec2(2.0, 3.0), 0.1)),
              "World::addObstacle: obstacle 1 (segment) has zero length: both ends are at [2, 3] "
              "(use a peg)");
    EXPECT_EQ(refusal(Obstacle::peg(Vec2(NAN, 3.0), 0.5)),
              "World::addObstacle: obstacle 1 (peg) centre must be finite (got [nan, 3])");
    EXPECT_EQ(refusal(Obstacle::segment(Vec2(1.0, 1.0), Vec2(INFINITY, 3.0), 0.1)),
              "World::addObstacle: obstacle 1 (segment) second end must be finite (got [inf, 3])");
    EXPECT_EQ(refusal(Obstacle::peg(Vec2(3.0, 3.0), 0.0)),
              "World::addObstacle: obstacle 1 (peg) radius must be finite and > 0 (got 0)");
    EXPECT_EQ(refusal(Obstacle::segment(Vec2(1.0, 1.0), Vec2(2.0, 3.0), -0.2)),
              "World::addObstacle: obstacle 1 (segment) thickness must be finite and > 0 (got "
              "-0.2)");
    EXPECT_EQ(refusal(Obstacle::peg(Vec2(12.0, 3.0), 0.5)),
              "World::addObstacle: obstacle 1 (peg) cannot be drawn in the 10 x 10 m box: its "
              "centre [12, 3] lies outside it");
    EXPECT_EQ(refusal(Obstacle::segment(Vec2(1.0, 1.0), Vec2(5.0, -1.0), 0.1)),
              "World::addObstacle: obstacle 1 (segment) cannot be drawn in the 10 x 10 m box: its "
              "end [5, -1] lies outside it");
    Obstacle bent = Obstacle::peg(Vec2(3.0, 3.0), 0.5);
    bent.b = Vec2(4.0, 3.0);
    EXPECT_EQ(refusal(bent),
              "World::addObstacle: obstacle 1 (peg) second point must equal its centre [3, 3] "
              "(got [4, 3])");
    // Larger than the box: it would only cover all of it (and make the obstacle grids huge).
    EXPECT_EQ(refusal(Obstacle::peg(Vec2(3.0, 3.0), 10.5)),
              "World::addObstacle: obstacle 1 (peg) radius must be at most the box's larger "
              "side, 10 m (got 10.5)");
    EXPECT_EQ(refusal(Obstacle::segment(Vec2(1.0, 1.0), Vec2(2.0, 3.0), 2e5)),
              "World::addObstacle: obstacle 1 (segment) thickness must be at most twice the "
              "box's larger side, 20 m (got 200000)");
    EXPECT_EQ(refusal(Obstacle::peg(Vec2(3.0, 3.0), 10.0)), "accepted");
    // On the box's edge is inside: a wall may run along it.
    EXPECT_EQ(refusal(Obstacle::segment(Vec2(0.0, 10.0), Vec2(10.0, 10.0), 0.1)), "accepted");
}

TEST(ObstacleValidate, SetObstaclesNamesTheFirstBadOneAndChangesNothing) {
    World w(WorldDef{.width = 10.0, .height = 10.0});
    w.setObstacles({Obstacle::peg(Vec2(5.0, 5.0), 1.0)});
    try {
        w.setObstacles({Obstacle::peg(Vec2(1.0, 1.0), 1.0),
                        Obstacle::segment(Vec2(1.0, 1.0), Vec2(1.0, 1.0), 1.0)});
        FAIL() << "accepted";
    } catch (const InvalidArgument& e) {
        EXPECT_NE(std::string(e.what()).find("obstacle 1 (segment) has zero length"),
                  std::string::npos)
            << e.what();
    }
    ASSERT_EQ(w.obstacles().size(), 1u);
    EXPECT_EQ(w.obstacles()[0], Obstacle::peg(Vec2(5.0, 5.0), 1.0));
}

TEST(ObstacleValidate, BoxThatWouldLeaveAnObstacleOutsideIsRefused) {
    World w(WorldDef{.width = 10.0, .height = 10.0});
    w.addObstacle(Obstacle::segment(Vec2(1.0, 1.0), Vec2(9.0, 9.0), 0.2));
    EXPECT_THROW(w.setBox(8.0, 10.0), InvalidArgument);
    EXPECT_EQ(w.def().width, 10.0);
    w.setBox(9.0, 9.0);  // the end on the edge is still inside
    EXPECT_EQ(w.def().width, 9.0);
}

TEST(ObstacleValidate, ExactModeAcceptsObstaclesEitherWay) {
    World w(WorldDef{.width = 10.0, .height = 10.0});
    w.addObstacle(Obstacle::peg(Vec2(5.0, 5.0), 1.0));
    EXPECT_NO_THROW(w.setSolver({.mode = StepMode::Exact}));
    EXPECT_EQ(w.solver().mode, StepMode::Exact);

    World exact(WorldDef{.width = 10.0, .height = 10.0}, {.mode = StepMode::Exact});
    EXPECT_NO_THROW(exact.addObstacle(Obstacle::peg(Vec2(5.0, 5.0), 1.0)));
    EXPECT_EQ(exact.obstacles().size(), 1u);
    WorldDef def{.width = 10.0, .height = 10.0};
    def.obstacles = {Obstacle::peg(Vec2(5.0, 5.0), 1.0)};
    EXPECT_NO_THROW(World(def, {.mode = StepMode::Exact}));
}

TEST(ObstacleValidate, RemoveObstacleKeepsTheOrderAndRefusesABadIndex) {
    World w(WorldDef{.width = 10.0, .height = 10.0});
    for (double x : {1.0, 2.0, 3.0})
        w.addObstacle(Obstacle::peg(Vec2(x, 5.0), 0.2));
    w.removeObstacle(0);
    ASSERT_EQ(w.obstacles().size(), 2u);
    EXPECT_EQ(w.obstacles()[0].a.x(), 2.0);
    EXPECT_EQ(w.obstacles()[1].a.x(), 3.0);
    try {
        w.removeObstacle(2);
        FAIL() << "accepted";
    } catch (const InvalidArgument& e) {
        EXPECT_EQ(std::string(e.what()),
                  "World::removeObstacle: index names no obstacle (got 2, the world has 2)");
    }
}

}  // namespace
}  // namespace psb
