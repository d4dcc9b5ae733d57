// Obstacles in the drawing batch: a peg is one disc, a segment two end discs and a bar.

#include <gtest/gtest.h>

#include "render/obstacle_drawing.hpp"
#include "session/camera.hpp"

namespace psb::app {
namespace {

TEST(ObstacleDrawing, PegsAreDiscsAndSegmentsAreBarsWithRoundEnds) {
    World w(WorldDef{.width = 10.0, .height = 10.0});
    Camera camera;
    camera.setViewport(800, 800);
    camera.set(80.0, Vec2::Zero());
    GeometryBatch batch;
    batchObstacles(w, camera, batch);
    EXPECT_TRUE(batch.empty());
    w.addObstacle(Obstacle::peg(Vec2(5.0, 5.0), 0.5));
    batchObstacles(w, camera, batch);
    EXPECT_EQ(batch.triangleCount(), 2u);  // one textured quad
    w.addObstacle(Obstacle::segment(Vec2(1.0, 1.0), Vec2(9.0, 3.0), 0.1));
    batchObstacles(w, camera, batch);
    EXPECT_EQ(batch.triangleCount(), 2u + 2u + 2u + 2u);  // peg, two end discs, one bar
}

}  // namespace
}  // namespace psb::app
