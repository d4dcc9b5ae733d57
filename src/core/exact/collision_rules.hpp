#pragma once
// The rules of the exact stepper's collisions that are not contact.hpp's impulses: the guards
// against inelastic collapse, and particles that do not fit in the box.
//
// Inelastic collapse. With e < 1 a cluster can collide infinitely often in finite time, and an
// event-driven code then stalls; with e = 0 it does so at once (a pair leaves a collision
// touching, at zero relative speed, so the next collision in the cluster is at zero gap). Two
// guards make restitution tend to 1 where the collapse would happen:
//   - the TC model (Luding & McNamara 1998): a particle that collided less than
//     kContactDuration ago collides elastically, so a cascade of near-simultaneous collisions
//     re-opens gaps instead of closing them;
//   - impacts slower than kElasticBelowSpeed use e_eff = 1 − (1 − e)·u/u_c, rising linearly to
//     1 as the speed goes to 0, so ever slower collisions lose ever less energy.
// A cooling pile therefore settles to small speeds with a bounded number of events per step.
//
// Particles that do not fit. A particle wider than the box along an axis stays on the box's
// centre line on that axis (as in the discrete mode; Cold::pinX, pinY): the walls hold it there,
// so a collision gives it no velocity across that axis (its inverse mass along the normal is
// that along its free axis), and the walls absorb at once any it has. Such a particle makes the
// cells as large as the box: correct but O(N) per event.

#include "contact/contact.hpp"
#include "exact/body.hpp"

namespace psb::exact {

/// The TC model's contact duration t_c (seconds): a collision of a particle that already
/// collided less than t_c ago is elastic. Ten microseconds: far below a frame (16 ms) and the
/// free flight times of the sandbox's scenes, far above the time between the zero-gap
/// collisions of a collapsing cluster.
inline constexpr double kContactDuration = 1e-5;

/// Impact speed (m/s) below which restitution rises linearly to 1. One millimetre per second:
/// far below the speeds of the sandbox's scenes (metres per second), far above the rounding
/// noise of their velocities.
inline constexpr double kElasticBelowSpeed = 1e-3;

/// Whether the particle with record b collided less than kContactDuration before `now`.
[[nodiscard]] inline bool collidedWithin(const Body& b, double now) {
    // t is the time of b's last velocity change; count > 0 says there was one since the last
    // rebuild (t = 0 at a rebuild is not a collision).
    return b.count > 0 && now - b.t < kContactDuration;
}

/// The restitution of an impact at `impactSpeed` (m/s) under the world's restitution e;
/// `recent`: one of the two collided within kContactDuration.
[[nodiscard]] inline double effectiveRestitution(double e, double impactSpeed, bool recent) {
    if (e >= 1.0 || recent) return 1.0;
    if (impactSpeed >= kElasticBelowSpeed) return e;
    return 1.0 - (1.0 - e) * (impactSpeed / kElasticBelowSpeed);
}

/// A particle's inverse mass seen along n, w being its own (c: its record): for one wider than
/// the box along an axis, what is left of w along its free axis, w·|P n|².
[[nodiscard]] inline double inverseMassAlong(const Cold& c, Normal n, double w) {
    if (!(c.pinX || c.pinY)) return w;
    const double fx = c.pinX ? 0.0 : n.x, fy = c.pinY ? 0.0 : n.y;
    return w * (fx * fx + fy * fy);
}

/// After a collision of a particle wider than the box along an axis (records a, c; its velocity
/// `before` it): its velocity change, found for the inverse mass `wSeen` it has along the
/// normal, turned into the change along its free axis: Δv = (w / w_seen)·P·Δv_seen.
inline void holdAcrossPinnedAxes(Body& a, const Cold& c, const Vec2& before, double wSeen) {
    if (!(c.pinX || c.pinY)) return;
    const double scale = wSeen > 0.0 ? c.w / wSeen : 0.0;
    a.vx = c.pinX ? before.x() : before.x() + scale * (a.vx - before.x());
    a.vy = c.pinY ? before.y() : before.y() + scale * (a.vy - before.y());
}

}  // namespace psb::exact
