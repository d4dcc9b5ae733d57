#pragma once
// Records for the unit tests of the exact stepper's parts (grid, placed contacts, jam guard,
// slides, rolls): a particle's Body at time 0 and an obstacle list for a box's cells.

#include <cstdint>

#include <particle_sandbox/obstacle.hpp>

#include "exact/body.hpp"
#include "exact/cell_list.hpp"
#include "exact/obstacle_cells.hpp"
#include "exact/time_of_impact.hpp"

namespace psb::exact {

// A particle at (x, y) with radius r and velocity (vx, vy), at time 0, flags as given.
inline Body bodyAt(double x, double y, double r, double vx = 0.0, double vy = 0.0,
                   std::uint32_t flags = 0) {
    return Body{x, y, vx, vy, 0.0, r, kNever, 0, flags};
}

// `obstacles` listed for a box of width × height in one cell, every one reachable from it.
inline ObstacleCells obstaclesIn(const Obstacles& obstacles, double width, double height) {
    CellList cells;
    cells.reset(0.0, 0.0, width, height, 1, 1, false, 1);
    ObstacleCells o;
    o.build(obstacles, cells, 0.0, 0.0, 1.0);
    return o;
}

}  // namespace psb::exact
