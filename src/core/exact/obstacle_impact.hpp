#pragma once
// Times of impact of a disc with a fixed obstacle (obstacle.hpp) under a constant acceleration
// (gravity), for the exact mode: the accelerated counterparts of obstacle_time_of_impact.hpp.
//
// The centre moves as p + v·t + ½·a·t². Against a fixed disc (a peg, or a segment's end cap)
// the squared distance is a quartic in t: parabolic_impact.hpp's first-root search
// (bracketed, safeguarded Newton; no closed formula). Against a segment's flat side only the
// distance across the core line matters, s(t) = s₀ + v_s·t + ½·a_s·t², a quadratic: its
// first crossing of r + h towards the line is crossingTime's (the one-sign root forms, the apex
// handled there), and the contact counts only if it lands strictly between the endpoints
// (beyond them the cap is met first, see segmentSideImpactTimeAccelerated). Without an
// acceleration each function is exactly the straight-line one of obstacle_time_of_impact.hpp.
//
// Conventions of time_of_impact.hpp and parabolic_impact.hpp: durations >= 0 or
// kNever; a disc that overlaps the obstacle and approaches it hits it now (0); one that
// overlaps and moves away is left alone unless the acceleration turns it back; the quartic
// searches only [0, horizon] (pass kNever for no bound).

#include <algorithm>
#include <cmath>

#include <particle_sandbox/obstacle.hpp>

#include "exact/parabolic_impact.hpp"
#include "obstacles/obstacle_geometry.hpp"
#include "obstacles/obstacle_time_of_impact.hpp"

