// The exact step's events with fixed obstacles (pegs and segments): prediction, rebound and the
// support a resting particle finds on them. The design note is in exact_stepper.hpp
// ("Obstacles"); the times of impact are exact_obstacle_impact.hpp's.

#include <algorithm>
#include <cmath>

#include "contact.hpp"
#include "exact_obstacle_impact.hpp"
#include "exact_stepper.hpp"
#include "obstacle_geometry.hpp"

namespace psb::exact {

namespace {
// How near an end of a face (as a fraction of its length) a contact is the cap's: a slide is
// not started there, and one that reaches an end leaves from this far past it.
constexpr double kSlideEndMargin = 1e-9;
}  // namespace

void ExactStepper::predictObstacles(std::uint32_t i, const Motion& m, double now, Event& best) {
    const Body& a = bodies_[i];
    // Held particles pass through obstacles (their owner moves them, as in the discrete mode);
    // sleepers do not move.
    if (a.flags & (kHeld | kAsleep)) return;
    const Cold& c = cold_[i];
    // The face a particle slides on is left at its end (predictSlide), never hit.
    const std::uint32_t sliding = (a.flags & kSliding) ? slide_[i].obstacle : UINT32_MAX;
    for (const std::uint32_t k : obstacles_.near(cells_, c.kx, c.ky)) {
        if (k == sliding) continue;
        const double t = now + obstacleEventTime(m.x, m.y, m.vx, m.vy, m.ax, m.ay, a.r,
                                                 obstacles_[k], best.time - now);
        if (t < best.time) best = {t, k, 0, Kind::Obstacle, 0};
    }
}

void ExactStepper::handleObstacle(std::uint32_t i, const Event& ev, StepCounters& counters) {
    Body& a = bodies_[i];
    const bool recent = collidedWithin(a, ev.time);
    advance(i, ev.time);
    stopSliding(a);  // another obstacle ends a slide
    ++events_;
    reboundOffObstacle(i, ev.partner, recent, counters);
    ++a.count;
    // Off the wall it rested on if the obstacle pushed it off; asleep if it is slow and held.
    if (gravity_) settleAfterPair(i, false);
    predictCollision(i, ev.time);
    predictCell(i, ev.time);
}

void ExactStepper::keepOnFace(std::uint32_t i, StepCounters& counters, bool maySlide) {
    // i slid on a face until a pair hit it just now. Sent off the face, it flies; still on it
    // (not moving away from it), the face answers at once, as the obstacle event that its next
    // prediction would find at this instant would: a rebound, and a slide again if slow.
    Body& a = bodies_[i];
    const std::uint32_t k = slide_[i].obstacle;
    double qx, qy;
    nearestCorePoint(obstacles_[k], a.x, a.y, qx, qy);
    if ((a.vx * (a.x - qx) + a.vy * (a.y - qy)) > 0.0) return;
    reboundOffObstacle(i, k, collidedWithin(a, a.t), counters, maySlide);
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
        accelerationOf(i, a, gax, gay);
        const double an = gax * nx + gay * ny;
        if (an < 0.0 && an * an > kPressTolerance * kPressTolerance * (gax * gax + gay * gay)) {
            const double lift = 0.5 * restSpeed_, leaving = a.vx * nx + a.vy * ny;
            if (leaving < lift && maySlide && !o.isPeg() && startSliding(i, k, nx, ny)) {
                // On a segment's face: it slides along it instead of hopping (see the design
                // note), what is left of its normal velocity absorbed by the contact.
            } else if (leaving < lift) {
                // The lift is part of the normal impulse the contact gives, so Coulomb's law
                // bounds the friction by mu times all of it: over the hops down a slope the
                // normal impulses add up to the weight's normal share (m g cos θ per second),
                // and the mean deceleration is then g (sin θ − mu cos θ). Friction only on the
                // rebound's part gave mu (1 + e)/2 in place of mu.
                const double extra = lift - leaving;
                if (def_.friction > 0.0) {
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
        if (log_) log_->push_back({a.t, order_[i], CollisionRecord::kObstacle + k});
    }
}

bool ExactStepper::startSliding(std::uint32_t i, std::uint32_t k, double nx, double ny) {
    Body& a = bodies_[i];
    // A particle wider than the box along an axis has no velocity across it, which a slide
    // down a slanted face would need: it hops.
    if (cold_[i].pinX || cold_[i].pinY) return false;
    const Obstacle& o = obstacles_[k];
    const double ex = o.b.x() - o.a.x(), ey = o.b.y() - o.a.y();
    const double length = std::sqrt(ex * ex + ey * ey);
    const double ux = ex / length, uy = ey / length;
    // Where along the face the contact is. Within a hair of an end the slide would end at once
    // (and rounding would decide which of face and cap the contact is): the cap's hop is left
    // to do there what it does on a cap.
    const double along = (a.x - o.a.x()) * ux + (a.y - o.a.y()) * uy;
    const double margin = kSlideEndMargin * length;
    if (!(along > margin && along < length - margin)) return false;
    // Normal velocity and any rounding of the contact distance absorbed: at contact, moving
    // along the face.
    const double vt = a.vx * ux + a.vy * uy;
    a.vx = vt * ux;
    a.vy = vt * uy;
    const double qx = o.a.x() + along * ux, qy = o.a.y() + along * uy;
    a.x = qx + (a.r + o.radius) * nx;
    a.y = qy + (a.r + o.radius) * ny;
    a.flags |= kSliding;
    a.flags &= ~(kRestX | kRestY);  // the face carries it now
    slide_[i].obstacle = k;
    setSlideAcceleration(i);
    return true;
}

void ExactStepper::setSlideAcceleration(std::uint32_t i) {
    // Gravity along the face, less kinetic friction mu·|g_n| against the motion; at rest, none
    // while static friction holds (|g_t| <= mu·|g_n|), else down the face less the friction.
    Body& a = bodies_[i];
    Slide& s = slide_[i];
    const Obstacle& o = obstacles_[s.obstacle];
    const double ex = o.b.x() - o.a.x(), ey = o.b.y() - o.a.y();
    const double length = std::sqrt(ex * ex + ey * ey);
    const double ux = ex / length, uy = ey / length;
    const double gt = gx_ * ux + gy_ * uy;
    const double friction = def_.friction * std::abs(gx_ * -uy + gy_ * ux);
    const double vt = a.vx * ux + a.vy * uy;
    double at = 0.0;
    if (vt != 0.0) {
        at = gt - std::copysign(friction, vt);
    } else if (std::abs(gt) > friction) {
        at = gt - std::copysign(friction, gt);
    }
    s.ax = at * ux;
    s.ay = at * uy;
}

void ExactStepper::predictSlide(std::uint32_t i, const Motion& m, double now, Event& best) const {
    // The end of the face (either end: a slide up a slope turns back), or, where friction
    // decelerates it, the instant the slide stops.
    const Slide& s = slide_[i];
    const Obstacle& o = obstacles_[s.obstacle];
    const double ex = o.b.x() - o.a.x(), ey = o.b.y() - o.a.y();
    const double length = std::sqrt(ex * ex + ey * ey);
    const double ux = ex / length, uy = ey / length;
    const double along = (m.x - o.a.x()) * ux + (m.y - o.a.y()) * uy;
    const double vt = m.vx * ux + m.vy * uy, at = s.ax * ux + s.ay * uy;
    const double t[3] = {crossingTime(along, vt, at, 0.0, -1.0),
                         crossingTime(along, vt, at, length, 1.0),
                         vt != 0.0 && at * vt < 0.0 ? -vt / at : kNever};
    for (std::int8_t side = 0; side < 3; ++side) {
        if (now + t[side] < best.time) best = {now + t[side], s.obstacle, 0, Kind::Slide, side};
    }
}

void ExactStepper::handleSlide(std::uint32_t i, const Event& ev) {
    Body& a = bodies_[i];
    advance(i, ev.time);
    ++events_;
    ++a.count;
    if (ev.side < 2) {
        // Off the end of the face: free flight. Round the cap it hops, as on any cap, unless it
        // is fast enough to fly clear of it. The centre is put past the end by startSliding's
        // margin (a nanometre on a metre-long face), at contact distance: at the end itself
        // rounding would decide whether it still touches the face, which gravity presses it
        // into, and a fast ball would be kicked by a hop it should not make.
        stopSliding(a);
        const Obstacle& o = obstacles_[ev.partner];
        const double ex = o.b.x() - o.a.x(), ey = o.b.y() - o.a.y();
        const double length = std::sqrt(ex * ex + ey * ey);
        const double ux = ex / length, uy = ey / length;
        const double side = (a.x - o.a.x()) * -uy + (a.y - o.a.y()) * ux >= 0.0 ? 1.0 : -1.0;
        const double along =
            ev.side == 0 ? -kSlideEndMargin * length : (1.0 + kSlideEndMargin) * length;
        a.x = o.a.x() + along * ux - side * (a.r + o.radius) * uy;
        a.y = o.a.y() + along * uy + side * (a.r + o.radius) * ux;
    } else {
        // Stopped by friction: at rest, held by static friction (and asleep if it may sleep
        // there), or sliding back down a slope steeper than the friction angle.
        a.vx = a.vy = 0.0;
        setSlideAcceleration(i);
        settleAfterPair(i, false);
    }
    predictCollision(i, ev.time);
    predictCell(i, ev.time);
}

int ExactStepper::obstacleSupports(std::uint32_t i, double* nx, double* ny, int count,
                                   int max) const {
    const Body& a = bodies_[i];
    const Cold& c = cold_[i];
    for (const std::uint32_t k : obstacles_.near(cells_, c.kx, c.ky)) {
        if (count == max) break;
        const Obstacle& o = obstacles_[k];
        double qx, qy;
        nearestCorePoint(o, a.x, a.y, qx, qy);
        const double rx = qx - a.x, ry = qy - a.y;  // from i to the obstacle
        const double d = std::sqrt(rx * rx + ry * ry);
        if (!(d > 0.0) || d - (a.r + o.radius) > restGap_) continue;
        nx[count] = rx / d;
        ny[count++] = ry / d;
    }
    return count;
}

}  // namespace psb::exact
