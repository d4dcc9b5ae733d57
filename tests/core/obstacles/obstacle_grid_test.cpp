// The obstacles' broadphase: every obstacle a disc can touch is a candidate, candidates come
// ascending and once, and a long diagonal wall costs cells along its length only.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "obstacles/obstacle_geometry.hpp"
#include "obstacles/obstacle_grid.hpp"

namespace psb {
namespace {

double coreDistance(const Obstacle& o, double x, double y) {
    double qx, qy;
    nearestCorePoint(o, x, y, qx, qy);
    return std::hypot(x - qx, y - qy);
}

/// `count` obstacles in the square [0, side]², pegs and segments in turn, radii (half
/// thicknesses) in [minRadius, maxRadius], segments reaching up to `reach` along each axis.
Obstacles randomObstacles(std::mt19937_64& rng, int count, double side, double minRadius,
                          double maxRadius, double reach) {
    std::uniform_real_distribution<double> pos(0.0, side), small(minRadius, maxRadius),
        len(-reach, reach);
    Obstacles obstacles;
    for (int k = 0; k < count; ++k) {
        const Vec2 a(pos(rng), pos(rng));
        if (k % 2 == 0) {
            obstacles.push_back(Obstacle::peg(a, small(rng)));
        } else {
            obstacles.push_back(Obstacle::segment(a, a + Vec2(len(rng), len(rng)), small(rng)));
        }
    }
    return obstacles;
}

TEST(ObstacleGrid, AnAbsurdPadOrHugeCoordinatesStillMakeAGridThatAnswersRight) {
    // A pad from particles flung near the largest double once overflowed the grid's extent and
    // turned its cell counts into NaN (undefined behaviour when cast; found by the world
    // mutation fuzzer). The pad is capped where it gains nothing; lookups stay exact.
    const Obstacles pegs = {Obstacle::peg({1.0, 1.0}, 0.1), Obstacle::segment({2, 2}, {3, 2}, 0.1)};
    for (const double pad : {1e300, 1.7e308, double{INFINITY}}) {
        ObstacleGrid grid;
        grid.build(pegs, pad);
        EXPECT_GE(grid.cellCount(), 1u);
        EXPECT_LE(grid.cellCount(), ObstacleGrid::kMaxCells);
        EXPECT_TRUE(std::isfinite(grid.cellSize())) << pad;
        std::vector<std::uint32_t> out;
        grid.query(0.0, 0.0, 4.0, 4.0, out);
        EXPECT_EQ(out, (std::vector<std::uint32_t>{0, 1})) << pad;
        const double clear = grid.clearance(1.0, 2.0);  // a lower bound of the true 0.9
        EXPECT_LE(clear, 0.9 + 1e-12) << pad;
        EXPECT_GT(clear, 0.5) << pad;
    }
    // Obstacles near the largest double: the extent itself overflows.
    const Obstacles far = {Obstacle::peg({1e308, 1e308}, 1e307), Obstacle::peg({-1e308, 0}, 1e307)};
    ObstacleGrid grid;
    grid.build(far, 1.0);
    EXPECT_GE(grid.cellCount(), 1u);
    std::vector<std::uint32_t> out;
    grid.query(-1.7e308, -1.7e308, 1.7e308, 1.7e308, out);
    EXPECT_EQ(out, (std::vector<std::uint32_t>{0, 1}));
}

TEST(ObstacleGrid, ListsEveryObstacleADiscTouchesAscendingAndOnce) {
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> pos(0.0, 100.0), small(0.1, 2.0);
    const Obstacles obstacles = randomObstacles(rng, 300, 100.0, 0.1, 2.0, 20.0);
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

/// The exact distance from (x, y) to the nearest obstacle's surface, by brute force.
double surfaceDistance(const Obstacles& obstacles, double x, double y) {
    double d = INFINITY;
    for (const Obstacle& o : obstacles)
        d = std::min(d, coreDistance(o, x, y) - o.radius);
    return d;
}

TEST(ObstacleGrid, ClearanceNeverExceedsTheDistanceToAnObstacle) {
    // A lower bound everywhere (inside, near and far from the obstacles, outside the grid), and
    // never below the true distance or the pad, whichever is less.
    std::mt19937_64 rng(21);
    std::uniform_real_distribution<double> pos(0.0, 200.0);
    const Obstacles obstacles = randomObstacles(rng, 120, 200.0, 0.05, 1.5, 15.0);
    for (const double pad : {0.0, 0.7, 3.0}) {
        ObstacleGrid grid;
        grid.build(obstacles, pad);
        int far = 0;
        for (int q = 0; q < 20000; ++q) {
            const double x = pos(rng) * 1.4 - 40.0, y = pos(rng) * 1.4 - 40.0;
            const double truth = std::max(0.0, surfaceDistance(obstacles, x, y));
            const double c = grid.clearance(x, y);
            ASSERT_LE(c, truth * (1.0 + 1e-12) + 1e-12) << "at " << x << ", " << y;
            ASSERT_GE(c, std::min(truth, pad) * (1.0 - 1e-12) - 1e-12) << "at " << x << ", " << y;
            far += c > pad + 2.0 * grid.cellSize();
        }
        EXPECT_GT(far, 1000) << "pad " << pad;  // the rings around an empty cell count
    }
    EXPECT_EQ(ObstacleGrid{}.clearance(1.0, 1.0), INFINITY);
    ObstacleGrid grid;
    grid.build(obstacles, 1.0);
    EXPECT_EQ(grid.clearance(NAN, 1.0), 0.0);
    EXPECT_EQ(grid.clearance(1.0, INFINITY), 0.0);
}

TEST(ObstacleGrid, ClearanceFarFromALoneObstacleReachesAcrossManyCells) {
    // Three pegs across a 1000 m square, cells of 2 m: a point 300 m from the nearest has no
    // obstacle within about 300 m, and the clearance knows it without looking at each cell.
    Obstacles obstacles{Obstacle::peg(Vec2(500.0, 500.0), 1.0), Obstacle::peg(Vec2(0.0, 0.0), 1.0),
                        Obstacle::peg(Vec2(1000.0, 1000.0), 1.0)};
    ObstacleGrid grid;
    grid.build(obstacles, 2.0);
    const double truth = surfaceDistance(obstacles, 800.0, 500.0);
    const double c = grid.clearance(800.0, 500.0);
    EXPECT_LE(c, truth);
    // At most 255 cells of 2 m are known empty, less one ring and the pad.
    EXPECT_GT(c, std::min(truth, 254.0 * grid.cellSize()) - 2.0 * grid.cellSize());
}

}  // namespace
}  // namespace psb
