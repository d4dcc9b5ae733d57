// A disc that turns, in continuous contact with a surface, in the exact stepper: slipping under
// kinetic friction, the slip-to-roll instant, and rolling; all of it closed-form motion.
//
// Where. With rough contacts (the world keeps rotation and has friction), a disc whose rotation
// is free on the face of a segment it slides on (kSliding, sliding.cpp) or on the one wall it
// rests on (kRestX or kRestY, resting.cpp). A disc that does not turn slides as a block: on a
// face by sliding.cpp's law, on a wall by the block's case below.
//
// How. n is the surface's outward normal (from the surface to the centre), t = (−n_y, n_x)
// its tangent, g_t = g·t and g_n = −g·n > 0 gravity's shares, q = 1/k. The contact point slips
// at s = v·t − ω r (contact.hpp's sign: a disc rolling along +t has ω = v / r > 0). Kinetic
// friction μ m g_n acts at the contact point against the slip, so while the disc slips with
// sign σ = sign(s)
//
//     a_t = g_t − σ μ g_n,     α = σ μ g_n q / r,     ds/dt = g_t − σ μ g_n (1 + q),
//
// all constant: the centre moves on a parabola along the surface and the angle on a parabola in
// time. The slip reaches 0 at t* = −s / (ds/dt) when ds/dt opposes s: the slip-to-roll instant,
// an event of the particle's collision key (Kind::Roll). There, or wherever a disc meets the
// surface not slipping, it rolls if friction can hold the rolling disc, |g_t| ≤ μ g_n (1 + q)
// (that is μ ≥ k tan θ / (1 + k)):
//
//     a_t = g_t / (1 + k) = g_t q / (1 + q),     α = a_t / r,     ω = v_t / r kept,
//
// with no friction work: the rolling disc keeps its energy. Otherwise it slips the way gravity
// pulls it, for good (ds/dt then has the slip's sign). The rolling itself makes no events: a
// disc rolling on a level floor rolls on at constant speed until something else happens to it.
// A slip smaller than kSlipRounding of the speeds is rounding (a sticking rough impulse with
// β = 0 leaves it so): the disc rolls, its ω set to v_t / r.
//
// What stays as it was. The acceleration along the surface is held in slide_, read by
// accelerationOf like a slide's, so pair times of impact, walls and cell faces take it as any
// other parabola. Any event of the particle ends the roll (stopSliding, endRoll: its spin
// brought to the event, alpha back to 0); the event's handler gives the phase again where the
// particle is still in contact (setRoll from handleWall, settleAfterPair, setSlideAcceleration,
// wake). The end of a face and leaving a wall work as for a block; a disc that falls asleep
// stops turning (its contacts' friction would stop it).
//
// A block on a wall. A disc that does not turn (q = 0) resting on a wall is the case q = 0 of
// the above: its contact point moves with its centre, so its slip is its speed along the wall,
// and it slides at a_t = g_t − σ μ g_n until it stops, at t* = −v_t / a_t (the slip-to-roll
// event, Kind::Roll, of a disc that cannot roll); there static friction holds it if
// |g_t| ≤ μ g_n (it then rests, asleep if held, as a slide stopped on a face does), else it
// slides back the way gravity pulls it. The same law as a block on a segment's face
// (sliding.cpp), so sliding along the floor costs no events between its ends either.

#include <cmath>

#include "exact/motion.hpp"
#include "exact/stepper.hpp"
#include "exact/time_of_impact.hpp"

