// The exact stepper's slides: a particle sliding on a segment's face, entering the slide, its
// acceleration, its events (the end of the face, the stop) and leaving it.
//
// Sliding (gravity only): a rebound off a segment's face that gravity presses the particle into
// and that leaves it slower than the lift (half the rest speed, resting.cpp) starts a sliding
// contact instead of a hop: the particle stays at contact distance and moves along the face with a
// constant acceleration, gravity's share along it less the kinetic friction mu·|g_n| against the
// motion (none while static friction holds a particle at rest). Its path is still a parabola, with
// another acceleration: pair times of impact take the relative-acceleration quartic, walls and
// cell faces their quadratics, as for any acceleration. The contact has events of its own, in
// the collision key (Kind::Slide): the end of the face (either end; it leaves from a hair past
// it in free flight, and hops round the cap only if too slow to fly clear of it), and, where
// friction decelerates it, the instant it stops (asleep there if the friction angle holds it,
// else sliding back down). Any other event of the particle (a pair, a wall, another obstacle)
// ends the slide; a slider a pair hit that is still on its face gets the face's answer at once
// (stillOnFace, then the stepper's rebound, and a slide again if slow), after a wall or another
// obstacle it is found touching at its next prediction and slides again at that same instant. Pegs
// and caps keep the hop: round a circle the normal force is not constant, and the path is not a
// parabola.
//
// A disc that turns, with rough contacts, slips and rolls on the face instead (rolls.cpp:
// kinetic friction on its contact point's slip until the slip-to-roll instant, an event, then
// a = g sin θ / (1 + k)); the block's motion above is that of a disc that does not turn.
//

#include "exact/slides.hpp"

#include <cmath>

#include "exact/parabolic_impact.hpp"
#include "obstacles/obstacle_geometry.hpp"

