#pragma once
// Where a point is relative to a fixed obstacle's core (obstacle.hpp): its nearest core point,
// and whether a straight move of a particle's centre crosses a segment's core line.

#include <algorithm>

#include <particle_sandbox/obstacle.hpp>

namespace psb {

/// The point of the obstacle's core (a peg's centre, or the segment from a to b) nearest to
/// (x, y), written to (qx, qy).
inline void nearestCorePoint(const Obstacle& o, double x, double y, double& qx, double& qy) {
    const double ax = o.a.x(), ay = o.a.y();
    const double ex = o.b.x() - ax, ey = o.b.y() - ay;
    const double len2 = ex * ex + ey * ey;
    const double t =
        len2 > 0.0 ? std::clamp(((x - ax) * ex + (y - ay) * ey) / len2, 0.0, 1.0) : 0.0;
    qx = ax + t * ex;
    qy = ay + t * ey;
}

/// Which side of a segment's core line (x, y) is on: > 0 left of a→b, < 0 right, 0 on it
/// (twice the signed area of the triangle a, b, (x, y)).
[[nodiscard]] inline double sideOf(const Obstacle& o, double x, double y) {
    return (o.b.x() - o.a.x()) * (y - o.a.y()) - (o.b.y() - o.a.y()) * (x - o.a.x());
}

/// Whether the move from (x0, y0) to (x1, y1) passes through a segment's core: it ends strictly
/// on the other side of the core line, and it meets the line between the endpoints. Always
/// false for a peg, whose core is a single point.
[[nodiscard]] inline bool crossesCore(const Obstacle& o, double x0, double y0, double x1,
                                      double y1) {
    if (o.isPeg()) return false;
    const double s0 = sideOf(o, x0, y0), s1 = sideOf(o, x1, y1);
    if (!((s0 > 0.0 && s1 < 0.0) || (s0 < 0.0 && s1 > 0.0))) return false;
    // The endpoints must lie on either side of the move's line (or on it).
    const double mx = x1 - x0, my = y1 - y0;
    const double ea = mx * (o.a.y() - y0) - my * (o.a.x() - x0);
    const double eb = mx * (o.b.y() - y0) - my * (o.b.x() - x0);
    return !((ea > 0.0 && eb > 0.0) || (ea < 0.0 && eb < 0.0));
}

}  // namespace psb
