// The obstacles stage of the discrete step (see discrete_step.hpp): particles against fixed
// pegs and segments.
//
// Per particle, with p0 its centre at the start of the step and p1 where the earlier stages
// left it:
//
//   0. The free disc. Each storage slot keeps a disc that no obstacle's surface and (with walls)
//      no wall enters, made where its particle last needed the steps below (the grid's
//      clearance there, obstacle_grid.hpp). A particle with p0 and p1 inside that disc, shrunk
//      by its radius, sweeps through free space: it can touch nothing and the wall stage will
//      not move it, so the steps below would leave it as it is, and it stops here. This is a
//      fact about the obstacles and the box, whichever particle the slot holds, so it can only
//      make the stage faster, never change what it does; the discs are dropped when the
//      obstacles or the box change, and move with their particles when storage is reordered.
//      Away from the obstacles a particle needs a new disc only every few hundred steps; the
//      test is made for runs of particles at a time, without a branch per particle.
//   1. Candidates. A particle with no obstacle surface within r + |p1 − p0| of p1 can touch
//      none this step and stops here: the grid (obstacle_grid.hpp) decides that with one
//      lookup, of the cell that holds p1, whenever that reach is within its pad (nearly always).
//      The others take every obstacle within 2r + |p1 − p0| of p1 (the wider ring guards the
//      pushes below against crossing a core) from a box query, filtered by exact distance, so
//      the candidates never depend on the grid's layout.
//   2. Sweep. A particle that does not touch an obstacle at p0 but whose straight move would
//      pass into it is stopped at the first contact (the earliest time of impact along the
//      move, obstacle_time_of_impact.hpp) and rebounds there. The rest of its move, without
//      the part into the obstacle, goes on along the surface from there, swept the same way
//      (up to kSlides times; what is left after the last contact is given up). So no speed
//      and no step, however large, carries a particle through a peg or a segment, and a
//      particle pressed onto a slope slides down it.
//   3. Overlaps. Up to kPasses passes over the candidates in ascending index: each obstacle the
//      particle overlaps pushes it out along the normal from its nearest core point (for a
//      segment, toward the side the particle started the step on, even if it has since crossed
//      the core line) and turns its velocity into it around (reboundOffWall, the walls' law).
//      With walls on, every push is clamped into the box.
//
// Caught between two obstacles (a gap narrower than the particle, or an obstacle against a
// wall): a push that would carry the centre across the core line of another segment is not
// made. The particle then stays where it is, overlapping both a little, its velocity into each
// turned around; it never passes through either, and it never leaves the box.
//
// Held (kinematic) particles are pushed out like the others but keep their owner's velocity.
// Each particle is handled on its own against obstacles that never move, so the stage runs in
// parallel blocks; the collision count is summed per block in block order (parallel.hpp).

#include <algorithm>
#include <array>
#include <cmath>
#include <span>

#include "contact/collision_capture.hpp"
#include "contact/contact.hpp"
#include "discrete/discrete_step.hpp"
#include "obstacles/obstacle_geometry.hpp"
#include "obstacles/obstacle_time_of_impact.hpp"
#include "support/parallel.hpp"

