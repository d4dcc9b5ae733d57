// The exact stepper's events with fixed obstacles (pegs and segments): prediction and rebound.
// The times of impact are obstacle_impact.hpp's; a rebound that starts a slide hands over to
// the slides (slides.hpp, stepper_surfaces.cpp).
//
// Obstacles (fixed pegs and segments). A third kind of collision
// event, kept in a particle's collision key like a wall's and replaced like it at every change
// of course. Each fine cell lists the obstacles a particle in it may reach before its next cell
// move (obstacle_cells.hpp); a prediction tests its cell's list, a cell move the new
// cell's. Times of impact: obstacle_impact.hpp (quadratics; under gravity the quartic
// for pegs and caps, a quadratic across a flat side). Rebound: the walls' law along the normal
// from the nearest core point. Under gravity obstacles are supports for resting (resting.hpp), a
// single one only within the friction angle, so a ball slides down a slope steeper than that.

#include <algorithm>
#include <cmath>

#include "contact/collision_capture.hpp"
#include "contact/contact.hpp"
#include "exact/motion.hpp"
#include "exact/obstacle_impact.hpp"
#include "exact/stepper.hpp"
#include "obstacles/obstacle_geometry.hpp"

namespace psb::exact {

void ExactStepper::predictObstacles(std::uint32_t i, const Motion& m, double now, Event& best) {
    const Body& a = bodies_[i];
    // Held particles pass through obstacles (their owner moves them, as in the discrete mode);
    // sleepers do not move.
    if (a.flags & (kHeld | kAsleep)) return;
    const Cold& c = cold_[i];
    // The face a particle slides on is left at its end (a slide event), never hit.
    const std::uint32_t sliding = (a.flags & kSliding) ? slides_[i].obstacle : UINT32_MAX;
    for (const std::uint32_t k : obstacles_.near(grid_.fine(), c.kx, c.ky)) {
        if (k == sliding) continue;
        const double t = now + obstacleEventTime(m.x, m.y, m.vx, m.vy, m.ax, m.ay, a.r,
                                                 obstacles_[k], best.time - now);
        if (t < best.time) best = {t, k, 0, Kind::Obstacle, 0};
    }
}

void ExactStepper::handleObstacle(std::uint32_t i, const Event& ev, StepCounters& counters) {
    Body& a = bodies_[i];
    if (jamsAt(i, ev.time)) {  // jammed here: its velocity is gone, nothing to rebound
        ++events_;
        predictCollision(i, ev.time);
        predictCell(i, ev.time);
        return;
    }
    const bool recent = collidedWithin(a, ev.time);
    advance(i, ev.time);
    stopSliding(i);  // another obstacle ends a slide
    ++events_;
    reboundOffObstacle(i, ev.partner, recent, counters);
    ++a.count;
    // Off the wall it rested on if the obstacle pushed it off; asleep if it is slow and held.
    if (gravity_.on) settleAfterPair(i, false);
    predictCollision(i, ev.time);
    predictCell(i, ev.time);
}

void ExactStepper::reboundOffObstacle(std::uint32_t i, std::uint32_t k, bool recent,
                                      StepCounters& counters, bool maySlide) {
    Body& a = bodies_[i];
    const Obstacle& o = obstacles_[k];
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
    const Vec2 before(a.vx, a.vy);
    const double into = -(a.vx * nx + a.vy * ny);
    const double e = effectiveRestitution(def_.restitution, into, recent);
    const RoughLaws laws{e, def_.friction, def_.tangentialRestitution};
    double dv = rolls_.rough()
                    ? roughReboundOffSurface(a.vx, a.vy, rolls_.spinAt(i, a.r, a.t), nx, ny, laws)
                : def_.friction > 0.0
                    ? reboundOffSurface<true>(a.vx, a.vy, nx, ny, e, def_.friction)
                    : reboundOffSurface<false>(a.vx, a.vy, nx, ny, e, 0.0);
    if (gravity_.on) {
        // Pressed into the obstacle by gravity and leaving it slower than the lift: leave at the
        // lift, as a pressed pair does (see resting.cpp), so that a particle on a slope
        // hops down it instead of making ever faster tiny bounces, and the next impact is never
        // at the same instant.
        double gax, gay;
        accelerationOf(i, a, gax, gay);
        const double an = gax * nx + gay * ny;
        if (an < 0.0 && an * an > kPressTolerance * kPressTolerance * (gax * gax + gay * gay)) {
            const double lift = 0.5 * rest_.restSpeed(), leaving = a.vx * nx + a.vy * ny;
            if (leaving < lift && maySlide && !o.isPeg() && startSliding(i, k, nx, ny)) {
                // On a segment's face: it slides along it instead of hopping
                // (slides.cpp), what is left of its normal velocity absorbed by the contact.
            } else if (leaving < lift) {
                // The lift is part of the normal impulse the contact gives, so Coulomb's law
                // bounds the friction by mu times all of it: over the hops down a slope the
                // normal impulses add up to the weight's normal share (m g cos θ per second),
                // and the mean deceleration is then g (sin θ − mu cos θ). Friction only on the
                // rebound's part gave mu (1 + e)/2 in place of mu.
                const double extra = lift - leaving;
                if (rolls_.rough()) {
                    double along = a.vx * -ny + a.vy * nx;
                    roughAlongSurface(along, rolls_.spinAt(i, a.r, a.t), extra, def_.friction,
                                      def_.tangentialRestitution);
                    a.vx = leaving * nx + along * -ny;
                    a.vy = leaving * ny + along * nx;
                } else if (def_.friction > 0.0) {
                    double along = a.vx * -ny + a.vy * nx;
                    const double cut = std::min(std::abs(along), def_.friction * extra);
                    along -= std::copysign(cut, along);
                    a.vx = leaving * nx + along * -ny;
                    a.vy = leaving * ny + along * nx;
                }
                a.vx += extra * nx;
                a.vy += extra * ny;
                dv += extra;
            }
        }
    }
    if (dv > 0.0) {
        ++counters.obstacleCollisions;
        if (recorder_.on()) {
            recorder_.add({a.t, order_[i], CollisionRecord::kObstacle + k}, [&](double t) {
                return surfaceCollision(t, Collision::With::Obstacle, k, ids_[i], before,
                                        Vec2(a.vx, a.vy), cold_[i].m);
            });
        }
    }
}

}  // namespace psb::exact