namespace psb::exact {

namespace {

// How near an end of a face (as a fraction of its length) a contact is the cap's: a slide is
// not started there, and one that reaches an end leaves from this far past it.
constexpr double kSlideEndMargin = 1e-9;
// A slide starts only at contact: the centre within this fraction of the contact distance of
// the face (rounding at an impact is ulps; a particle placed inside the obstacle is far more).
constexpr double kSlideSnap = 1e-9;

}  // namespace

bool Slides::start(std::uint32_t i, Body& a, const Cold& c, const ObstacleCells& obstacles,
                   std::uint32_t k, double nx, double ny) {
    // A particle wider than the box along an axis has no velocity across it, which a slide
    // down a slanted face would need: it hops.
    if (c.pinX || c.pinY) return false;
    const Obstacle& o = obstacles[k];
    const double ex = o.b.x() - o.a.x(), ey = o.b.y() - o.a.y();
    const double length = std::sqrt(ex * ex + ey * ey);
    const double ux = ex / length, uy = ey / length;
    // Where along the face the contact is. Within a hair of an end the slide would end at once
    // (and rounding would decide which of face and cap the contact is): the cap's hop is left
    // to do there what it does on a cap.
    const double along = (a.x - o.a.x()) * ux + (a.y - o.a.y()) * uy;
    const double margin = kSlideEndMargin * length;
    if (!(along > margin && along < length - margin)) return false;
    const double qx = o.a.x() + along * ux, qy = o.a.y() + along * uy;
    // Only a particle at contact slides. One placed inside the obstacle (spawned, dragged or
    // grown there) would be moved out onto the face, a jump that can take it through a wall;
    // it leaves as from any placed overlap.
    const double contact = a.r + o.radius;
    if (std::abs(std::hypot(a.x - qx, a.y - qy) - contact) > kSlideSnap * contact) return false;
    // Normal velocity and any rounding of the contact distance absorbed: at contact, moving
    // along the face.
    const double vt = a.vx * ux + a.vy * uy;
    a.vx = vt * ux;
    a.vy = vt * uy;
    a.x = qx + (a.r + o.radius) * nx;
    a.y = qy + (a.r + o.radius) * ny;
    a.flags |= kSliding;
    a.flags &= ~(kRestX | kRestY);  // the face carries it now
    slide_[i].obstacle = k;
    return true;
}

void Slides::setBlockAcceleration(std::uint32_t i, const Body& a, const ObstacleCells& obstacles,
                                  const Gravity& g, double friction) {
    // Gravity along the face, less kinetic friction mu·|g_n| against the motion; at rest, none
    // while static friction holds (|g_t| <= mu·|g_n|), else down the face less the friction.
    Slide& s = slide_[i];
    const Obstacle& o = obstacles[s.obstacle];
    const double ex = o.b.x() - o.a.x(), ey = o.b.y() - o.a.y();
    const double length = std::sqrt(ex * ex + ey * ey);
    const double ux = ex / length, uy = ey / length;
    const double gt = g.x * ux + g.y * uy;
    const double kinetic = friction * std::abs(g.x * -uy + g.y * ux);
    const double vt = a.vx * ux + a.vy * uy;
    double at = 0.0;
    if (vt != 0.0) {
        at = gt - std::copysign(kinetic, vt);
    } else if (std::abs(gt) > kinetic) {
        at = gt - std::copysign(kinetic, gt);
    }
    s.ax = at * ux;
    s.ay = at * uy;
}

void Slides::predict(std::uint32_t i, const Body& a, const ObstacleCells& obstacles,
                     const Motion& m, double now, Event& best) const {
    // The end of the face (either end: a slide up a slope turns back), or, where friction
    // decelerates it, the instant the slide stops.
    const Slide& s = slide_[i];
    const Obstacle& o = obstacles[s.obstacle];
    const double ex = o.b.x() - o.a.x(), ey = o.b.y() - o.a.y();
    const double length = std::sqrt(ex * ex + ey * ey);
    const double ux = ex / length, uy = ey / length;
    const double along = (m.x - o.a.x()) * ux + (m.y - o.a.y()) * uy;
    const double vt = m.vx * ux + m.vy * uy, at = s.ax * ux + s.ay * uy;
    // A disc that rolls (or slips) does not stop where its centre does: its phase ends where its
    // slip does (rolls.hpp).
    const bool stops = vt != 0.0 && at * vt < 0.0 && !(a.flags & kRolling);
    const double t[3] = {crossingTime(along, vt, at, 0.0, -1.0),
                         crossingTime(along, vt, at, length, 1.0), stops ? -vt / at : kNever};
    for (std::int8_t side = 0; side < 3; ++side) {
        if (now + t[side] < best.time) best = {now + t[side], s.obstacle, 0, Kind::Slide, side};
    }
}

void Slides::leaveEnd(Body& a, const Obstacle& o, int end) {
    // Round the cap it hops, as on any cap, unless it is fast enough to fly clear of it. The
    // centre is put past the end by start()'s margin (a nanometre on a metre-long face), at
    // contact distance: at the end itself rounding would decide whether it still touches the
    // face, which gravity presses it into, and a fast ball would be kicked by a hop it should
    // not make.
    const double ex = o.b.x() - o.a.x(), ey = o.b.y() - o.a.y();
    const double length = std::sqrt(ex * ex + ey * ey);
    const double ux = ex / length, uy = ey / length;
    const double side = (a.x - o.a.x()) * -uy + (a.y - o.a.y()) * ux >= 0.0 ? 1.0 : -1.0;
    const double along = end == 0 ? -kSlideEndMargin * length : (1.0 + kSlideEndMargin) * length;
    a.x = o.a.x() + along * ux - side * (a.r + o.radius) * uy;
    a.y = o.a.y() + along * uy + side * (a.r + o.radius) * ux;
}

bool Slides::stillOnFace(std::uint32_t i, const Body& a, const ObstacleCells& obstacles) const {
    double qx, qy;
    nearestCorePoint(obstacles[slide_[i].obstacle], a.x, a.y, qx, qy);
    return !((a.vx * (a.x - qx) + a.vy * (a.y - qy)) > 0.0);
}

}  // namespace psb::exact
