// The exact step's events with fixed obstacles (pegs and segments): prediction, rebound and the
// support a resting particle finds on them. The design note is in exact_stepper.hpp
// ("Obstacles"); the times of impact are exact_obstacle_impact.hpp's.

#include <cmath>

#include "contact.hpp"
#include "exact_obstacle_impact.hpp"
#include "exact_stepper.hpp"
#include "obstacle_geometry.hpp"

namespace psb::exact {

void ExactStepper::predictObstacles(std::uint32_t i, const Motion& m, double now, Event& best) {
    const Body& a = bodies_[i];
    // Held particles pass through obstacles (their owner moves them, as in the discrete mode);
    // sleepers do not move.
    if (a.flags & (kHeld | kAsleep)) return;
    const Cold& c = cold_[i];
    for (const std::uint32_t k : obstacles_.near(cells_, c.kx, c.ky)) {
        const double t = now + obstacleEventTime(m.x, m.y, m.vx, m.vy, m.ax, m.ay, a.r,
                                                 obstacles_[k], best.time - now);
        if (t < best.time) best = {t, k, 0, Kind::Obstacle, 0};
    }
}

void ExactStepper::handleObstacle(std::uint32_t i, const Event& ev, StepCounters& counters) {
    Body& a = bodies_[i];
    const bool recent = collidedWithin(a, ev.time);
    advance(a, ev.time);
    ++stats_.obstacles;
    const Obstacle& o = obstacles_[ev.partner];
    // The outward normal: from the nearest point of the core to the centre.
    double qx, qy;
    nearestCorePoint(o, a.x, a.y, qx, qy);
    double nx = a.x - qx, ny = a.y - qy;
    const double d = std::sqrt(nx * nx + ny * ny);
    if (d > 0.0 && std::isfinite(nx / d) && std::isfinite(ny / d)) {
        nx /= d;
        ny /= d;
    } else {
        // On the core itself (placed so): out against its motion.
        const double v = std::hypot(a.vx, a.vy);
        nx = v > 0.0 ? -a.vx / v : 0.0;
        ny = v > 0.0 ? -a.vy / v : -1.0;
    }
    const double into = -(a.vx * nx + a.vy * ny);
    const double e = effectiveRestitution(into, recent);
    double dv = def_.friction > 0.0 ? reboundOffSurface<true>(a.vx, a.vy, nx, ny, e, def_.friction)
                                    : reboundOffSurface<false>(a.vx, a.vy, nx, ny, e, 0.0);
    if (gravity_) {
        // Pressed into the obstacle by gravity and leaving it slower than the lift: leave at the
        // lift, as a pressed pair does (see the design note), so that a particle on a slope
        // hops down it instead of making ever faster tiny bounces, and the next impact is never
        // at the same instant.
        double gax, gay;
        accelerationOf(a, gax, gay);
        const double an = gax * nx + gay * ny;
        if (an < 0.0 && an * an > kPressTolerance * kPressTolerance * (gax * gax + gay * gay)) {
            const double lift = 0.5 * restSpeed_, leaving = a.vx * nx + a.vy * ny;
            if (leaving < lift) {
                a.vx += (lift - leaving) * nx;
                a.vy += (lift - leaving) * ny;
                dv += lift - leaving;
            }
        }
    }
    if (dv > 0.0) {
        ++counters.obstacleCollisions;
        if (log_) log_->push_back({ev.time, order_[i], CollisionRecord::kObstacle + ev.partner});
    }
    ++a.count;
    // Off the wall it rested on if the obstacle pushed it off; asleep if it is slow and held.
    if (gravity_) settleAfterPair(i, false);
    predictCollision(i, ev.time);
    predictCell(i, ev.time);
}

int ExactStepper::obstacleSupports(std::uint32_t i, double* nx, double* ny, double* cone, int count,
                                   int max) const {
    const Body& a = bodies_[i];
    const Cold& c = cold_[i];
    // One obstacle holds a particle only within the friction angle (see supported()).
    const double slack = std::atan(def_.friction) + 1e-9;
    for (const std::uint32_t k : obstacles_.near(cells_, c.kx, c.ky)) {
        if (count == max) break;
        const Obstacle& o = obstacles_[k];
        double qx, qy;
        nearestCorePoint(o, a.x, a.y, qx, qy);
        const double rx = qx - a.x, ry = qy - a.y;  // from i to the obstacle
        const double d = std::sqrt(rx * rx + ry * ry);
        if (!(d > 0.0) || d - (a.r + o.radius) > restGap_) continue;
        nx[count] = rx / d;
        ny[count] = ry / d;
        cone[count++] = slack;
    }
    return count;
}

}  // namespace psb::exact
