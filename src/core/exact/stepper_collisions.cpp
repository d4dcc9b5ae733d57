// Pair and wall events of the exact stepper: the collision at the instant of contact, its
// restitution, what it does to sleepers and slides, and the rules that keep rounding from
// deciding.
//
// Rules for invalid states (Bannerman et al. 2014), so rounding never decides:
//   - no event is scheduled before the current time (times of impact are durations >= 0);
//   - an overlapping pair collides at once if it approaches and is left alone if it separates;
//   - but a pair already overlapping at a rebuild was placed so (rounding leaves a few ulps at
//     most): its contact distance is the distance it was placed at until a prediction finds it
//     apart. The rule above alone would be a ratchet (every drift apart kept), squeezing the
//     overlaps of a box too full for its discs into the others' gaps until the pile jams;
//   - a disc past a wall collides with it at once if moving outward, else is left alone;
//   - a collision whose pair turns out not to approach at its instant changes nothing.
//
// Inelastic collapse and particles that do not fit in the box: the rules in collision_rules.hpp.
//
// Held (kinematic) particles. Infinite mass, straight lines: they push and are not pushed
// (contact.hpp's kinematic limit). A held particle that reaches a wall stops moving across it.
// A free particle squeezed between a held one and a wall or another held one is the jam
// guard's (jam_guard.hpp).

#include <algorithm>
#include <cmath>

#include "contact/collision_capture.hpp"
#include "contact/contact.hpp"
#include "exact/motion.hpp"
#include "exact/stepper.hpp"
#include "support/periodic_box.hpp"

