// What comes next for a particle of the exact stepper: its earliest collision (pair, wall,
// obstacle, the end of a slide, a recheck) and its next cell move; and the cell move itself,
// which searches only the cells it brings within reach.
//
// Two scheduled events per particle (after Smallenburg 2022). A particle's collision key holds
// only its earliest collision (pair or wall) and its cell key only its next cell move. That is
// enough: a later collision of i would come after its earliest one, when i is predicted again;
// an event of i with j that j's own collisions make wrong is caught by j's counter (bumped at
// every velocity change); and a particle that comes near i does so at a cell move of its own or
// of i, which searches the newly adjacent cells. A candidate (i, j) later than j's own scheduled
// collision is not even kept: j is predicted again against everything around it by then.

#include <algorithm>

#include "exact/grid.hpp"
#include "exact/motion.hpp"
#include "exact/parabolic_impact.hpp"
#include "exact/stepper.hpp"
#include "exact/time_of_impact.hpp"

namespace psb::exact {

namespace {

// A relative velocity below this fraction of the pair's own speeds is rounding (gravity only).
constexpr double kRoundingVelocity = 1e-9;

}  // namespace

void ExactStepper::predictCollision(std::uint32_t i, double now) {
    const Body& a = bodies_[i];
    const Cold& ac = cold_[i];
    // Where i is now. Its stored position stays that of its last velocity change: re-deriving
    // it at every cell face would add a rounding error per face crossed.
    const double ha = now - a.t;
    double ax = a.x + a.vx * ha, ay = a.y + a.vy * ha;
    Event best{kNever, 0, 0, Kind::None, 0};

    Motion m{ax, ay, a.vx, a.vy, 0.0, 0.0};
    if (gravity_.on) {
        m = motionAt(i, a, now);
        ax = m.x;
        ay = m.y;
        if (def_.walls) predictWallsUnderGravity(i, m, now, best);
    } else if (def_.walls) {
        // A pinned axis has no room: any velocity across it is absorbed at once.
        double tw[4] = {kNever, kNever, kNever, kNever};  // left, right, top, bottom
        if (ac.pinX) {
            if (a.vx != 0.0) tw[a.vx > 0.0 ? 1 : 0] = 0.0;
        } else {
            tw[0] = wallImpactTime(ax, a.vx, a.r, -1.0);
            tw[1] = wallImpactTime(ax, a.vx, def_.width - a.r, 1.0);
        }
        if (ac.pinY) {
            if (a.vy != 0.0) tw[a.vy > 0.0 ? 3 : 2] = 0.0;
        } else {
            tw[2] = wallImpactTime(ay, a.vy, a.r, -1.0);
            tw[3] = wallImpactTime(ay, a.vy, def_.height - a.r, 1.0);
        }
        for (std::int8_t side = 0; side < 4; ++side) {
            // Durations >= 0 added to the current time: never an event in the past.
            if (now + tw[side] < best.time) best = {now + tw[side], 0, 0, Kind::Wall, side};
        }
    }
    if (!obstacles_.empty()) {
        predictObstacles(i, m, now, best);
        if (a.flags & kSliding) slides_.predict(i, a, obstacles_, m, now, best);
    }
    if (a.flags & kRolling) rolls_.predict(i, slides_, now, best);
    scanNeighbours(i, now, ax, ay, best);
    if ((a.flags & kProvisional) && rest_.recheckAt(i) < best.time)
        best = {std::max(now, rest_.recheckAt(i)), 0, 0, Kind::Recheck, 0};
    cold_[i].coll = best;
    bodies_[i].nextColl = best.time;
    queue_.update(2 * i, best.time);
}

void ExactStepper::predictWallsUnderGravity(std::uint32_t i, const Motion& m, double now,
                                            Event& best) const {
    const Body& a = bodies_[i];
    const Cold& ac = cold_[i];
    double tw[4] = {kNever, kNever, kNever, kNever};  // left, right, top, bottom
    if (ac.pinX) {
        if (m.vx != 0.0) tw[m.vx > 0.0 ? 1 : 0] = 0.0;
    } else {
        tw[0] = crossingTime(m.x, m.vx, m.ax, a.r, -1.0);
        tw[1] = crossingTime(m.x, m.vx, m.ax, def_.width - a.r, 1.0);
    }
    if (ac.pinY) {
        if (m.vy != 0.0) tw[m.vy > 0.0 ? 3 : 2] = 0.0;
    } else {
        tw[2] = crossingTime(m.y, m.vy, m.ay, a.r, -1.0);
        tw[3] = crossingTime(m.y, m.vy, m.ay, def_.height - a.r, 1.0);
    }
    for (std::int8_t side = 0; side < 4; ++side) {
        if (now + tw[side] < best.time) best = {now + tw[side], 0, 0, Kind::Wall, side};
    }
}

void ExactStepper::predictCell(std::uint32_t i, double now) {
    const Body& a = bodies_[i];
    const Cold& ac = cold_[i];
    const double ha = now - a.t;
    Motion m{a.x + a.vx * ha, a.y + a.vy * ha, a.vx, a.vy, 0.0, 0.0};
    if (gravity_.on) m = motionAt(i, a, now);
    const auto exitTime = [&](double x, double v, double acc, double lo, double hi, int& f) {
        return gravity_.on ? slabExitTimeAccelerated(x, v, acc, lo, hi, f)
                           : slabExitTime(x, v, lo, hi, f);
    };
    double best = kNever;
    std::int8_t side = 0;
    // With walls the outer faces are never crossed (the wall comes first).
    int face;
    const CellList& cells = grid_.fine();
    double loX = cells.faceX(ac.kx) - grid_.skinX(), hiX = cells.faceX(ac.kx + 1) + grid_.skinX();
    double loY = cells.faceY(ac.ky) - grid_.skinY(), hiY = cells.faceY(ac.ky + 1) + grid_.skinY();
    if (grid_.periodic()) {
        // The box's own faces have no skin: a centre leaves the box only to wrap at once.
        if (ac.kx == 0) loX = 0.0;
        if (ac.kx == cells.nx() - 1) hiX = def_.width;
        if (ac.ky == 0) loY = 0.0;
        if (ac.ky == cells.ny() - 1) hiY = def_.height;
    }
    const double tx = exitTime(m.x, m.vx, m.ax, loX, hiX, face);
    const bool outerX =
        !cells.wraps() && ((face < 0 && ac.kx == 0) || (face > 0 && ac.kx == cells.nx() - 1));
    if (face != 0 && !outerX) {
        best = tx;
        side = face < 0 ? 0 : 1;
    }
    const double ty = exitTime(m.y, m.vy, m.ay, loY, hiY, face);
    const bool outerY =
        !cells.wraps() && ((face < 0 && ac.ky == 0) || (face > 0 && ac.ky == cells.ny() - 1));
    if (face != 0 && !outerY && ty < best) {
        best = ty;
        side = face < 0 ? 2 : 3;
    }
    cold_[i].cellSide = side;
    queue_.update(2 * i + 1, now + best);
}

void ExactStepper::scanNeighbours(std::uint32_t i, double now, double ax, double ay, Event& best) {
    const Cold& c = cold_[i];
    for (std::uint8_t l = 0; l < grid_.levelCount(); ++l) {
        const std::int64_t k = grid_.reach(c.level, l);
        scanBlock(i, now, ax, ay, l, c.kx - k, c.kx + k, c.ky - k, c.ky + k, best);
    }
}

void ExactStepper::scanBlock(std::uint32_t i, double now, double ax, double ay, std::uint8_t level,
                             std::int64_t x0, std::int64_t x1, std::int64_t y0, std::int64_t y1,
                             Event& best) {
    if (grid_.periodic()) {
        scanBlockPeriodic(i, now, ax, ay, level, x0, x1, y0, y1, best);
        return;
    }
    const CellList& list = grid_.listOf(level);
    constexpr int kCells = 16;
    std::uint32_t cells[kCells];
    int count = 0;
    grid_.forCells(level, x0, x1, y0, y1, [&](std::uint32_t c) {
        cells[count++] = c;
        if (count == kCells) {
            scanCells(i, now, ax, ay, list, cells, count, best);
            count = 0;
        }
    });
    if (count > 0) scanCells(i, now, ax, ay, list, cells, count, best);
}

void ExactStepper::scanBlockPeriodic(std::uint32_t i, double now, double ax, double ay,
                                     std::uint8_t level, std::int64_t x0, std::int64_t x1,
                                     std::int64_t y0, std::int64_t y1, Event& best) {
    // Fine cell coordinates past an edge are those of the other side, m boxes over: the piece
    // of the range in box (mx, my) is the cells [x - mx nx, ...] seen mx widths and my heights
    // away. Each piece lies within one box, so forCells never folds it onto itself.
    const CellList& fine = grid_.fine();
    const std::int64_t nx = fine.nx(), ny = fine.ny();
    const CellList& list = grid_.listOf(level);
    constexpr int kCells = 16;
    std::uint32_t cells[kCells];
    for (std::int64_t my = floorDiv(y0, ny); my <= floorDiv(y1, ny); ++my) {
        const std::int64_t ya = std::max(y0, my * ny) - my * ny;
        const std::int64_t yb = std::min(y1, my * ny + ny - 1) - my * ny;
        for (std::int64_t mx = floorDiv(x0, nx); mx <= floorDiv(x1, nx); ++mx) {
            const std::int64_t xa = std::max(x0, mx * nx) - mx * nx;
            const std::int64_t xb = std::min(x1, mx * nx + nx - 1) - mx * nx;
            const double sx = static_cast<double>(mx) * def_.width;
            const double sy = static_cast<double>(my) * def_.height;
            int count = 0;
            grid_.forCells(level, xa, xb, ya, yb, [&](std::uint32_t c) {
                cells[count++] = c;
                if (count == kCells) {
                    scanCells(i, now, ax - sx, ay - sy, list, cells, count, best, sx, sy);
                    count = 0;
                }
            });
            if (count > 0) scanCells(i, now, ax - sx, ay - sy, list, cells, count, best, sx, sy);
        }
    }
}

void ExactStepper::scanCells(std::uint32_t i, double now, double ax, double ay,
                             const CellList& list, const std::uint32_t* cells, int cellCount,
                             Event& best, double sx, double sy) {
    const Body& a = bodies_[i];
    const bool aHeld = (a.flags & kHeld) != 0, aJammed = (a.flags & kJammed) != 0;
    Motion am = gravity_.on ? motionAt(i, a, now) : Motion{};
    // Seen from the members' images: i moved the other way (x − 0 is x, bit for bit).
    am.x -= sx;
    am.y -= sy;
    // Gather the members first and prefetch their bodies, so that the cache misses of a whole
    // neighbourhood overlap instead of following one another.
    constexpr int kBatch = 32;
    std::uint32_t members[kBatch];
    int k = 0;
    std::uint32_t j = CellList::kNone;
    for (;;) {
        int count = 0;
        while (count < kBatch) {
            if (j == CellList::kNone) {
                if (k == cellCount) break;
                j = list.head(cells[k++]);
                continue;
            }
            // In a periodic box i's own images are no partners either.
            if (j != i) {
                members[count++] = j;
                __builtin_prefetch(&bodies_[j]);
            }
            j = list.next(j);
        }
        for (int m = 0; m < count; ++m) {
            const std::uint32_t q = members[m];
            const Body& b = bodies_[q];
            const bool bHeld = (b.flags & kHeld) != 0;
            // Held particles pass through each other, and through a pinned one (kPinned).
            if ((a.flags & kImmovable) && (b.flags & kImmovable)) continue;
            if ((aJammed && bHeld) || (aHeld && (b.flags & kJammed))) continue;
            const double h = now - b.t;
            Motion bm{};
            double rx, ry;
            if (gravity_.on) {
                bm = motionAt(q, b, now);
                rx = bm.x - am.x;
                ry = bm.y - am.y;
            } else {
                rx = b.x + b.vx * h - ax;
                ry = b.y + b.vy * h - ay;
            }
            double sigma = a.r + b.r;
            if (a.flags & b.flags & kPlacedOverlapping)
                sigma = placed_.contactDistance(order_[i], order_[q], rx, ry, sigma);
            const double t =
                now + (gravity_.on ? pairTimeUnderGravity(a, am, b, bm, sigma,
                                                          std::min(best.time, b.nextColl) - now)
                                   : pairImpactTime(rx, ry, b.vx - a.vx, b.vy - a.vy, sigma));
            // Only a collision before q's own scheduled collision can happen as predicted: at
            // that time q changes course or is predicted again against everything around it,
            // i included (Smallenburg 2022). Skipping later ones saves stale events.
            if (!(t < b.nextColl)) continue;
            if (t < best.time || (t == best.time && best.kind == Kind::Pair && q < best.partner)) {
                best = {t, q, b.count, Kind::Pair, 0};
            }
        }
        if (count < kBatch) return;
    }
}

double ExactStepper::pairTimeUnderGravity(const Body& a, const Motion& am, const Body& b,
                                          const Motion& bm, double sigma, double horizon) {
    if (isStatic(a) && isStatic(b)) return kNever;
    const double rx = bm.x - am.x, ry = bm.y - am.y;
    const double dvx = bm.vx - am.vx, dvy = bm.vy - am.vy;
    const double rax = bm.ax - am.ax, ray = bm.ay - am.ay;
    // Falling alike: a straight line relative to each other. Particles that fall together (a
    // pile woken by a rebuild, a stack dropped as one) move at the same velocity to rounding;
    // the direction of a relative velocity made of rounding is noise, so such a pair is at rest
    // relative to each other, not approaching.
    if (rax == 0.0 && ray == 0.0) {
        const double dv2 = dvx * dvx + dvy * dvy;
        const double v2 = am.vx * am.vx + am.vy * am.vy + bm.vx * bm.vx + bm.vy * bm.vy;
        if (dv2 <= kRoundingVelocity * kRoundingVelocity * v2) return kNever;
        return pairImpactTime(rx, ry, dvx, dvy, sigma);
    }
    return parabolicPairImpactTime(rx, ry, dvx, dvy, rax, ray, sigma, horizon);
}

void ExactStepper::handleCell(std::uint32_t i, double now) {
    Cold& a = cold_[i];
    ++events_;
    const std::int8_t side = a.cellSide;  // predictCell below overwrites it
    if (const int boxes = grid_.move(i, a, side); boxes != 0) {
        // Across an edge of a periodic box: the centre wraps to the other side.
        Body& w = bodies_[i];
        if (side < 2) {
            const double shift = boxes * def_.width;
            w.x += shift;
            unwrapX_[i] -= shift;
        } else {
            const double shift = boxes * def_.height;
            w.y += shift;
            unwrapY_[i] -= shift;
        }
    }
    predictCell(i, now);

    // The cells that just came within reach at each level: the far column (or row) in the
    // direction of motion (for two of level 0, the three cells that just came into i's 3 × 3
    // neighbourhood). Everything else within reach was searched by i's last full prediction,
    // whose earliest result is still scheduled, so only these can bring an earlier event.
    const Body& b = bodies_[i];
    const double h = now - b.t;
    double ax = b.x + b.vx * h, ay = b.y + b.vy * h;
    Motion m{ax, ay, b.vx, b.vy, 0.0, 0.0};
    if (gravity_.on) {
        m = motionAt(i, b, now);
        ax = m.x;
        ay = m.y;
    }
    Event best = a.coll;
    for (std::uint8_t l = 0; l < grid_.levelCount(); ++l) {
        const std::int64_t k = grid_.reach(a.level, l);
        switch (side) {
            case 0:
                scanBlock(i, now, ax, ay, l, a.kx - k, a.kx - k, a.ky - k, a.ky + k, best);
                break;
            case 1:
                scanBlock(i, now, ax, ay, l, a.kx + k, a.kx + k, a.ky - k, a.ky + k, best);
                break;
            case 2:
                scanBlock(i, now, ax, ay, l, a.kx - k, a.kx + k, a.ky - k, a.ky - k, best);
                break;
            default:
                scanBlock(i, now, ax, ay, l, a.kx - k, a.kx + k, a.ky + k, a.ky + k, best);
                break;
        }
    }
    // The new cell's obstacles (the old cell's are in a.coll already, or later than it).
    if (!obstacles_.empty()) predictObstacles(i, m, now, best);
    if (best.time < a.coll.time) {
        a.coll = best;
        bodies_[i].nextColl = best.time;
        queue_.update(2 * i, best.time);
    }
}

}  // namespace psb::exact
