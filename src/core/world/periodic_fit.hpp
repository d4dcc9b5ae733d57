#pragma once
// What a periodic box requires of what is in it, checked by World wherever it could change (the
// box, the particles' radii, the obstacles, the droppers' balls). Each check throws
// psb::InvalidArgument naming the function, the field and the numbers.
//
//   - Every particle fits twice across the box: its diameter is at most half the width and half
//     the height. Two touching discs are then at most half a side apart, so the nearest image is
//     the only one that can touch (support/periodic_box.hpp).
//   - Every obstacle stays a largest particle's diameter inside every edge. Obstacles do not
//     act across the edges (they have no images): kept that far in, no particle can reach one
//     across an edge, so none is missed.

#include <particle_sandbox/obstacle.hpp>

namespace psb::detail {

/// A particle (or dropper ball) of radius `radius` in a periodic box of width × height metres;
/// `what` names it in the message ("radius", "dropper 0 radius").
void requireFitsPeriodic(double radius, double width, double height, const char* where,
                         const char* what);
/// Every obstacle, for particles up to `largestRadius` metres, in a periodic box of width ×
/// height metres.
void requireObstaclesClearOfEdges(const Obstacles& obstacles, double largestRadius, double width,
                                  double height, const char* where);

}  // namespace psb::detail