namespace psb::exact {

namespace {

// The rough tangential impulse of wall `side` (0..3) on a (spin: its rotation), after a rebound
// of dv along the wall's normal.
void roughWallTangential(Body& a, Spin spin, int side, double dv, const WorldDef& def) {
    // Wall `side` has the outward normal n = −outward along its axis (outward: +1 for the
    // right and bottom walls), and the tangent t = (−n_y, n_x): −outward times the other axis
    // for the x walls, +outward times it for the y walls (as in the discrete mode's walls).
    const bool alongX = side < 2;
    const double outward = (side % 2 == 0) ? -1.0 : 1.0;
    const double sign = alongX ? -outward : outward;
    double& vt = alongX ? a.vy : a.vx;
    double along = sign * vt;
    roughAlongSurface(along, spin, dv, def.friction, def.tangentialRestitution);
    vt = sign * along;
}

}  // namespace

void ExactStepper::handlePair(std::uint32_t i, const Event& ev, StepCounters& counters) {
    const std::uint32_t j = ev.partner;
    __builtin_prefetch(&cold_[j]);
    queue_.prefetch(2 * j);
    Body& a = bodies_[i];
    Body& b = bodies_[j];
    if (b.count != ev.partnerCount) {
        ++events_;  // stale: j changed course after this was predicted
        predictCollision(i, ev.time);
        return;
    }
    ++events_;
    // Squeezed by a held particle: the held jam guard's (JamGuard::countHeldHit).
    const bool byHeld = ((a.flags | b.flags) & kHeld) != 0;
    const bool aJammed = !byHeld && jamsAt(i, ev.time), bJammed = !byHeld && jamsAt(j, ev.time);
    const bool recent = collidedWithin(a, ev.time) || collidedWithin(b, ev.time);
    // A sleeper does not move; advancing it would only restart its clock (t).
    if (!(a.flags & kAsleep)) advance(i, ev.time);
    if (!(b.flags & kAsleep)) advance(j, ev.time);
    // A pair event ends a slide (the pair's impulses and lift are those of free particles); a
    // slider still on its face afterwards slides on (keepOnFace below). Its acceleration has
    // changed, so its counter does too.
    // So does a pair event end a roll on a face or a wall (settleAfterPair gives the phase
    // again where the disc is still in contact).
    const bool aSlid = (a.flags & kSliding) != 0, bSlid = (b.flags & kSliding) != 0;
    if (a.flags & (kSliding | kRolling)) {
        stopSliding(i);
        ++a.count;
    }
    if (b.flags & (kSliding | kRolling)) {
        stopSliding(j);
        ++b.count;
    }
    double dx = b.x - a.x, dy = b.y - a.y;
    if (def_.periodic) {
        // Touching, so at most half a box apart: the nearest images are the ones that touch.
        dx = periodic::minimumImage(dx, def_.width);
        dy = periodic::minimumImage(dy, def_.height);
    }
    const double d = std::sqrt(dx * dx + dy * dy);
    maxOverlap_ = std::max(maxOverlap_, a.r + b.r - d);
    Normal n;
    if (d > 0.0 && std::isfinite(dx / d) && std::isfinite(dy / d)) {
        n = {dx / d, dy / d};
    } else {
        n = coincidentNormal(ids_[i], ids_[j]);
    }
    const double approach = (a.vx - b.vx) * n.x + (a.vy - b.vy) * n.y;
    // A sleeper hit hard enough, or by a held particle, wakes; otherwise it stays put and the
    // other bounces off it as off an infinitely heavy disc.
    bool aStays = false, bStays = false, woke = false;
    if (gravity_.on) {
        const auto hitsSleeper = [&](std::uint32_t s, std::uint32_t o) {
            if (!(bodies_[s].flags & kAsleep)) return false;
            // A particle wedged between sleepers (no room between them) would bounce between
            // them ever faster: after kWakeAfterHits such hits in a step it wakes them, and the
            // wedge opens as it would, by pushing them apart.
            if ((bodies_[o].flags & kHeld) || approach > 2.0 * rest_.restSpeed() ||
                jams_.countHit(o, cold_[o]) >= kWakeAfterHits) {
                wake(s, ev.time);
                woke = true;
                return false;
            }
            return true;
        };
        aStays = hitsSleeper(i, j);
        bStays = hitsSleeper(j, i);
    }
    // A particle wider than the box along an axis takes no impulse across it: the walls hold
    // it there. Seen along the normal, its inverse mass is w·|P n|² (P keeps its free axes), so
    // a disc that hits it across a pinned axis bounces as off a wall, and one pinned on both
    // axes is as fixed as a sleeper.
    // A particle jammed at this instant is as fixed as a sleeper.
    aStays = aStays || aJammed;
    bStays = bStays || bJammed;
    const double wi = inverseMassAlong(cold_[i], n, aStays ? 0.0 : cold_[i].w);
    const double wj = inverseMassAlong(cold_[j], n, bStays ? 0.0 : cold_[j].w);
    const auto massSeen = [](const Cold& c, double w) {
        return (c.pinX || c.pinY) && w > 0.0 ? 1.0 / w : c.m;
    };
    const double mi = massSeen(cold_[i], wi), mj = massSeen(cold_[j], wj);
    // Off a sleeper, which does not move, a bounce cannot start a collapse: the TC model's
    // elastic rule would only keep a particle wedged between sleepers rattling at full speed.
    const bool offStatic = aStays || bStays;
    double e = effectiveRestitution(def_.restitution, approach, recent && !offStatic);
    // And a rebound off it slower than the rest speed ends the approach, as on a wall the
    // particle rests on: a particle in a slot between sleepers stops instead of rattling.
    if (offStatic && approach * e < rest_.restSpeed()) e = 0.0;
    const Vec2 aBefore(a.vx, a.vy), bBefore(b.vx, b.vy);
    const bool hit =
        rolls_.rough() ? collideRoughDiscs(a.vx, a.vy, rolls_.spinAt(i, a.r, ev.time), b.vx, b.vy,
                                           rolls_.spinAt(j, b.r, ev.time), wi, wj, mi, mj, n,
                                           {e, def_.friction, def_.tangentialRestitution})
        : def_.friction > 0.0
            ? collideDiscs<true>(a.vx, a.vy, b.vx, b.vy, wi, wj, mi, mj, n, e, def_.friction)
            : collideDiscs<false>(a.vx, a.vy, b.vx, b.vy, wi, wj, mi, mj, n, e, 0.0);
    if (hit) {
        // A pinned particle's impulse, found for the inverse mass it has along n, moves it
        // along its free axis only: Δv = (w / w_seen)·P·Δv_seen.
        holdAcrossPinnedAxes(a, cold_[i], aBefore, wi);
        holdAcrossPinnedAxes(b, cold_[j], bBefore, wj);
        ++counters.collisions;
        if (!aStays) ++a.count;
        if (!bStays) ++b.count;
        if (b.flags & kHeld) jams_.countHeldHit(i, a, cold_[i]);
        if (a.flags & kHeld) jams_.countHeldHit(j, b, cold_[j]);
        if (virial_) {
            // The impulse on a: m_a Δv_a, or, when a took less than the contact gave (held,
            // pinned, staying put), what b received, reversed. r_ab = −(dx, dy).
            const bool aFree = wi > 0.0 && !cold_[i].pinX && !cold_[i].pinY;
            const double jx =
                aFree ? cold_[i].m * (a.vx - aBefore.x()) : -cold_[j].m * (b.vx - bBefore.x());
            const double jy =
                aFree ? cold_[i].m * (a.vy - aBefore.y()) : -cold_[j].m * (b.vy - bBefore.y());
            counters.pairVirial -= dx * jx + dy * jy;
        }
        if (recorder_.on()) {
            recorder_.add({ev.time, order_[i], order_[j]}, [&](double t) {
                // A pinned a's momentum changes by less than the contact's impulse (the walls
                // take the rest): the impulse is then what b received.
                const bool aPinned = cold_[i].pinX || cold_[i].pinY;
                return pairCollision(t, ids_[i], ids_[j], aBefore, Vec2(a.vx, a.vy), bBefore,
                                     Vec2(b.vx, b.vy), aPinned ? 0.0 : wi, cold_[i].m, cold_[j].m);
            });
        }
    }
    if (gravity_.on) {
        // Lift what gravity presses together (judged by how they moved into the contact), then
        // let them rest (what this hit just woke does not).
        rest_.liftPressedPair(i, j, n, aSlid, bSlid, around());
        // A slider pressed along its face into a neighbour without an impulse (at rest against
        // it) would slide into it again at once, the same event at the same instant without
        // end: it hops off the face instead, as before slides, and slides again when it lands.
        if (aSlid) keepOnFace(i, counters, hit);
        if (bSlid) keepOnFace(j, counters, hit);
        settleAfterPair(i, woke);
        settleAfterPair(j, woke);
    }
    predictCollision(i, ev.time);
    predictCollision(j, ev.time);
    predictCell(i, ev.time);
    predictCell(j, ev.time);
}

void ExactStepper::handleWall(std::uint32_t i, const Event& ev, StepCounters& counters) {
    Body& a = bodies_[i];
    if (jamsAt(i, ev.time)) {  // jammed here: its velocity is gone, nothing to rebound
        ++events_;
        predictCollision(i, ev.time);
        predictCell(i, ev.time);
        return;
    }
    const bool recent = collidedWithin(a, ev.time);
    advance(i, ev.time);
    stopSliding(i);
    ++events_;
    const bool alongX = ev.side < 2;
    double& v = alongX ? a.vx : a.vy;
    double& vt = alongX ? a.vy : a.vx;
    const double outward = (ev.side % 2 == 0) ? -1.0 : 1.0;
    const bool pinned = alongX ? cold_[i].pinX : cold_[i].pinY;
    if (!pinned) {
        // At the wall by definition of the event: a parabola's root can leave the centre a few
        // ulps past it, which a particle resting there would keep. A straight line's root is
        // left as computed (an ulp or two off the wall) unless the speed makes that rounding a
        // distance: at 10¹³ m/s one ulp of the event's time is micrometres.
        double& x = alongX ? a.x : a.y;
        const double extent = alongX ? def_.width : def_.height;
        const double inside = std::clamp(x, a.r, extent - a.r);
        if (gravity_.on || std::abs(x - inside) > kWallSlack * extent) x = inside;
    }
    const Vec2 before(a.vx, a.vy);
    double dv = 0.0;
    if (a.flags & kHeld) {
        // A held particle stops moving across the wall; its owner sets its velocity again.
        if (outward * v > 0.0) v = 0.0;
    } else if (pinned) {
        dv = std::abs(v);
        v = 0.0;
    } else {
        double out = outward * v;
        const double e = effectiveRestitution(def_.restitution, out, recent);
        if (rolls_.rough()) {
            dv = reboundOffWall<false>(out, vt, e, 0.0);
            v = outward * out;
            if (dv > 0.0) roughWallTangential(a, rolls_.spinAt(i, a.r, ev.time), ev.side, dv, def_);
        } else {
            dv = def_.friction > 0.0 ? reboundOffWall<true>(out, vt, e, def_.friction)
                                     : reboundOffWall<false>(out, vt, e, 0.0);
        }
        v = outward * out;
        // A rough wall's friction may send it along the wall, off the other wall it rested on (a
        // disc rolling on the floor into a side wall is kicked up it by its spin): gravity takes
        // it again, or, sent into that wall, the wall event comes at once and decides.
        const std::uint32_t across = alongX ? kRestY : kRestX;
        if ((a.flags & across) && vt != 0.0 && !(alongX ? cold_[i].pinY : cold_[i].pinX))
            a.flags &= ~across;
        // Pressed into this wall by gravity and leaving it too slowly to fly: it rests on it.
        if (gravity_.on && outward * (alongX ? gravity_.x : gravity_.y) > 0.0 &&
            std::abs(v) < rest_.restSpeed()) {
            dv += std::abs(v);
            v = 0.0;
            a.flags |= alongX ? kRestX : kRestY;
        }
    }
    if (dv > 0.0) {
        ++counters.wallCollisions;
        counters.wallImpulse += cold_[i].m * dv;
        if (recorder_.on()) {
            recorder_.add({ev.time, order_[i], CollisionRecord::kWall + ev.side}, [&](double t) {
                return surfaceCollision(t, Collision::With::Wall,
                                        static_cast<std::uint32_t>(ev.side), ids_[i], before,
                                        Vec2(a.vx, a.vy), cold_[i].m);
            });
        }
    }
    ++a.count;
    if (gravity_.on && !(a.flags & kHeld)) {
        settle(i, ev.time, rest_.slow(a) && rest_.mayRest(i, ev.time));
        // Resting on a wall, a disc that turns slips or rolls along it (rolls.hpp).
        setRoll(i);
    }
    predictCollision(i, ev.time);
    predictCell(i, ev.time);
}

bool ExactStepper::jamsAt(std::uint32_t i, double t) {
    Body& a = bodies_[i];
    if (a.flags & (kHeld | kAsleep)) return false;  // cannot jam
    if (!jams_.jams(a, i, order_, t)) return false;
    // Jammed: no room to move. Its velocity, and any it is given while its hits keep coming
    // without time between, goes to the bodies that hold it.
    if (gravity_.on) {
        const Resting::Sleep s = rest_.caught(i, t, around());
        fallAsleep(i, t, s.depth, s.provisional);
    } else if (a.vx != 0.0 || a.vy != 0.0) {
        advance(i, t);
        stopSliding(i);
        a.vx = a.vy = 0.0;
        ++a.count;
    }
    return true;
}

}  // namespace psb::exact
