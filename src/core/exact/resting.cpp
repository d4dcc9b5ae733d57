// The exact stepper's resting contacts (gravity only): when a particle falls asleep, what holds
// it up, when it wakes, and what a rebuild keeps asleep.
//
// Resting (gravity only; Bannerman et al. 2014, DynamO's sleeping particles, after Luding &
// McNamara 1998). A ball with e < 1 makes infinitely many bounces in finite time, and the guards
// against inelastic collapse (collision_rules.hpp) only slow the cascade, so particles that come to
// rest are taken out of the dynamics:
//   - a wall that gravity presses a particle into: a rebound slower than restSpeed_ ends with
//     the particle resting on the wall (its velocity and acceleration across the wall zero); it
//     still slides along it;
//   - a particle slower than restSpeed_ after an event falls asleep (zero velocity, no
//     acceleration, no cell events) if the supports within restGap_ hold it (hold()): gravity
//     lies in the cone of their contact normals (along one, or strictly between two less than
//     a half turn apart), or the one face gravity slides it down (the loaded support no other
//     blocks) is tilted less than the friction angle atan(mu), but not when that face is the
//     only support of a disc that turns (it rolls off a peg's top). Not each normal's cone widened
//     by that angle: that counts a neighbour the slide only grazes (one above the particle) as
//     pushing with any force, and grains above a neck locked into arches nothing held up.
//     Supports are walls, obstacles, held particles at rest and sleepers. Each sleeper has a
//     depth: 1 on a wall, an obstacle or a held particle, else 1 + the least depth of the
//     sleepers it rests on; it must keep a support of lower depth, so every sleeper rests on a
//     chain down to something fixed and no cluster holds itself up;
//   - provisional sleep (e < 1): a particle that only slow free neighbours (slower than
//     restSpeed_, not woken in the last kRecheckAfter, not in the first kSettleTime after a
//     rebuild) help hold, with something static among its supports, sleeps until a recheck
//     kRecheckAfter later (Kind::Recheck, in its collision key): held then by what is static,
//     it sleeps for good; still held only with free neighbours' help, it waits again (and a
//     free neighbour at rest with no acceleration, which has no event of its own to fall
//     asleep at, falls asleep then if what is static holds it); else it wakes. Without it an arch
//     of discs leaning on each other waits for the others to sleep first, and none does; with it a
//     grain that slept on a moving one does not hang in the air when that one has gone. A particle
//     woken less than kContactDuration ago does not fall asleep again;
//   - a sleeping particle hit at a normal speed above 2·restSpeed_ (or by a held particle, or,
//     as a backstop, by a particle that already hit sleepers kWakeAfterHits times in this step)
//     wakes; then every sleeper within restGap_ of a woken one is judged again (hold() at its
//     depth) and wakes if no longer held, and so on (a support that moves lets what it held
//     fall, whether it held it from below or from the side; one still held with slow free
//     neighbours' help turns provisional instead); slower hits bounce off it as off
//     an infinitely heavy disc, with the restitution e itself (no TC rule: a sleeper does not
//     move, so there is no collapse to prevent, and the elastic rule only kept a disc wedged
//     between sleepers rattling at full speed) and with none if the rebound would be slower
//     than restSpeed_ (it stops, as on a wall it rests on);
//   - a pair that gravity presses together (one falls and the other does not: it is asleep,
//     held or resting on a wall) and that leaves a collision slower than restSpeed_ / 2 leaves
//     at restSpeed_ / 2 (an impulse shared as the collision shares it): a particle on the side
//     of its support hops down it instead of making ever faster tiny bounces on it, and no
//     pair is ever predicted to touch again at the same instant (a slider the pair event took
//     off its face counts as moving with its slide's acceleration: it is still on the face).
// Rattling (e < 1). Where the weight of a frictionless pile has to be carried by collisions
// alone, the hard-disc model carries it by ever more frequent ones (a disc squeezed between
// two others on a floor it slides on, a cluster collapsing, McNamara & Young 1994): the rules
// above do not bound them. So a particle that collides more than kRattleLimit times within
// kRattleWindow of simulated time falls asleep where it is (it is caught among its neighbours
// at that instant): for good if what is static holds it, else provisionally (rechecked as
// above: a ball squeezed against a neighbour on a slope slides on when the neighbour has
// left). The count is in simulated time, so it does not depend on how steps chop it;
// particles a rebuild sets free are left alone by it for kSettleTime (they are falling).
// restSpeed_ is kRestSpeed for e < 1, or the speed of a hop of kRestHop smallest radii if that
// is higher (large discs under strong gravity); with e = 1 it is the speed of a fall through
// rounding (kRestRoundingGap of the box), so that only particles placed at rest on a support rest,
// and nothing moving ever sleeps (the free-neighbour and rattle rules are off). restGap_ is the
// height of a hop at restSpeed_, restSpeed_²/(2g): waking a sleeper lets it fall at most that
// far, which reaches only restSpeed_ and does not wake what is under it.
// A rebuild (any change to the world) keeps what sleeps where it slept, at its depth (a
// provisional sleeper is rechecked kRecheckAfter after it), if the laws (gravity, box, walls,
// restitution, friction) are unchanged: a particle removed, added, moved or set in motion
// wakes the sleepers within restGap_ of it (and so what they held up); more than
// kMaxDisturbances such changes, or changed laws, wake everything. A drag through a settled
// pile therefore wakes only what the dragged particle touches.

