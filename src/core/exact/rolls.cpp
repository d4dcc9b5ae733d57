// The exact stepper's rolls: a disc that turns, in continuous contact with a surface, slipping
// under kinetic friction, the slip-to-roll instant, and rolling; all of it closed-form motion.
//
// Where. With rough contacts (the world keeps rotation and has friction), a disc whose rotation
// is free on the face of a segment it slides on (kSliding, slides.cpp) or on the one wall it
// rests on (kRestX or kRestY, resting.cpp). A disc that does not turn slides as a block: on a
// face by slides.cpp's law, on a wall by the block's case below.
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
// What stays as it was. The acceleration along the surface is held in the particle's Slide,
// read by accelerationOf (motion.hpp) like a slide's, so pair times of impact, walls and cell
// faces take it as any other parabola. Any event of the particle ends the roll (end(): its spin
// brought to the event, alpha back to 0); the stepper's handler of the event gives the phase
// again where the particle is still in contact (set(), after a wall, a pair, a slide's stop, a
// wake). The end of a face and leaving a wall work as for a block; a disc that falls asleep
// stops turning (its contacts' friction would stop it).
//
// A block on a wall. A disc that does not turn (q = 0) resting on a wall is the case q = 0 of
// the above: its contact point moves with its centre, so its slip is its speed along the wall,
// and it slides at a_t = g_t − σ μ g_n until it stops, at t* = −v_t / a_t (the slip-to-roll
// event, Kind::Roll, of a disc that cannot roll); there static friction holds it if
// |g_t| ≤ μ g_n (it then rests, asleep if held, as a slide stopped on a face does), else it
// slides back the way gravity pulls it. The same law as a block on a segment's face
// (slides.cpp), so sliding along the floor costs no events between its ends either.

#include "exact/rolls.hpp"

#include <cmath>

#include "exact/time_of_impact.hpp"

namespace psb::exact {

namespace {

// A slip below this fraction of the contact's speeds (|v_t| + |ω r|) is rounding: the disc
// rolls. A sticking rough impulse leaves a few ulps of them.
constexpr double kSlipRounding = 1e-12;

}  // namespace

void Rolls::reset(const ParticleArrays& p, double friction) {
    turn_.resize(p.rotation ? p.size() : 0);
    for (std::uint32_t i = 0; i < turn_.size(); ++i)
        turn_[i] = Turn{p.angle[i], 0.0, p.omega[i], p.spinWeight(i), 0.0};
    rough_ = p.rotation && friction > 0.0;
}

void Rolls::stopTurning(std::uint32_t i, double now) {
    if (rough_ && turn_[i].q > 0.0) {
        advanceTurn(turn_[i], now);
        turn_[i].omega = 0.0;
    }
}

bool Rolls::surface(std::uint32_t i, const Body& a, const Cold& c, const Slides& slides,
                    const ObstacleCells& obstacles, const Gravity& g, double& nx,
                    double& ny) const {
    if (a.flags & kSliding) {
        // The face's normal on the side the centre is on.
        const Obstacle& o = obstacles[slides[i].obstacle];
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
    const bool restX = (a.flags & kRestX) != 0, restY = (a.flags & kRestY) != 0;
    if (restX == restY || c.pinX || c.pinY) return false;
    nx = restX ? (g.x > 0.0 ? -1.0 : 1.0) : 0.0;
    ny = restY ? (g.y > 0.0 ? -1.0 : 1.0) : 0.0;
    return true;
}

void Rolls::set(std::uint32_t i, Body& a, const Cold& c, Slides& slides,
                const ObstacleCells& obstacles, const Gravity& g, double mu) {
    if (!rough_) return;
    Turn& r = turn_[i];
    double nx, ny;
    // A block on a segment's face slides by slides.cpp's law (Slides::setBlockAcceleration).
    if ((a.flags & (kHeld | kAsleep)) || (r.q == 0.0 && (a.flags & kSliding)) ||
        !surface(i, a, c, slides, obstacles, g, nx, ny)) {
        if (a.flags & kRolling) end(i, a);
        return;
    }
    advanceTurn(r, a.t);
    const double tx = -ny, ty = nx;
    const double gt = g.x * tx + g.y * ty, gn = -(g.x * nx + g.y * ny);
    const double friction = mu * gn;
    const double vt = a.vx * tx + a.vy * ty;
    const double slip = vt - r.omega * a.r;
    Slide& s = slides[i];
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

void Rolls::end(std::uint32_t i, Body& a) {
    Turn& r = turn_[i];
    advanceTurn(r, a.t);
    r.alpha = 0.0;
    a.flags &= ~kRolling;
}

bool Rolls::endSlip(std::uint32_t i, Body& a, const Cold& c, Slides& slides,
                    const ObstacleCells& obstacles, const Gravity& g, double friction, double now) {
    // The slip is zero now, to rounding: the disc rolls from here (ω = v_t / r exactly), or
    // slips the other way if friction cannot hold a rolling disc.
    Turn& r = turn_[i];
    advanceTurn(r, now);
    if (r.q == 0.0) {
        // A block stopped by friction (it has no velocity across the wall it rests on): at
        // rest, or sliding back (the stepper settles it, and that gives the phase).
        a.vx = a.vy = 0.0;
        end(i, a);
        return true;
    }
    double nx, ny;
    if (surface(i, a, c, slides, obstacles, g, nx, ny)) r.omega = (a.vx * -ny + a.vy * nx) / a.r;
    end(i, a);
    set(i, a, c, slides, obstacles, g, friction);
    return false;
}

void Rolls::sync(ParticleArrays& p, const std::vector<std::uint32_t>& order, double t) const {
    for (std::size_t k = 0; k < turn_.size(); ++k) {
        Turn r = turn_[k];
        advanceTurn(r, t);
        p.angle[order[k]] = r.angle;
        p.omega[order[k]] = r.omega;
    }
}

}  // namespace psb::exact