namespace psb::exact {

namespace {

// A slip below this fraction of the contact's speeds (|v_t| + |ω r|) is rounding: the disc
// rolls. A sticking rough impulse leaves a few ulps of them.
constexpr double kSlipRounding = 1e-12;

}  // namespace

bool ExactStepper::rollingSurface(std::uint32_t i, double& nx, double& ny) const {
    const Body& a = bodies_[i];
    if (a.flags & kSliding) {
        // The face's normal on the side the centre is on.
        const Obstacle& o = obstacles_[slides_[i].obstacle];
        const double ex = o.b.x() - o.a.x(), ey = o.b.y() - o.a.y();
        const double length = std::sqrt(ex * ex + ey * ey);
        const double px = -ey / length, py = ex / length;
        const double side = (a.x - o.a.x()) * px + (a.y - o.a.y()) * py >= 0.0 ? 1.0 : -1.0;
        nx = side * px;
        ny = side * py;
        return true;
    }
    // One wall, that gravity presses the disc into (a corner holds it along both axes; a disc
    // pinned across an axis touches both walls of it).
    const Cold& c = cold_[i];
    const bool restX = (a.flags & kRestX) != 0, restY = (a.flags & kRestY) != 0;
    if (restX == restY || c.pinX || c.pinY) return false;
    nx = restX ? (gravity_.x > 0.0 ? -1.0 : 1.0) : 0.0;
    ny = restY ? (gravity_.y > 0.0 ? -1.0 : 1.0) : 0.0;
    return true;
}

void ExactStepper::setRoll(std::uint32_t i) {
    Body& a = bodies_[i];
    if (!rough_) return;
    Turn& r = turn_[i];
    double nx, ny;
    // A block on a segment's face slides by sliding.cpp's law (setSlideAcceleration).
    if ((a.flags & (kHeld | kAsleep)) || (r.q == 0.0 && (a.flags & kSliding)) ||
        !rollingSurface(i, nx, ny)) {
        if (a.flags & kRolling) endRoll(i);
        return;
    }
    advanceTurn(r, a.t);
    const double tx = -ny, ty = nx;
    const double gt = gravity_.x * tx + gravity_.y * ty, gn = -(gravity_.x * nx + gravity_.y * ny);
    const double friction = def_.friction * gn;
    const double vt = a.vx * tx + a.vy * ty;
    const double slip = vt - r.omega * a.r;
    Slide& s = slides_[i];
    s.slipEnds = kNever;
    double at;
    if (r.q == 0.0) {
        // A block on a wall: kinetic friction against its motion until it stops, an event; at
        // rest none while static friction holds it, else down the wall less the friction.
        at = 0.0;
        if (vt != 0.0) {
            at = gt - std::copysign(friction, vt);
        } else if (std::abs(gt) > friction) {
            at = gt - std::copysign(friction, gt);
        }
        if (at * vt < 0.0) s.slipEnds = a.t + -vt / at;
    } else if (std::abs(slip) <= kSlipRounding * (std::abs(vt) + std::abs(r.omega * a.r)) &&
               std::abs(gt) <= friction * (1.0 + r.q)) {
        // Rolling: the contact point stays at rest on the surface.
        r.omega = vt / a.r;
        at = gt * r.q / (1.0 + r.q);
        r.alpha = at / a.r;
    } else {
        // Slipping, against the slip's sign (or, not slipping yet, the way gravity pulls where
        // friction cannot hold a rolling disc).
        const double sign =
            std::abs(slip) <= kSlipRounding * (std::abs(vt) + std::abs(r.omega * a.r))
                ? std::copysign(1.0, gt)
                : std::copysign(1.0, slip);
        at = gt - sign * friction;
        r.alpha = sign * friction * r.q / a.r;
        const double rate = gt - sign * friction * (1.0 + r.q);
        if (rate * sign < 0.0 && slip * sign > 0.0) s.slipEnds = a.t + -slip / rate;
    }
    s.ax = at * tx;
    s.ay = at * ty;
    a.flags |= kRolling;
}

void ExactStepper::endRoll(std::uint32_t i) {
    Body& a = bodies_[i];
    Turn& r = turn_[i];
    advanceTurn(r, a.t);
    r.alpha = 0.0;
    a.flags &= ~kRolling;
}

void ExactStepper::predictRoll(std::uint32_t i, double now, Event& best) const {
    const double t = std::max(now, slides_[i].slipEnds);
    if (t < best.time) best = {t, 0, 0, Kind::Roll, 0};
}

void ExactStepper::handleRoll(std::uint32_t i, const Event& ev) {
    // The slip is zero now, to rounding: the disc rolls from here (ω = v_t / r exactly), or
    // slips the other way if friction cannot hold a rolling disc.
    Body& a = bodies_[i];
    advance(i, ev.time);
    ++events_;
    ++a.count;  // its acceleration changes: what neighbours predicted with it is stale
    Turn& r = turn_[i];
    advanceTurn(r, ev.time);
    if (r.q == 0.0) {
        // A block stopped by friction (it has no velocity across the wall it rests on): at
        // rest, asleep if it may sleep there, or sliding back (settleAfterPair gives the phase).
        a.vx = a.vy = 0.0;
        endRoll(i);
        settleAfterPair(i, false);
    } else {
        double nx, ny;
        if (rollingSurface(i, nx, ny)) r.omega = (a.vx * -ny + a.vy * nx) / a.r;
        endRoll(i);
        setRoll(i);
    }
    predictCollision(i, ev.time);
    predictCell(i, ev.time);
}

}  // namespace psb::exact
