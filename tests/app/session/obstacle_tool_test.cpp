// The obstacle tools' gestures without a session: what a press, drag and release make, what is
// refused and why, and picking an obstacle under the cursor.

#include <gtest/gtest.h>

#include "session/obstacle_tool.hpp"

namespace psb::app {
namespace {

WorldDef box() {
    WorldDef d;
    d.width = 10.0;
    d.height = 8.0;
    return d;
}

const ObstacleSizes kSizes{0.5, 0.2};

TEST(ObstacleTool, AClickWithThePegToolPlacesAPegAtTheRelease) {
    ObstacleTool t;
    t.press(ObstacleTool::Kind::Peg, Vec2(3.0, 4.0));
    EXPECT_TRUE(t.active());
    const ObstaclePlacement p = t.release(Vec2(3.0, 4.0), kSizes, box(), 0.01);
    ASSERT_TRUE(p.obstacle);
    EXPECT_EQ(*p.obstacle, Obstacle::peg(Vec2(3.0, 4.0), 0.5));
    EXPECT_FALSE(t.active());
}

TEST(ObstacleTool, APegOutsideTheBoxIsRefused) {
    ObstacleTool t;
    t.press(ObstacleTool::Kind::Peg, Vec2(-1.0, 4.0));
    const ObstaclePlacement p = t.release(Vec2(-1.0, 4.0), kSizes, box(), 0.01);
    EXPECT_FALSE(p.obstacle);
    EXPECT_NE(p.refusal.find("inside the box"), std::string::npos);
}

TEST(ObstacleTool, ADragWithTheWallToolDrawsAWallFromPressToRelease) {
    ObstacleTool t;
    t.press(ObstacleTool::Kind::Wall, Vec2(1.0, 2.0));
    t.moveTo(Vec2(4.0, 3.0));
    const auto preview = t.preview(kSizes, box());
    ASSERT_TRUE(preview);
    EXPECT_EQ(*preview, Obstacle::segment(Vec2(1.0, 2.0), Vec2(4.0, 3.0), 0.2));
    const ObstaclePlacement p = t.release(Vec2(6.0, 5.0), kSizes, box(), 0.01);
    ASSERT_TRUE(p.obstacle);
    EXPECT_EQ(*p.obstacle, Obstacle::segment(Vec2(1.0, 2.0), Vec2(6.0, 5.0), 0.2));
    EXPECT_DOUBLE_EQ(p.obstacle->thickness(), 0.2);
    EXPECT_FALSE(t.preview(kSizes, box()));
}

TEST(ObstacleTool, AWallDraggedPastTheEdgeEndsOnTheEdge) {
    ObstacleTool t;
    t.press(ObstacleTool::Kind::Wall, Vec2(5.0, 4.0));
    t.moveTo(Vec2(12.0, -3.0));
    EXPECT_EQ(t.preview(kSizes, box())->b, Vec2(10.0, 0.0));  // what is shown is what is made
    const ObstaclePlacement p = t.release(Vec2(12.0, -3.0), kSizes, box(), 0.01);
    ASSERT_TRUE(p.obstacle);
    EXPECT_EQ(p.obstacle->b, Vec2(10.0, 0.0));
}

TEST(ObstacleTool, AWallStartedOutsideTheBoxOrTooShortIsRefused) {
    ObstacleTool t;
    t.press(ObstacleTool::Kind::Wall, Vec2(11.0, 4.0));
    EXPECT_FALSE(t.preview(kSizes, box()));
    ObstaclePlacement p = t.release(Vec2(5.0, 4.0), kSizes, box(), 0.01);
    EXPECT_FALSE(p.obstacle);
    EXPECT_NE(p.refusal.find("start the drag inside the box"), std::string::npos);

    t.press(ObstacleTool::Kind::Wall, Vec2(5.0, 4.0));
    p = t.release(Vec2(5.0, 4.0), kSizes, box(), 0.01);  // a click: zero length
    EXPECT_FALSE(p.obstacle);
    EXPECT_NE(p.refusal.find("drag from one end"), std::string::npos);

    t.press(ObstacleTool::Kind::Wall, Vec2(5.0, 4.0));
    p = t.release(Vec2(5.005, 4.0), kSizes, box(), 0.01);  // shorter than the least length
    EXPECT_FALSE(p.obstacle);
}

TEST(ObstacleTool, AReleaseWithoutAPressMakesNothingAndSaysNothing) {
    ObstacleTool t;
    const ObstaclePlacement p = t.release(Vec2(5.0, 4.0), kSizes, box(), 0.01);
    EXPECT_FALSE(p.obstacle);
    EXPECT_TRUE(p.refusal.empty());
}

TEST(ObstacleTool, AMoveTranslatesTheObstacleByTheDragOrIsRefusedOutsideTheBox) {
    const Obstacle wall = Obstacle::segment(Vec2(1.0, 1.0), Vec2(3.0, 2.0), 0.2);
    ObstacleTool t;
    t.pressOn(4, wall, Vec2(2.0, 1.5));
    EXPECT_EQ(t.kind(), ObstacleTool::Kind::Move);
    EXPECT_EQ(t.movedIndex(), 4u);
    EXPECT_FALSE(t.preview(kSizes, box()));  // not moved yet
    t.moveTo(Vec2(3.0, 3.5));
    ASSERT_TRUE(t.preview(kSizes, box()));
    EXPECT_EQ(t.preview(kSizes, box())->a, Vec2(2.0, 3.0));
    ObstaclePlacement p = t.release(Vec2(3.0, 3.5), kSizes, box(), 0.01);
    ASSERT_TRUE(p.obstacle);
    EXPECT_EQ(*p.obstacle, Obstacle::segment(Vec2(2.0, 3.0), Vec2(4.0, 4.0), 0.2));

    t.pressOn(4, wall, Vec2(2.0, 1.5));
    p = t.release(Vec2(9.5, 1.5), kSizes, box(), 0.01);  // the far end would be at x = 10.5
    EXPECT_FALSE(p.obstacle);
    EXPECT_EQ(p.refusal, "Not moved: the wall would leave the box");

    t.pressOn(4, wall, Vec2(2.0, 1.5));
    p = t.release(Vec2(2.001, 1.5), kSizes, box(), 0.01);  // a click: nothing, nothing said
    EXPECT_FALSE(p.obstacle);
    EXPECT_TRUE(p.refusal.empty());
}

TEST(ObstacleTool, SizesMustBePositiveAndFitTheBox) {
    EXPECT_TRUE(obstacleSizesRefusal(kSizes, box()).empty());
    EXPECT_NE(obstacleSizesRefusal({0.0, 0.2}, box()).find("peg radius"), std::string::npos);
    EXPECT_NE(obstacleSizesRefusal({0.5, -1.0}, box()).find("wall thickness"), std::string::npos);
    EXPECT_NE(obstacleSizesRefusal({4.5, 0.2}, box()).find("at most 4.00 m"), std::string::npos);
    EXPECT_FALSE(obstacleSizesRefusal({std::nan(""), 0.2}, box()).empty());
    const ObstacleSizes scaled = obstacleSizesFor(0.25);
    EXPECT_DOUBLE_EQ(scaled.pegRadius, 0.25);
    EXPECT_DOUBLE_EQ(scaled.wallThickness, 0.25);
}

TEST(ObstacleTool, DistanceIsToTheSurfaceOfThePegOrTheCapsule) {
    const Obstacle peg = Obstacle::peg(Vec2(0.0, 0.0), 1.0);
    EXPECT_DOUBLE_EQ(distanceToObstacle(peg, Vec2(3.0, 4.0)), 4.0);
    EXPECT_DOUBLE_EQ(distanceToObstacle(peg, Vec2(0.0, 0.0)), -1.0);
    const Obstacle wall = Obstacle::segment(Vec2(0.0, 0.0), Vec2(4.0, 0.0), 1.0);
    EXPECT_DOUBLE_EQ(distanceToObstacle(wall, Vec2(2.0, 3.0)), 2.5);   // beside the line
    EXPECT_DOUBLE_EQ(distanceToObstacle(wall, Vec2(7.0, 4.0)), 4.5);   // beyond an end's cap
    EXPECT_DOUBLE_EQ(distanceToObstacle(wall, Vec2(-3.0, 0.0)), 2.5);  // before the first end
}

TEST(ObstacleTool, PickFindsTheNearestObstacleWithinReach) {
    const Obstacles obstacles{Obstacle::peg(Vec2(1.0, 1.0), 0.5),
                              Obstacle::segment(Vec2(0.0, 3.0), Vec2(6.0, 3.0), 0.4),
                              Obstacle::peg(Vec2(2.0, 3.5), 0.5)};
    EXPECT_EQ(pickObstacle(obstacles, Vec2(1.2, 1.1), 0.05), 0u);
    EXPECT_EQ(pickObstacle(obstacles, Vec2(5.0, 3.1), 0.05), 1u);
    EXPECT_EQ(pickObstacle(obstacles, Vec2(2.0, 3.15), 0.05), 2u);  // inside both: the deeper
    EXPECT_FALSE(pickObstacle(obstacles, Vec2(5.0, 6.0), 0.05));
    EXPECT_EQ(pickObstacle(obstacles, Vec2(1.0, 1.55), 0.1), 0u);  // just outside, in reach
    EXPECT_FALSE(pickObstacle({}, Vec2(1.0, 1.0), 1.0));
}

}  // namespace
}  // namespace psb::app