namespace psb::stages {
namespace {

constexpr int kPasses = 4;
constexpr int kSlides = 2;  ///< slides along obstacles after a sweep's first contact
/// (1 + 10⁻¹²)²: a centre this close to an obstacle's contact distance touches it, so that a
/// ball left exactly in contact (to rounding) is not met again at time 0 by a move along it.
constexpr double kTouching = (1.0 + 1e-12) * (1.0 + 1e-12);
/// A move heads into a touched obstacle when its cosine with the inward normal is above this:
/// a slide along it (its inward part removed, to rounding) does not.
constexpr double kInward = 1e-9;

/// The particle's state while the stage works on it.
struct Body {
    double x, y, vx, vy, r, m;
    bool held;
    double omega = 0.0, q = 0.0;  ///< angular velocity and spin weight, read when kRough
};

/// What one particle's contacts did: obstacle rebounds, and the wall rebounds the stage made
/// itself (count and impulse, kg·m/s) for a particle it pushed while it was past a wall.
struct Hits {
    std::uint64_t obstacles = 0, walls = 0;
    double wallImpulse = 0.0;
    std::uint32_t lastObstacle = 0;  ///< the index of the last obstacle rebounded off
};

/// Turns the velocity's component into the obstacle (along -n, n the outward unit normal)
/// around with the walls' law. Returns whether it rebounded.
template <bool kFriction, bool kRough>
bool rebound(Body& b, double nx, double ny, const RoughLaws& laws) {
    if (b.held) return false;
    if constexpr (kRough) {
        return roughReboundOffSurface(b.vx, b.vy, {b.omega, b.r, b.q}, nx, ny, laws) > 0.0;
    } else {
        return reboundOffSurface<kFriction>(b.vx, b.vy, nx, ny, laws.e, laws.mu) > 0.0;
    }
}

/// Brings a centre into the box as the wall stage does: into [r, extent − r] on each axis, or
/// to the middle of an axis narrower than the disc.
void clampIntoBox(double& x, double& y, double r, const WorldDef& def) {
    x = std::clamp(x, std::min(r, 0.5 * def.width), std::max(def.width - r, 0.5 * def.width));
    y = std::clamp(y, std::min(r, 0.5 * def.height), std::max(def.height - r, 0.5 * def.height));
}

/// The outward unit normal at (x, y) for obstacle o, the particle having started the step at
/// (x0, y0). Writes the distance the centre must move along it to just touch (> 0 when
/// overlapping) to `depth`.
void contactNormal(const Obstacle& o, double x, double y, double r, double x0, double y0,
                   double& nx, double& ny, double& depth) {
    double qx, qy;
    nearestCorePoint(o, x, y, qx, qy);
    double dx = x - qx, dy = y - qy;
    double dist = std::sqrt(dx * dx + dy * dy);
    if (!o.isPeg()) {
        // A centre that crossed the core line during this step goes back to its own side.
        const double s0 = sideOf(o, x0, y0);
        if (crossesCore(o, x0, y0, x, y) || (dist == 0.0 && s0 != 0.0)) {
            const double ex = o.b.x() - o.a.x(), ey = o.b.y() - o.a.y();
            const double len = std::sqrt(ex * ex + ey * ey);
            const double sign = s0 >= 0.0 ? 1.0 : -1.0;
            nx = -ey / len * sign;
            ny = ex / len * sign;
            // Through the line and out by r + h on the starting side.
            const double signedDist = dx * nx + dy * ny;  // < 0 on the wrong side
            depth = r + o.radius - signedDist;
            return;
        }
    }
    if (dist > 0.0) {
        nx = dx / dist;
        ny = dy / dist;
    } else {
        // A centre exactly on a peg's centre (or on a segment's core from the start): back the
        // way it came, or up when it did not move.
        const double bx = x0 - x, by = y0 - y, back = std::sqrt(bx * bx + by * by);
        if (back > 0.0) {
            nx = bx / back;
            ny = by / back;
        } else {
            nx = 0.0;
            ny = -1.0;
        }
    }
    depth = r + o.radius - dist;
}

template <bool kFriction, bool kRough>
void collideOne(Body& b, double x0, double y0, const Obstacles& obstacles,
                const std::vector<std::uint32_t>& candidates, const WorldDef& def, Hits& out) {
    const double e = def.restitution, mu = def.friction;
    const RoughLaws laws{e, mu, def.tangentialRestitution};
    std::uint64_t hits = 0;

    // 2. The sweep: the earliest contact along p0 -> p1 with an obstacle not touched at p0. With
    // walls on, p1 is first brought into the box as the wall stage will bring it: a move that
    // leaves the box must not pass around the end of a segment that reaches the wall, outside.
    // (leftX, leftY): where the earlier stages left it; (x1, y1): where the wall stage will put
    // it.
    const double leftX = b.x, leftY = b.y;
    double x1 = b.x, y1 = b.y;
    if (def.walls) clampIntoBox(x1, y1, b.r, def);
    const double mx = x1 - x0, my = y1 - y0;
    bool moved = false;  // by this stage
    // The move is followed from contact to contact: at each, the rest of the move loses its
    // part into the obstacle and goes on along it (a ball on a slope slides down it instead of
    // giving up its move every step). The candidates cover a ring of 2r + |move| around p1: the
    // first slide ends within |move| of p1, later ones within 2 |move|, so a second slide is
    // made only when |move| <= r. What is left after the last slide is given up.
    const double moveLength = std::sqrt(mx * mx + my * my);
    const int slides = moveLength <= b.r ? kSlides : 1;
    double sx = x0, sy = y0, dx = mx, dy = my;
    for (int leg = 0; leg <= slides && (dx != 0.0 || dy != 0.0); ++leg) {
        double first = exact::kNever;
        std::uint32_t hit = UINT32_MAX;
        for (const std::uint32_t k : candidates) {
            const Obstacle& o = obstacles[k];
            double qx, qy;
            nearestCorePoint(o, sx, sy, qx, qy);
            const double sigma = b.r + o.radius;
            const double ox = sx - qx, oy = sy - qy, d2 = ox * ox + oy * oy;
            double t;
            if (d2 < sigma * sigma * kTouching) {
                // Touching (to rounding) or inside: met at once if the move heads into it,
                // else the overlap pass below deals with it.
                const double into = -(dx * ox + dy * oy);
                if (!(d2 > 0.0) || !(into > kInward * std::sqrt(d2 * (dx * dx + dy * dy))))
                    continue;
                t = 0.0;
            } else {
                t = exact::obstacleImpactTime(sx, sy, dx, dy, b.r, o);
            }
            if (t < first) {
                first = t;
                hit = k;
            }
        }
        if (!(first <= 1.0)) {
            if (moved) {  // the last slide is free
                b.x = sx + dx;
                b.y = sy + dy;
            }
            break;
        }
        b.x = sx + first * dx;
        b.y = sy + first * dy;
        moved = true;
        double nx, ny, depth;
        contactNormal(obstacles[hit], b.x, b.y, b.r, x0, y0, nx, ny, depth);
        if (rebound<kFriction, kRough>(b, nx, ny, laws)) {
            ++hits;
            out.lastObstacle = hit;
        }
        if (leg == slides) break;
        // The rest of the move, without its part into the obstacle.
        double rx = (1.0 - first) * dx, ry = (1.0 - first) * dy;
        const double into = rx * nx + ry * ny;
        if (into < 0.0) {
            rx -= into * nx;
            ry -= into * ny;
        }
        // Kept in the box as the move's end was, for the same reason.
        double ex = b.x + rx, ey = b.y + ry;
        if (def.walls) clampIntoBox(ex, ey, b.r, def);
        sx = b.x;
        sy = b.y;
        dx = ex - sx;
        dy = ey - sy;
    }

    // 3. Overlaps, pushed out one obstacle at a time, never across another's core. With walls
    // on, a particle past a wall is judged where the wall stage will put it, so that the wall's
    // clamp cannot push it into an obstacle afterwards (a ball pressed below the floor next to a
    // wall standing on it).
    if (!moved) {
        b.x = x1;
        b.y = y1;
    }
    for (int pass = 0; pass < kPasses; ++pass) {
        bool pushed = false;
        for (const std::uint32_t k : candidates) {
            const Obstacle& o = obstacles[k];
            double nx, ny, depth;
            contactNormal(o, b.x, b.y, b.r, x0, y0, nx, ny, depth);
            if (!(depth > 0.0)) continue;
            double x = b.x + depth * nx, y = b.y + depth * ny;
            if (def.walls) clampIntoBox(x, y, b.r, def);
            bool blocked = false;
            for (const std::uint32_t other : candidates) {
                if (other != k && crossesCore(obstacles[other], b.x, b.y, x, y)) {
                    blocked = true;
                    break;
                }
            }
            if (!blocked && (x != b.x || y != b.y)) {
                b.x = x;
                b.y = y;
                moved = pushed = true;
            }
            if (rebound<kFriction, kRough>(b, nx, ny, laws)) {
                ++hits;
                out.lastObstacle = k;
            }
        }
        if (!pushed) break;
    }
    if (!moved) {
        // Nothing moved it: the wall stage clamps it and turns it around as usual.
        b.x = leftX;
        b.y = leftY;
    } else if (!b.held && (leftX != x1 || leftY != y1)) {
        // It was past a wall and this stage moved it inside, where the wall stage will not see
        // it: the wall's rebound, by the wall stage's law, is made here.
        auto wall = [&](double& v, double& vt, double outward, double tSign) {
            double outwardSpeed = outward * v;
            double dv;
            if constexpr (kRough) {
                // The wall's outward normal is −outward along the axis; its tangent is
                // −outward · tSign times the other axis (roughWallAxis in discrete_walls.cpp).
                dv = reboundOffWall<false>(outwardSpeed, vt, e, 0.0);
                if (dv > 0.0) {
                    const double sign = -outward * tSign;
                    double along = sign * vt;
                    roughAlongSurface(along, {b.omega, b.r, b.q}, dv, mu,
                                      def.tangentialRestitution);
                    vt = sign * along;
                }
            } else {
                dv = reboundOffWall<kFriction>(outwardSpeed, vt, e, mu);
            }
            v = outward * outwardSpeed;
            if (dv > 0.0) {
                ++out.walls;
                out.wallImpulse += b.m * dv;
            }
        };
        if (leftX != x1) wall(b.vx, b.vy, leftX > x1 ? 1.0 : -1.0, 1.0);
        if (leftY != y1) wall(b.vy, b.vx, leftY > y1 ? 1.0 : -1.0, -1.0);
    }
    out.obstacles += hits;
}

/// Sets slot i's free disc around (x, y): as wide as the grid's clearance there and, with walls,
/// inside the box; less a hair (relative to the distances and coordinates involved) so that
/// rounding never lets a move inside it graze an obstacle or a wall. Kept in single precision,
/// half the memory: the centre is rounded, and the radius shrunk by the rounding and rounded
/// down, so that the stored disc lies inside the exact one. None for a point that is not
/// finite.
void setFreeDisc(StepContext& ctx, std::size_t i, const ObstacleGrid& grid, const WorldDef& def,
                 double x, double y) {
    ctx.freeX[i] = ctx.freeY[i] = 0.0f;
    ctx.freeRadius[i] = -1.0f;
    if (!std::isfinite(x) || !std::isfinite(y)) return;
    double clearance = grid.clearance(x, y);
    if (def.walls) clearance = std::min({clearance, x, def.width - x, y, def.height - y});
    const float cx = static_cast<float>(x), cy = static_cast<float>(y);
    const double shift = std::sqrt((x - cx) * (x - cx) + (y - cy) * (y - cy));
    const double radius = clearance * (1.0 - 1e-9) - 1e-9 * (std::abs(x) + std::abs(y)) - shift;
    float r = static_cast<float>(radius);
    if (static_cast<double>(r) > radius) r = std::nextafter(r, -INFINITY);
    if (!std::isfinite(cx) || !std::isfinite(cy) || !(r >= 0.0f)) return;
    ctx.freeX[i] = cx;
    ctx.freeY[i] = cy;
    ctx.freeRadius[i] = r;
}

/// The grid's pad: a quarter more than the particles' mean reach (radius plus this step's
/// move), so that nearly every particle needs one cell lookup. Only speed depends on it.
double choosePad(const ParticleArrays& p, const StepContext& ctx, bool haveStart) {
    double sum = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const double mx = haveStart ? p.x[i] - ctx.startX[i] : 0.0;
        const double my = haveStart ? p.y[i] - ctx.startY[i] : 0.0;
        const double reach = p.radius[i] + std::sqrt(mx * mx + my * my);
        if (std::isfinite(reach)) sum += reach;
    }
    return p.size() > 0 ? 1.25 * sum / static_cast<double>(p.size()) : 0.0;
}

template <bool kFriction, bool kRough>
void obstaclesImpl(ParticleArrays& p, const WorldDef& def, StepContext& ctx,
                   StepCounters& counters) {
    const std::size_t n = p.size();
    const bool haveStart = ctx.startX.size() == n;
    // (Re)build for new obstacles, or when more than one particle in eight needed a box query
    // last step and a pad chosen now would be clearly wider.
    std::uint64_t fallbacks = 0;
    for (const std::uint64_t f : ctx.obstacleFallbackScratch)
        fallbacks += f;
    if (!ctx.obstacleGrid.builtFor(def.obstacles)) {
        ctx.obstacleGrid.build(def.obstacles, choosePad(p, ctx, haveStart));
        ctx.freeRadius.clear();  // facts about the obstacles there were
    } else if (8 * fallbacks > n) {
        const double pad = choosePad(p, ctx, haveStart);
        if (pad > 1.5 * ctx.obstacleGrid.pad()) ctx.obstacleGrid.build(def.obstacles, pad);
    }
    const ObstacleGrid& grid = ctx.obstacleGrid;
    const double pad = grid.pad();
    const double maxRadius = grid.maxRadius();
    const Obstacles& obstacles = def.obstacles;
    const std::size_t blocks = parallel::blockCount(n);
    ctx.obstacleCandidates.resize(blocks);
    ctx.obstacleNearby.resize(blocks);
    ctx.obstacleHitScratch.resize(blocks);
    ctx.obstacleWallHitScratch.resize(blocks);
    ctx.obstacleWallImpulseScratch.resize(blocks);
    ctx.obstacleFallbackScratch.assign(blocks, 0);
    // Recorded per block and appended in block order (parallel.hpp), one record per particle
    // the stage turned: its velocity before and after all it did.
    const bool record = ctx.collisionLog != nullptr;
    if (record) ctx.collisionScratch.resize(blocks);
    // The free discs keep clear of the walls of the box they were made in.
    if (ctx.freeBox != std::array{def.width, def.height, def.walls ? 1.0 : 0.0}) {
        ctx.freeRadius.clear();
        ctx.freeBox = {def.width, def.height, def.walls ? 1.0 : 0.0};
    }
    ctx.freeX.resize(n);
    ctx.freeY.resize(n);
    ctx.freeRadius.resize(n, -1.0f);
    parallel::forBlocks(ctx.threads, n, [&](std::size_t blk, std::size_t begin, std::size_t end) {
        std::vector<std::uint32_t>& candidates = ctx.obstacleCandidates[blk];
        std::vector<std::uint32_t>& nearby = ctx.obstacleNearby[blk];
        Hits hits;
        std::uint64_t boxQueries = 0;
        if (record) ctx.collisionScratch[blk].clear();
        // Particle i against the obstacles near it, steps 1 to 3 above.
        auto contact = [&](std::size_t i, double x0, double y0) {
            // 1. Candidates.
            const double x1 = p.x[i], y1 = p.y[i];
            const double r = p.radius[i];
            const double mx = x1 - x0, my = y1 - y0, move2 = mx * mx + my * my;
            const double slack = pad - r;
            double move = 0.0;  // |p1 − p0|, worked out only once an obstacle is near
            // Whether an obstacle lies within r + move of p1: one the move or an overlap can
            // touch. Nearly always decided by the one cell that holds p1.
            auto touches = [&](std::uint32_t k) {
                const Obstacle& o = obstacles[k];
                double qx, qy;
                nearestCorePoint(o, x1, y1, qx, qy);
                const double d2 = (x1 - qx) * (x1 - qx) + (y1 - qy) * (y1 - qy);
                const double touch = o.radius + r + move;
                return d2 < touch * touch;
            };
            if (slack >= 0.0 && move2 <= slack * slack) {
                const std::span<const std::uint32_t> listed = grid.cellAt(x1, y1);
                if (listed.empty()) return;
                move = std::sqrt(move2);
                if (std::none_of(listed.begin(), listed.end(), touches)) return;
            } else {
                move = std::sqrt(move2);
                ++boxQueries;
            }
            // The candidates: every obstacle within 2r + move of p1 (the ones within r more
            // guard the pushes against crossing a core). Each is listed in a cell within its
            // radius of that distance, which the box below covers.
            const double h = maxRadius + 2.0 * r + move;
            grid.query(x1 - h, y1 - h, x1 + h, y1 + h, nearby);
            candidates.clear();
            bool touchable = false;
            for (const std::uint32_t k : nearby) {
                const Obstacle& o = obstacles[k];
                double qx, qy;
                nearestCorePoint(o, x1, y1, qx, qy);
                const double d2 = (x1 - qx) * (x1 - qx) + (y1 - qy) * (y1 - qy);
                const double guard = o.radius + 2.0 * r + move;
                if (d2 < guard * guard) {
                    candidates.push_back(k);
                    touchable = touchable || touches(k);
                }
            }
            if (!touchable) return;
            Body b{x1, y1, p.vx[i], p.vy[i], r, p.mass[i], p.invMass[i] == 0.0};
            if constexpr (kRough) {
                b.omega = p.omega[i];
                b.q = p.spinWeight(i);
            }
            const std::uint64_t obstacleHits = hits.obstacles, wallHits = hits.walls;
            collideOne<kFriction, kRough>(b, x0, y0, obstacles, candidates, def, hits);
            if (record && (hits.obstacles != obstacleHits || hits.walls != wallHits)) {
                // An obstacle's record when one turned it, else the wall's this stage made.
                const bool obstacle = hits.obstacles != obstacleHits;
                std::uint32_t where = hits.lastObstacle;
                if (!obstacle) {
                    const double outX = x1 < r ? -1.0 : (x1 > def.width - r ? 1.0 : 0.0);
                    where = static_cast<std::uint32_t>(
                        outX != 0.0 ? (outX < 0.0 ? WallSide::Left : WallSide::Right)
                                    : (y1 < r ? WallSide::Top : WallSide::Bottom));
                }
                ctx.collisionScratch[blk].push_back(surfaceCollision(
                    ctx.collisionTime, obstacle ? Collision::With::Obstacle : Collision::With::Wall,
                    where, p.id[i], Vec2(p.vx[i], p.vy[i]), Vec2(b.vx, b.vy), p.mass[i]));
            }
            p.x[i] = b.x;
            p.y[i] = b.y;
            p.vx[i] = b.vx;
            p.vy[i] = b.vy;
            if constexpr (kRough) p.omega[i] = b.omega;
        };
        const double* sx = haveStart ? ctx.startX.data() : p.x.data();
        const double* sy = haveStart ? ctx.startY.data() : p.y.data();
        const double* px = p.x.data();
        const double* py = p.y.data();
        const double* pr = p.radius.data();
        const float* fx = ctx.freeX.data();
        const float* fy = ctx.freeY.data();
        const float* fr = ctx.freeRadius.data();
        // 0. The free disc: a particle that starts and ends the step inside its slot's free
        // disc sweeps through a disc that no obstacle and no wall enters, and so touches none and
        // is left alone by the wall stage. Its margin, the least of the room left on those
        // conditions, is then >= 0. (A margin can lose a NaN; a particle at a position that is
        // not a number is one the stage below leaves alone anyway.)
        auto margin = [=](std::size_t i) {
            const double x0 = sx[i], y0 = sy[i], x1 = px[i], y1 = py[i];
            const double cx = fx[i], cy = fy[i], room = fr[i] - pr[i];
            const double d0 = (x0 - cx) * (x0 - cx) + (y0 - cy) * (y0 - cy);
            const double d1 = (x1 - cx) * (x1 - cx) + (y1 - cy) * (y1 - cy);
            // The branch-free min and max (a < b ? a : b) let the compiler test several at once.
            const double m = room * room - (d0 > d1 ? d0 : d1);
            return m < room ? m : room;
        };
        // A particle that left its disc gets a new one where it is now; a particle far from
        // every obstacle is then inside it and needs nothing more.
        auto visit = [&](std::size_t i) {
            const double x1 = px[i], y1 = py[i];
            setFreeDisc(ctx, i, grid, def, x1, y1);
            if (margin(i) >= 0.0) return;
            contact(i, sx[i], sy[i]);
            if (px[i] != x1 || py[i] != y1) setFreeDisc(ctx, i, grid, def, px[i], py[i]);
        };
        // Nearly every particle away from the obstacles has a margin >= 0: work out runs of kRun
        // margins at a time, without a branch, and look at each particle of a run only if the
        // least of them is < 0 (as the wall stage does).
        constexpr std::size_t kRun = 16;
        std::size_t i = begin;
        for (; i + kRun <= end; i += kRun) {
            double m[kRun];
            for (std::size_t k = 0; k < kRun; ++k)
                m[k] = margin(i + k);
            double least = m[0];
            for (std::size_t k = 1; k < kRun; ++k)
                least = least < m[k] ? least : m[k];
            if (least >= 0.0) continue;
            for (std::size_t k = 0; k < kRun; ++k)
                if (!(m[k] >= 0.0)) visit(i + k);
        }
        for (; i < end; ++i)
            if (!(margin(i) >= 0.0)) visit(i);
        ctx.obstacleHitScratch[blk] = hits.obstacles;
        ctx.obstacleWallHitScratch[blk] = hits.walls;
        ctx.obstacleWallImpulseScratch[blk] = hits.wallImpulse;
        ctx.obstacleFallbackScratch[blk] = boxQueries;
    });
    for (std::size_t b = 0; b < blocks; ++b) {
        counters.obstacleCollisions += ctx.obstacleHitScratch[b];
        counters.wallCollisions += ctx.obstacleWallHitScratch[b];
        counters.wallImpulse += ctx.obstacleWallImpulseScratch[b];
        if (record) {
            for (const Collision& c : ctx.collisionScratch[b])
                ctx.collisionLog->add(c);
        }
    }
}

}  // namespace

void saveStartPositions(const ParticleArrays& p, StepContext& ctx) {
    ctx.startX.assign(p.x.begin(), p.x.end());
    ctx.startY.assign(p.y.begin(), p.y.end());
}

void obstacles(ParticleArrays& p, const WorldDef& def, StepContext& ctx, StepCounters& counters) {
    if (def.friction > 0.0 && p.rotation) {
        obstaclesImpl<true, true>(p, def, ctx, counters);
    } else if (def.friction > 0.0) {
        obstaclesImpl<true, false>(p, def, ctx, counters);
    } else {
        obstaclesImpl<false, false>(p, def, ctx, counters);
    }
}

}  // namespace psb::stages
