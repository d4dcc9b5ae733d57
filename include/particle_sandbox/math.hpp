#pragma once
/// \file
/// Vector types shared by the whole library. Units are SI throughout: metres, seconds,
/// kilograms. Coordinates: origin at the box's top-left corner, x to the right, y downward
/// (as on screen), so a gravity of (0, 9.81) m/s² points down.

#include <Eigen/Core>

namespace psb {

/// A 2-D vector of doubles (metres, metres per second, ... depending on use).
using Vec2 = Eigen::Vector2d;

}  // namespace psb
