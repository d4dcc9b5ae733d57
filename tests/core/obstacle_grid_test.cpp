// The obstacles' broadphase: every obstacle a disc can touch is a candidate, candidates come
// ascending and once, and a long diagonal wall costs cells along its length only.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "obstacle_geometry.hpp"
#include "obstacle_grid.hpp"

namespace psb {
namespace {

double coreDistance(const Obstacle& o, double x, double y) {
    double qx, qy;
    nearestCorePoint(o, x, y, qx, qy);
    return std::hypot(x - qx, y - qy);
}

TEST(ObstacleGrid, ListsEveryObstacleADiscTouchesAscendingAndOnce) {
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> pos(0.0, 100.0), small(0.1, 2.0), len(-20.0, 20.0);
    Obstacles obstacles;
    for (int k = 0; k < 300; ++k) {
        const Vec2 a(pos(rng), pos(rng));
        if (k % 2 == 0) {
            obstacles.push_back(Obstacle::peg(a, small(rng)));
        } else {
            obstacles.push_back(Obstacle::segment(a, a + Vec2(len(rng), len(rng)), small(rng)));
        }
    }
    ObstacleGrid grid;
    grid.build(obstacles);
    EXPECT_TRUE(grid.builtFor(obstacles));
    std::vector<std::uint32_t> out;
    int touching = 0;
    for (int q = 0; q < 5000; ++q) {
        const double x = pos(rng) * 1.2 - 10.0, y = pos(rng) * 1.2 - 10.0, r = small(rng);
        grid.query(x - r, y - r, x + r, y + r, out);
        EXPECT_TRUE(std::is_sorted(out.begin(), out.end()));
        EXPECT_EQ(std::adjacent_find(out.begin(), out.end()), out.end());
        for (std::size_t k = 0; k < obstacles.size(); ++k) {
            if (coreDistance(obstacles[k], x, y) <= r + obstacles[k].radius) {
                ++touching;
                EXPECT_TRUE(std::binary_search(out.begin(), out.end(), k))
                    << "obstacle " << k << " missed at " << x << ", " << y;
            }
        }
    }
    EXPECT_GT(touching, 500);
}

TEST(ObstacleGrid, BoxOutsideTheGridHasNoCandidates) {
    ObstacleGrid grid;
    grid.build({Obstacle::peg(Vec2(5.0, 5.0), 1.0)});
    std::vector<std::uint32_t> out{7};
    grid.query(20.0, 20.0, 21.0, 21.0, out);
    EXPECT_TRUE(out.empty());
    grid.query(NAN, 0.0, NAN, 1.0, out);
    EXPECT_TRUE(out.empty());
    grid.query(4.0, 4.0, 6.0, 6.0, out);
    EXPECT_EQ(out, std::vector<std::uint32_t>{0});
}

TEST(ObstacleGrid, DiagonalWallUsesCellsAlongItsLength) {
    // One thin wall across a 1000 m square among 999 pegs: its bounding box holds about all
    // 4000 cells, the cells it comes near only about a row's worth.
    Obstacles obstacles{Obstacle::segment(Vec2(0.0, 0.0), Vec2(1000.0, 1000.0), 0.1)};
    std::mt19937_64 rng(9);
    std::uniform_real_distribution<double> pos(0.0, 1000.0);
    for (int k = 0; k < 999; ++k)
        obstacles.push_back(Obstacle::peg(Vec2(pos(rng), pos(rng)), 0.5));
    ObstacleGrid grid;
    grid.build(obstacles);
    const double perSide = std::sqrt(static_cast<double>(grid.cellCount()));
    // Pegs take one to four cells each; the wall a band about three cells wide.
    EXPECT_LT(static_cast<double>(grid.entryCount()), 4.0 * 999 + 4.0 * perSide);
    EXPECT_GT(grid.cellCount(), 3000u);
}

TEST(ObstacleGrid, RebuildsForAChangedList) {
    ObstacleGrid grid;
    Obstacles obstacles{Obstacle::peg(Vec2(5.0, 5.0), 1.0)};
    grid.build(obstacles);
    obstacles.push_back(Obstacle::peg(Vec2(8.0, 5.0), 1.0));
    EXPECT_FALSE(grid.builtFor(obstacles));
    grid.build(obstacles);
    std::vector<std::uint32_t> out;
    grid.query(7.5, 4.5, 8.5, 5.5, out);
    EXPECT_EQ(out, std::vector<std::uint32_t>{1});
}

}  // namespace
}  // namespace psb
