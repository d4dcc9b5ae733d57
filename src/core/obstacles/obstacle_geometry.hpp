#pragma once
// Where a point is relative to a fixed obstacle's core (obstacle.hpp): its nearest core point,
// whether a straight move of a particle's centre crosses a segment's core line, and how far a
// core is from a rectangle (a grid cell).

#include <algorithm>
#include <cmath>

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

/// Distance from a point to the rectangle [x0, x1] × [y0, y1] (0 inside).
[[nodiscard]] inline double pointToRectangle(double x, double y, double x0, double y0, double x1,
                                             double y1) {
    const double dx = std::max({x0 - x, 0.0, x - x1}), dy = std::max({y0 - y, 0.0, y - y1});
    return std::sqrt(dx * dx + dy * dy);
}

/// Distance from an obstacle's core (a point or a segment) to a rectangle: 0 when they meet;
/// otherwise the nearest pair involves an end of the segment or a corner of the rectangle.
[[nodiscard]] inline double coreToRectangle(const Obstacle& o, double x0, double y0, double x1,
                                            double y1) {
    double d = std::min(pointToRectangle(o.a.x(), o.a.y(), x0, y0, x1, y1),
                        pointToRectangle(o.b.x(), o.b.y(), x0, y0, x1, y1));
    if (o.isPeg() || d == 0.0) return d;
    const double cx[4] = {x0, x1, x1, x0}, cy[4] = {y0, y0, y1, y1};
    for (int k = 0; k < 4; ++k) {
        // The segment crossing an edge of the rectangle means they meet.
        const Obstacle edge =
            Obstacle::segment(Vec2(cx[k], cy[k]), Vec2(cx[(k + 1) % 4], cy[(k + 1) % 4]), 0.0);
        if (crossesCore(edge, o.a.x(), o.a.y(), o.b.x(), o.b.y())) return 0.0;
        double qx, qy;
        nearestCorePoint(o, cx[k], cy[k], qx, qy);
        d = std::min(d, std::hypot(cx[k] - qx, cy[k] - qy));
    }
    return d;
}

}  // namespace psb
