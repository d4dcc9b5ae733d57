#pragma once
// The checks World makes on fixed obstacles. Each throws psb::InvalidArgument naming the
// function, the obstacle (by index and kind) and what is wrong with it.

#include <cstddef>

#include <particle_sandbox/obstacle.hpp>
#include <particle_sandbox/solver_settings.hpp>

namespace psb::detail {

/// One obstacle, the `index`-th of its list, in a box of width × height metres: finite
/// coordinates, a radius (half-thickness) finite, > 0 and at most the box's larger side (a
/// larger one would only cover the whole box, and makes the obstacle grids huge), a segment of
/// non-zero length, a peg with b == a, and a core (centre, or both ends) inside the closed box [0,
/// width] × [0, height], where it can be drawn and reached.
void validateObstacle(const Obstacle& o, std::size_t index, double width, double height,
                      const char* where);
/// Every obstacle of the list, as validateObstacle.
void validateObstacles(const Obstacles& obstacles, double width, double height, const char* where);

}  // namespace psb::detail
