#pragma once
// Where a particle of the exact stepper is at a time, and how it moves there.
//
// Lazy advance (Lubachevsky 1991). Each particle keeps the position it had at its last
// velocity change; an event touches only its one or two particles, so an event costs a search
// of the cells around a particle and an O(1)–O(log N) queue update, not O(N). Positions for
// the outside world are computed when it reads them (sync) and never fed back, so how dt is
// chopped does not change the trajectory (only, in the last bits, the time t + dt itself).
//
// Gravity. Between events a free particle flies on a parabola, r(t) = r₀ + v₀t + ½gt², and
// lazy advance stays as it is (a particle's stored state is the one at its last velocity
// change). Two free particles fall alike, so their relative motion is a straight line and their
// time of impact time_of_impact.hpp's quadratic. A free particle against one that does not fall
// (held, asleep, or resting on a wall) needs the first root of a quartic; walls and cell faces are
// crossed at the root of a quadratic, either face of a cell (a particle thrown up falls back
// through the face it came in by). All in parabolic_impact.hpp. A world without gravity
// takes none of these paths: its trajectories are bit for bit those of the linear code.
//
// Inline: the searches of stepper_prediction.cpp call these for every neighbour they test.

#include <cstdint>

#include "exact/body.hpp"
#include "exact/slides.hpp"

namespace psb::exact {

// At rest: asleep, or held and not moving.
[[nodiscard]] inline bool isStatic(const Body& b) {
    return (b.flags & kAsleep) || ((b.flags & kHeld) && b.vx == 0.0 && b.vy == 0.0);
}

// The acceleration of particle i, whose record is b (its own, or a copy of it): none held or
// asleep; its surface's while it slides or rolls (found by the index, never by b's address:
// rebuild() projects copies of the records to the clock); else gravity, less what a wall it
// rests on holds.
inline void accelerationOf(std::uint32_t i, const Body& b, const Gravity& g, const Slides& slides,
                           double& ax, double& ay) {
    if (b.flags & (kHeld | kAsleep)) {
        ax = ay = 0.0;
        return;
    }
    if (b.flags & (kSliding | kRolling)) {
        const Slide& s = slides[i];
        ax = s.ax;
        ay = s.ay;
        return;
    }
    ax = (b.flags & kRestX) ? 0.0 : g.x;
    ay = (b.flags & kRestY) ? 0.0 : g.y;
}

// Where particle i (record b) is at time t, and how it moves there.
[[nodiscard]] inline Motion motionAt(std::uint32_t i, const Body& b, const Gravity& g,
                                     const Slides& slides, double t) {
    Motion m{};
    accelerationOf(i, b, g, slides, m.ax, m.ay);
    const double h = t - b.t;
    m.x = b.x + b.vx * h + 0.5 * m.ax * h * h;
    m.y = b.y + b.vy * h + 0.5 * m.ay * h * h;
    m.vx = b.vx + m.ax * h;
    m.vy = b.vy + m.ay * h;
    return m;
}

// Brings particle i's record b to time t.
inline void advance(std::uint32_t i, Body& b, const Gravity& g, const Slides& slides, double t) {
    const double h = t - b.t;
    if (h != 0.0) {
        if (g.on) {
            double ax, ay;
            accelerationOf(i, b, g, slides, ax, ay);
            b.x += b.vx * h + 0.5 * ax * h * h;
            b.y += b.vy * h + 0.5 * ay * h * h;
            b.vx += ax * h;
            b.vy += ay * h;
        } else {
            b.x += b.vx * h;
            b.y += b.vy * h;
        }
        b.t = t;
    }
}

// A rotation brought to time t: the angle grows linearly between rough impulses, and as a
// parabola while the disc slips or rolls on a surface (alpha != 0). The linear case is the
// expression of before rolling existed, bit for bit.
inline void advanceTurn(Turn& r, double t) {
    const double h = t - r.t;
    if (r.alpha == 0.0) {
        r.angle += r.omega * h;
    } else {
        r.angle += r.omega * h + 0.5 * r.alpha * h * h;
        r.omega += r.alpha * h;
    }
    r.t = t;
}

}  // namespace psb::exact
