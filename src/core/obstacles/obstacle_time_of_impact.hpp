#pragma once
// Times of impact of a disc moving in a straight line with a fixed obstacle (obstacle.hpp):
// a peg, and a segment's two parts, its flat sides and its rounded end caps.
//
// Without gravity the centre moves as p + t·v, so each contact condition is a quadratic (a
// cap or a peg: |p + t·v − c| = r + R) or linear (a flat side: signed distance to the core
// line = ±(r + h)) equation in t. Each function answers "how long from now", a duration >= 0,
// or kNever, with the conventions of exact/time_of_impact.hpp: a disc that overlaps the
// obstacle and approaches it hits it now (0); one that overlaps and moves away is left alone.
// The discrete mode calls them with v = the step's displacement, so that the answer is the
// fraction of the step before contact (its sweep, discrete_obstacles.cpp).

#include <algorithm>
#include <cmath>

#include <particle_sandbox/obstacle.hpp>

#include "exact/time_of_impact.hpp"

namespace psb::exact {

/// Time until a disc of radius r at (px, py) moving at (vx, vy) touches the fixed disc of
/// radius R at (cx, cy): the smaller root of |p + t·v − c| = r + R (pairImpactTime with the
/// peg as the second, resting body).
[[nodiscard]] inline double pegImpactTime(double px, double py, double vx, double vy, double r,
                                          double cx, double cy, double R) {
    return pairImpactTime(cx - px, cy - py, -vx, -vy, r + R);
}

/// Time until the disc (radius r, centre p, velocity v) touches a flat side of the segment from
/// a to b of half-thickness h: the contact whose nearest core point lies strictly between the
/// endpoints. Contacts at or beyond an endpoint belong to that end's cap (capImpactTime).
[[nodiscard]] inline double segmentSideImpactTime(double px, double py, double vx, double vy,
                                                  double r, double ax, double ay, double bx,
                                                  double by, double h) {
    const double ex = bx - ax, ey = by - ay;
    const double length = std::sqrt(ex * ex + ey * ey);
    if (!(length > 0.0)) return kNever;
    const double ux = ex / length, uy = ey / length;  // along the segment
    // Signed distance of the centre from the core line (its normal is (−uy, ux)) and its rate.
    const double s = (px - ax) * -uy + (py - ay) * ux;
    const double vs = vx * -uy + vy * ux;
    const double sigma = r + h;
    const double side = s >= 0.0 ? 1.0 : -1.0;
    const double approach = -side * vs;  // > 0 when the centre moves toward the line
    if (!(approach > 0.0)) return kNever;
    const double gap = side * s - sigma;
    const double t = gap <= 0.0 ? 0.0 : gap / approach;
    // Where along the segment the contact happens.
    const double along = (px + t * vx - ax) * ux + (py + t * vy - ay) * uy;
    return (along > 0.0 && along < length) ? t : kNever;
}

/// Time until the disc touches the rounded end of a segment at (cx, cy), half-thickness h: a
/// peg of radius h at the endpoint.
[[nodiscard]] inline double capImpactTime(double px, double py, double vx, double vy, double r,
                                          double cx, double cy, double h) {
    return pegImpactTime(px, py, vx, vy, r, cx, cy, h);
}

/// Time until the disc touches the segment: the earliest of its two sides and two caps. A
/// segment is the union of those parts, so its first contact is the first contact with any.
[[nodiscard]] inline double segmentImpactTime(double px, double py, double vx, double vy, double r,
                                              double ax, double ay, double bx, double by,
                                              double h) {
    return std::min({segmentSideImpactTime(px, py, vx, vy, r, ax, ay, bx, by, h),
                     capImpactTime(px, py, vx, vy, r, ax, ay, h),
                     capImpactTime(px, py, vx, vy, r, bx, by, h)});
}

/// Time until the disc touches the obstacle, whichever kind it is.
[[nodiscard]] inline double obstacleImpactTime(double px, double py, double vx, double vy, double r,
                                               const Obstacle& o) {
    if (o.isPeg()) return pegImpactTime(px, py, vx, vy, r, o.a.x(), o.a.y(), o.radius);
    return segmentImpactTime(px, py, vx, vy, r, o.a.x(), o.a.y(), o.b.x(), o.b.y(), o.radius);
}

}  // namespace psb::exact