#include "exact/resting.hpp"

#include <algorithm>
#include <cmath>

#include "exact/collision_rules.hpp"
#include "exact/motion.hpp"
#include "exact/parabolic_impact.hpp"
#include "obstacles/obstacle_geometry.hpp"
#include "support/periodic_box.hpp"

namespace psb::exact {

namespace {

// A separation between neighbours brought to their nearest images in a periodic box (the only
// ones near enough to rest on each other); untouched otherwise.
void nearestImage(const WorldDef& def, double& rx, double& ry) {
    if (!def.periodic) return;
    rx = periodic::minimumImage(rx, def.width);
    ry = periodic::minimumImage(ry, def.height);
}

}  // namespace

void Resting::remember(const std::vector<Body>& bodies, const std::vector<ParticleId>& ids,
                       const Gravity& g, const Slides& slides, double clock, Snapshot& out) const {
    for (std::uint32_t i = 0; i < bodies.size(); ++i) {
        // Each particle as sync() wrote it: one that went on unchanged is no disturbance.
        Body b = bodies[i];
        if (!(b.flags & kAsleep)) {
            const Motion m = motionAt(i, b, g, slides, clock);
            b.x = m.x;
            b.y = m.y;
            b.vx = m.vx;
            b.vy = m.vy;
        }
        out.emplace(ids[i], Kept{b, depth_[i]});
    }
}

void Resting::reset(const WorldDef& def, const Gravity& g, const ParticleArrays& p,
                    std::uint32_t n) {
    if (g.on) {
        const double gn = std::hypot(g.x, g.y);
        restSpeed_ = def.restitution < 1.0
                         ? kRestSpeed
                         : std::sqrt(2.0 * gn * kRestRoundingGap * std::max(def.width, def.height));
        // In a scene of large discs under strong gravity the rest speed is the speed of a hop
        // of kRestHop radii, so that resting means the same there as in a scene at human scale.
        if (def.restitution < 1.0 && p.size() > 0) {
            const double rmin = *std::min_element(p.radius.begin(), p.radius.end());
            restSpeed_ = std::max(restSpeed_, std::sqrt(2.0 * gn * kRestHop * rmin));
        }
        restGap_ = restSpeed_ * restSpeed_ / (2.0 * gn);
    }
    wokeAt_.assign(g.on ? n : 0, -kNever);
    depth_.assign(g.on ? n : 0, 0);
    recheckAt_.assign(g.on ? n : 0, kNever);
    rate_.reset(g.on ? n : 0);
    keptSleepers_ = false;
}

bool Resting::keep(Snapshot& before, std::vector<Body>& bodies, const std::vector<ParticleId>& ids,
                   std::vector<Spot>& spots, std::vector<bool>& carried) {
    // A sleeper still where it slept, at rest, sleeps on. Everything else is a disturbance: a
    // particle removed (where it was), added, moved or set in motion (where it is now); the
    // sleepers it touches wake, and with them what rests on them.
    keptSleepers_ = true;
    const auto n = static_cast<std::uint32_t>(bodies.size());
    carried.assign(n, false);  // awake, and going on as it was
    for (std::uint32_t i = 0; i < n; ++i) {
        Body& b = bodies[i];
        const auto it = before.find(ids[i]);
        const Body* was = it != before.end() ? &it->second.body : nullptr;
        const bool same = was && was->x == b.x && was->y == b.y && was->r == b.r &&
                          was->vx == b.vx && was->vy == b.vy;
        if (same && (was->flags & kAsleep) && b.vx == 0.0 && b.vy == 0.0 && !(b.flags & kHeld)) {
            // As it slept: at its depth, and a provisional sleep checked again from now.
            b.flags |= was->flags & (kAsleep | kProvisional);
            depth_[i] = it->second.depth;
            recheckAt_[i] = kRecheckAfter;
        } else if (!same || (b.flags & kHeld)) {
            spots.push_back({b.x, b.y, b.r});
        } else {
            carried[i] = true;
        }
        if (it != before.end()) before.erase(it);
    }
    for (const auto& [id, kept] : before)  // removed
        spots.push_back({kept.body.x, kept.body.y, kept.body.r});
    // A change to many particles at once (a setter, a load) starts everything afresh.
    if (spots.size() > kMaxDisturbances) {
        for (Body& b : bodies)
            b.flags &= ~(kAsleep | kProvisional);
        keptSleepers_ = false;
        return false;
    }
    return true;
}

bool Resting::touches(const Spot& s, const Body& b) const {
    const double reach = s.r + b.r + restGap_;
    const double dx = b.x - s.x, dy = b.y - s.y;
    return dx * dx + dy * dy <= reach * reach;
}

void Resting::settleFreed(const std::vector<Body>& bodies, const std::vector<bool>& carried) {
    // What the changes set free falls: the rattle guard leaves it alone for a while.
    for (std::uint32_t i = 0; i < bodies.size(); ++i) {
        if (!(bodies[i].flags & kAsleep) && !carried[i]) rate_.quiet(i, kSettleTime);
    }
}

bool Resting::mayRest(std::uint32_t i, double now) const {
    return now - wokeAt_[i] >= kContactDuration;
}

Resting::Sleep Resting::settle(std::uint32_t i, double now, bool slow, const Surroundings& s) {
    // Slow and held by what does not move: asleep for good. Held only with slow free
    // neighbours' help, or caught rattling: asleep until a recheck kRecheckAfter later.
    if (slow) {
        const Hold h = hold(i, kUngrounded + 1, now, s);
        if (h.firm) return {true, h.depth, false};
        if (h.withFree) return {true, h.depth, true};
        if (!rattles(i, now, s.def.restitution)) return {};
        return {true, h.depth, !h.firm};
    }
    if (!rattles(i, now, s.def.restitution)) return {};
    return caught(i, now, s);
}

Resting::Sleep Resting::caught(std::uint32_t i, double now, const Surroundings& s) const {
    const Hold h = hold(i, kUngrounded + 1, now, s);
    return {true, h.depth, !h.firm};
}

Resting::Sleep Resting::atRestBeside(std::uint32_t q, std::uint32_t i, double now,
                                     const Surroundings& s) const {
    // A free neighbour with no velocity and no acceleration (one woken or hit at rest on the
    // floor, say) has no event of its own to fall asleep at, and would keep i provisional for
    // ever: it falls asleep now if what is static holds it.
    const Body& a = s.bodies[i];
    const Body& b = s.bodies[q];
    if (q == i || (b.flags & (kAsleep | kHeld)) || b.vx != 0.0 || b.vy != 0.0) return {};
    double ax, ay;
    accelerationOf(q, b, s.gravity, s.slides, ax, ay);
    if (ax != 0.0 || ay != 0.0 || !mayRest(q, now)) return {};
    double rx = b.x - a.x, ry = b.y - a.y;
    nearestImage(s.def, rx, ry);
    const double reach = a.r + b.r + restGap_;
    if (rx * rx + ry * ry > reach * reach) return {};
    const Hold h = hold(q, kUngrounded + 1, now, s);
    if (!h.firm) return {};
    return {true, h.depth, false};
}

void Resting::fallAsleep(std::uint32_t i, Body& b, double now, std::uint32_t depth,
                         bool provisional) {
    b.vx = b.vy = 0.0;
    b.flags |= kAsleep;
    depth_[i] = depth;
    if (provisional) makeProvisional(i, b, now);
}

void Resting::makeProvisional(std::uint32_t i, Body& b, double now) {
    b.flags |= kProvisional;
    recheckAt_[i] = now + kRecheckAfter;
}

void Resting::rouse(std::uint32_t i, Body& b, double now) {
    // It still rests on the walls it rested on (until it moves off them): what presses it
    // into them is then lifted off it, not pressed through it.
    b.flags &= ~(kAsleep | kProvisional);
    b.t = now;
    wokeAt_[i] = now;
    ++b.count;
}

Resting::Support Resting::afterWake(std::uint32_t q, std::uint32_t p, double now,
                                    const Surroundings& s) {
    // A sleeper nearer the ground does not rest on p (see hold()); one farther from it that
    // what stays asleep no longer holds (with a support nearer the ground than itself) wakes.
    const Body& a = s.bodies[p];
    Body& b = s.bodies[q];
    if (!(b.flags & kAsleep)) return Support::Holds;
    double rx = b.x - a.x, ry = b.y - a.y;
    nearestImage(s.def, rx, ry);
    const double reach = a.r + b.r + restGap_;
    if (rx * rx + ry * ry > reach * reach) return Support::Holds;
    const Hold h = hold(q, depth_[q], now, s);
    if (h.firm) return Support::Holds;
    if (h.withFree) {
        // Held now only with slow free neighbours' help: provisional, as if it had just
        // fallen asleep so (one that already is keeps its recheck).
        if (b.flags & kProvisional) return Support::Holds;
        makeProvisional(q, b, now);
        return Support::Provisional;
    }
    return Support::Gone;
}

Resting::Support Resting::recheck(std::uint32_t i, double now, const Surroundings& s) {
    // A provisional sleeper: held now by what does not move, with a support nearer the ground
    // than itself, it sleeps for good; still held with slow free neighbours' help, it waits
    // another kRecheckAfter; else it wakes (and what it holds up).
    Body& a = s.bodies[i];
    a.flags &= ~kProvisional;
    const Hold h = hold(i, depth_[i], now, s);
    if (h.firm) {
        depth_[i] = std::min(depth_[i], h.depth);
        return Support::Holds;
    }
    return h.withFree ? Support::Provisional : Support::Gone;
}

void Resting::liftPressedPair(std::uint32_t i, std::uint32_t j, Normal n, bool aSlid, bool bSlid,
                              const Surroundings& s) const {
    Body& a = s.bodies[i];
    Body& b = s.bodies[j];
    // A particle wider than the box along an axis is held across it (collision_rules.hpp).
    const Cold& ac = s.cold[i];
    const Cold& bc = s.cold[j];
    const double wi = inverseMassAlong(ac, n, (a.flags & (kAsleep | kHeld)) ? 0.0 : ac.w);
    const double wj = inverseMassAlong(bc, n, (b.flags & (kAsleep | kHeld)) ? 0.0 : bc.w);
    if (wi == 0.0 && wj == 0.0) return;
    // Pressed together by gravity (one falls, the other does not, or less) and leaving each
    // other slower than the lift: leave at the lift, by an impulse along n shared as a
    // collision shares it (see above).
    // A slider the pair event took off its face is still on it: judged by how it moved into
    // the contact, it does not fall (else a ball at rest on a slider, both woken at once, would
    // meet it again at the same instant without end).
    double aax, aay, bax, bay;
    accelerationOf(i, a, s.gravity, s.slides, aax, aay);
    accelerationOf(j, b, s.gravity, s.slides, bax, bay);
    if (aSlid) aax = s.slides[i].ax, aay = s.slides[i].ay;
    if (bSlid) bax = s.slides[j].ax, bay = s.slides[j].ay;
    const double rax = bax - aax, ray = bay - aay, an = rax * n.x + ray * n.y;
    if (!(an < 0.0 && an * an > kPressTolerance * kPressTolerance * (rax * rax + ray * ray)))
        return;
    const double lift = 0.5 * restSpeed_;
    const double leaving = (b.vx - a.vx) * n.x + (b.vy - a.vy) * n.y;
    if (!(leaving < lift)) return;
    const double dv = lift - leaving, share = wi / (wi + wj);
    const Vec2 aBefore(a.vx, a.vy), bBefore(b.vx, b.vy);
    a.vx -= dv * share * n.x;
    a.vy -= dv * share * n.y;
    b.vx += dv * (1.0 - share) * n.x;
    b.vy += dv * (1.0 - share) * n.y;
    holdAcrossPinnedAxes(a, ac, aBefore, wi);
    holdAcrossPinnedAxes(b, bc, bBefore, wj);
    if (wi > 0.0) ++a.count;
    if (wj > 0.0) ++b.count;
}

Resting::Hold Resting::hold(std::uint32_t i, std::uint32_t below, double now,
                            const Surroundings& s) const {
    // The contact normals (from i to what holds it) of everything within restGap_ that does not
    // move: walls, obstacles, held particles at rest (depth 0), sleepers (their depth); then the
    // same with the slow free neighbours added. holdsAgainstGravity says whether they hold i.
    const Body& a = s.bodies[i];
    constexpr int kMax = 16;
    double nx[kMax], ny[kMax];
    int count = 0;
    std::uint32_t lowest = kUngrounded;  // the least depth of a static support below `below`
    const auto add = [&](double x, double y) {
        if (count < kMax) nx[count] = x, ny[count++] = y;
    };
    if (s.def.walls) {
        if (a.x - a.r <= restGap_) add(-1.0, 0.0);
        if (s.def.width - a.r - a.x <= restGap_) add(1.0, 0.0);
        if (a.y - a.r <= restGap_) add(0.0, -1.0);
        if (s.def.height - a.r - a.y <= restGap_) add(0.0, 1.0);
    }
    if (!s.obstacles.empty()) count = obstacleSupports(i, nx, ny, count, kMax, s);
    if (count > 0) lowest = 0;
    // Slow free neighbours, kept apart: a sleep that needs them is provisional (see
    // above). With e = 1 only what is static holds; a neighbour rebuilt or woken less than
    // kRecheckAfter ago may be falling away.
    double fx[kMax], fy[kMax];
    int free = 0;
    const bool freeCount = s.def.restitution < 1.0 && (keptSleepers_ || now >= kSettleTime);
    s.grid.forEachAround(s.cold[i], [&](std::uint32_t q) {
        const Body& b = s.bodies[q];
        if (q == i || (b.flags & kHeld && !isStatic(b))) return;
        const bool still = isStatic(b);
        double bx = b.x, by = b.y;  // a static b does not move: b.x is now
        if (!still) {
            // After a rebuild that kept the sleepers only what it set free or added is
            // settling, not everything.
            if (!freeCount || now - wokeAt_[q] < kRecheckAfter) return;
            if (keptSleepers_ && rate_.quietAt(q, now)) return;
            const Motion m = motionAt(q, b, s.gravity, s.slides, now);
            if (m.vx * m.vx + m.vy * m.vy >= restSpeed_ * restSpeed_) return;
            bx = m.x;
            by = m.y;
        }
        double rx = bx - a.x, ry = by - a.y;
        nearestImage(s.def, rx, ry);
        const double d = std::sqrt(rx * rx + ry * ry);
        if (!(d > 0.0 && d - (a.r + b.r) <= restGap_)) return;
        if (!still) {
            if (free < kMax) fx[free] = rx / d, fy[free++] = ry / d;
            return;
        }
        add(rx / d, ry / d);
        const std::uint32_t depth = (b.flags & kAsleep) ? depth_[q] : 0;
        if (depth < below) lowest = std::min(lowest, depth);
    });
    Hold h;
    h.depth = lowest >= kUngrounded ? kUngrounded : lowest + 1;
    const bool turns = s.rolls.turns(i);
    h.firm = lowest < kUngrounded &&
             holdsAgainstGravity(nx, ny, count, turns, s.gravity, s.def.friction);
    if (h.firm || count == 0 || free == 0) return h;
    // An arch of discs leaning on each other would wait for the others to sleep first, and
    // none would: the slow free neighbours count too, as long as something static is among the
    // supports (two discs falling side by side have nothing static).
    const int statics = count;
    for (int k = 0; k < free; ++k)
        add(fx[k], fy[k]);
    h.withFree =
        count > statics && holdsAgainstGravity(nx, ny, count, turns, s.gravity, s.def.friction);
    return h;
}

bool Resting::holdsAgainstGravity(const double* nx, const double* ny, int count, bool turns,
                                  const Gravity& g, double friction) {
    // Without friction: gravity in the cone of the normals, along one of them (to 1e-9 rad) or
    // strictly between two less than a half turn apart. Anything else lets i move down.
    const double pi = 3.14159265358979323846;
    const double ga = std::atan2(g.y, g.x);
    double lo = -kNever, hi = kNever;  // the nearest normals on either side of gravity
    bool left = false, right = false;
    for (int k = 0; k < count; ++k) {
        double d = std::atan2(ny[k], nx[k]) - ga;  // angle from gravity to normal k, (-pi, pi]
        if (d > pi) d -= 2.0 * pi;
        if (d <= -pi) d += 2.0 * pi;
        if (std::abs(d) <= 1e-9) return true;
        if (d < 0.0 && d > lo) lo = d, left = true;
        if (d > 0.0 && d < hi) hi = d, right = true;
    }
    if (left && right && hi - lo < pi - 1e-9) return true;
    // A disc that turns, on a single support: friction cannot hold it on a tilted face or a
    // peg's side, since gravity's torque about the contact point rolls it off (only a support
    // right under it holds it, above). With other supports, the friction of one that loads it
    // (a grain on top of it) can stop the roll; judged grain by grain, without forces, any
    // other support is taken to, and the friction angle below stands. (Taking none to, a
    // friction angle of 0 for every disc that turns, left the pile preset with e = 0 rattling
    // for good: a disc against a wall between a sleeper under it and one on top hopped between
    // them 2·10³ times a second.)
    if (turns && count == 1) return false;
    // Then i slides down the face of one support that gravity presses it into, the one that no
    // other support blocks (or falls free if it presses into none). Friction holds it there
    // only if that face is tilted less than the friction angle: it carries i's whole weight.
    // (Widening every normal's cone by the friction angle instead would count a neighbour that
    // the slide only grazes as pushing, with any force: a grain between one above and one
    // below it would be held, and the grains above a neck would lock into a fake arch.)
    const double gn = std::hypot(g.x, g.y), ux = g.x / gn, uy = g.y / gn;
    bool pressed = false;
    for (int k = 0; k < count; ++k) {
        const double c = ux * nx[k] + uy * ny[k];  // cos of the face's tilt
        if (!(c > 0.0)) continue;
        pressed = true;
        const double tx = ux - c * nx[k], ty = uy - c * ny[k];  // down the face, |t| = sin tilt
        bool blocked = false;
        for (int m = 0; m < count && !blocked; ++m)
            blocked = m != k && tx * nx[m] + ty * ny[m] > 1e-9;
        if (!blocked && std::sqrt(tx * tx + ty * ty) > friction * c + 1e-9) return false;
    }
    return pressed;
}

int Resting::obstacleSupports(std::uint32_t i, double* nx, double* ny, int count, int max,
                              const Surroundings& s) const {
    const Body& a = s.bodies[i];
    const Cold& c = s.cold[i];
    for (const std::uint32_t k : s.obstacles.near(s.grid.fine(), c.kx, c.ky)) {
        if (count == max) break;
        const Obstacle& o = s.obstacles[k];
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

void Resting::renumber(const std::vector<std::uint32_t>& to) {
    exact::renumber(wokeAt_, to);
    exact::renumber(depth_, to);
    exact::renumber(recheckAt_, to);
    rate_.renumber(to);
}

}  // namespace psb::exact