namespace psb::exact {

/// Time until a disc of radius r at p moving at v with acceleration a touches the fixed disc of
/// radius R at c, searched in [0, horizon].
[[nodiscard]] inline double pegImpactTimeAccelerated(double px, double py, double vx, double vy,
                                                     double ax, double ay, double r, double cx,
                                                     double cy, double R, double horizon) {
    if (ax == 0.0 && ay == 0.0) return pegImpactTime(px, py, vx, vy, r, cx, cy, R);
    return parabolicPairImpactTime(px - cx, py - cy, vx, vy, ax, ay, r + R, horizon);
}

/// Time until the disc touches a flat side of the segment from a to b of half-thickness h, at a
/// point strictly between the endpoints. The disc can only meet the side it is on: reaching the
/// other one means crossing the core line, and so the near side first.
///
/// The first crossing of the side's offset line is the only candidate: after it the centre is
/// within r + h of the core line, and it leaves that band only through the same line again.
/// If that crossing lands beyond an end, the centre is then within r + h of the core line but
/// past the end; moving back between the endpoints inside the band it would pass within r + h
/// of the endpoint first, so the cap sees that contact earlier.
[[nodiscard]] inline double segmentSideImpactTimeAccelerated(double px, double py, double vx,
                                                             double vy, double ax, double ay,
                                                             double r, double sax, double say,
                                                             double sbx, double sby, double h) {
    if (ax == 0.0 && ay == 0.0)
        return segmentSideImpactTime(px, py, vx, vy, r, sax, say, sbx, sby, h);
    const double ex = sbx - sax, ey = sby - say;
    const double length = std::sqrt(ex * ex + ey * ey);
    if (!(length > 0.0)) return kNever;
    const double ux = ex / length, uy = ey / length;  // along the segment
    // Distance from the core line on the centre's side, its rate and its acceleration.
    const double s = (px - sax) * -uy + (py - say) * ux;
    const double side = s >= 0.0 ? 1.0 : -1.0;
    const double d = side * s;
    const double vd = side * (vx * -uy + vy * ux);
    const double ad = side * (ax * -uy + ay * ux);
    // Towards the line is "outward" for crossingTime: the limit is r + h, reached going down.
    const double t = crossingTime(d, vd, ad, r + h, -1.0);
    if (!(t < kNever)) return kNever;
    const double along =
        (px - sax + t * (vx + 0.5 * ax * t)) * ux + (py - say + t * (vy + 0.5 * ay * t)) * uy;
    return (along > 0.0 && along < length) ? t : kNever;
}

/// Relative slack of the end-cap rule below (segmentCapContactTime): far above the rounding of
/// a coordinate, far below any disc's size.
inline constexpr double kCapSlack = 1e-9;

/// The time t of a disc's contact with the end cap of a segment at (cx, cy), or kNever if that
/// contact is not the segment's: a cap's contact counts only with the centre then at or beyond
/// its end ((centre − c)·(ox, oy) >= 0 within rounding, (ox, oy) the unit vector out of the
/// segment at that end), where the end is the nearest core point and the rebound's normal
/// (the exact stepper's, from the nearest core point) is the cap's. A "contact" with the
/// centre between the endpoints lies inside the band of the flat sides: from a state outside
/// the segment the side is met first (segmentSideImpactTimeAccelerated), and a disc that
/// already overlaps the side is the side rule's to judge. Counted anyway, such a contact
/// would be an event whose rebound along the side's normal changes nothing, predicted again
/// at the same instant, forever.
[[nodiscard]] inline double segmentCapContactTime(double t, double px, double py, double vx,
                                                  double vy, double ax, double ay, double r,
                                                  double cx, double cy, double h, double ox,
                                                  double oy) {
    if (!(t < kNever)) return kNever;
    const double beyond =
        (px + t * (vx + 0.5 * ax * t) - cx) * ox + (py + t * (vy + 0.5 * ay * t) - cy) * oy;
    const double slack = kCapSlack * (r + h + std::abs(cx) + std::abs(cy));
    return beyond >= -slack ? t : kNever;
}

/// Time until the disc touches the segment (its two sides and its two caps), searched in
/// [0, horizon] for the caps.
[[nodiscard]] inline double segmentImpactTimeAccelerated(double px, double py, double vx, double vy,
                                                         double ax, double ay, double r, double sax,
                                                         double say, double sbx, double sby,
                                                         double h, double horizon) {
    const double side =
        segmentSideImpactTimeAccelerated(px, py, vx, vy, ax, ay, r, sax, say, sbx, sby, h);
    const double ex = sbx - sax, ey = sby - say;
    const double length = std::sqrt(ex * ex + ey * ey);
    const double ux = length > 0.0 ? ex / length : 0.0, uy = length > 0.0 ? ey / length : 0.0;
    const double capA = segmentCapContactTime(
        pegImpactTimeAccelerated(px, py, vx, vy, ax, ay, r, sax, say, h, std::min(horizon, side)),
        px, py, vx, vy, ax, ay, r, sax, say, h, -ux, -uy);
    const double capB =
        segmentCapContactTime(pegImpactTimeAccelerated(px, py, vx, vy, ax, ay, r, sbx, sby, h,
                                                       std::min({horizon, side, capA})),
                              px, py, vx, vy, ax, ay, r, sbx, sby, h, ux, uy);
    return std::min({side, capA, capB});
}

/// Time until the disc touches the obstacle, whichever kind it is, searched in [0, horizon].
[[nodiscard]] inline double obstacleImpactTimeAccelerated(double px, double py, double vx,
                                                          double vy, double ax, double ay, double r,
                                                          const Obstacle& o, double horizon) {
    if (o.isPeg()) {
        return pegImpactTimeAccelerated(px, py, vx, vy, ax, ay, r, o.a.x(), o.a.y(), o.radius,
                                        horizon);
    }
    return segmentImpactTimeAccelerated(px, py, vx, vy, ax, ay, r, o.a.x(), o.a.y(), o.b.x(),
                                        o.b.y(), o.radius, horizon);
}

/// The exact mode's event time of a disc with an obstacle: obstacleImpactTimeAccelerated, except
/// that a disc touching it now that neither clearly approaches it (its speed towards the core
/// above kApproachTolerance of its speed) nor is pressed into it by the acceleration (above
/// kPressTolerance of it) is left alone. A rebound leaves the disc touching, with a normal
/// speed that is zero up to rounding when e = 0 or the contact is sliding; without the
/// tolerance its sign would decide whether the disc collides again at the same instant,
/// forever (pairImpactTime has the same guard).
[[nodiscard]] inline double obstacleEventTime(double px, double py, double vx, double vy, double ax,
                                              double ay, double r, const Obstacle& o,
                                              double horizon) {
    const double t = obstacleImpactTimeAccelerated(px, py, vx, vy, ax, ay, r, o, horizon);
    if (t != 0.0) return t;
    double qx, qy;
    nearestCorePoint(o, px, py, qx, qy);
    const double nx = qx - px, ny = qy - py, n2 = nx * nx + ny * ny;  // towards the core
    const double un = vx * nx + vy * ny, an = ax * nx + ay * ny;
    const bool approaching =
        un > 0.0 && un * un > kApproachTolerance * kApproachTolerance * n2 * (vx * vx + vy * vy);
    const bool pressed =
        an > 0.0 && an * an > kPressTolerance * kPressTolerance * n2 * (ax * ax + ay * ay);
    return approaching || pressed ? 0.0 : kNever;
}

}  // namespace psb::exact
