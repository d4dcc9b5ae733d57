// The wall stage of the discrete step (see discrete_step.hpp).

#include <algorithm>
#include <cmath>

#include "contact/collision_capture.hpp"
#include "contact/contact.hpp"
#include "discrete/discrete_step.hpp"
#include "support/parallel.hpp"

namespace psb::stages {
namespace {

/// One axis of one particle against the walls at 0 and `extent`. The wall sets the sign of the
/// velocity: a particle past a wall and moving outward is turned inward with speed e·|v|; one
/// already moving inward keeps its velocity (the original negated it, throwing it back out).
/// Returns the normal impulse per unit mass delivered (>= 0). `vt` is the other velocity
/// component, reduced by wall friction when kFriction.
template <bool kFriction>
inline double wallAxis(double& x, double& v, double& vt, double r, double extent, double e,
                       double mu) {
    const double lo = r, hi = extent - r;
    if (lo >= hi) {
        // As wide as the box or wider: it touches both walls at once, so the only place it can
        // be is the centre and the only velocity it can have along this axis is zero.
        x = 0.5 * extent;
        const double dv = std::abs(v);
        v = 0.0;
        if constexpr (kFriction) vt -= std::copysign(std::min(std::abs(vt), mu * dv), vt);
        return dv;
    }
    if (x < lo) {
        x = lo;
        double out = -v;  // the left/top wall's outward normal points to -x
        const double dv = reboundOffWall<kFriction>(out, vt, e, mu);
        v = -out;
        return dv;
    }
    if (x > hi) {
        x = hi;
        return reboundOffWall<kFriction>(v, vt, e, mu);
    }
    return 0.0;
}

/// wallAxis for a turning disc: the walls' law along the axis, then the rough tangential impulse
/// (contact.hpp) of the wall it hit. `vt` is the velocity component along the other axis and
/// `tSign` the sign that turns it into the component along the tangent t = (−n_y, n_x) of a
/// wall whose outward normal n points along +axis: +1 for the x axis, −1 for the y axis.
inline double roughWallAxis(double& x, double& v, double& vt, Spin s, double extent, double tSign,
                            const RoughLaws& laws) {
    const double before = v;
    const double dv = wallAxis<false>(x, v, vt, s.r, extent, laws.e, 0.0);
    if (dv == 0.0) return 0.0;
    // The wall hit: the low one (outward normal +axis) if it was moving toward it.
    const double side = before < 0.0 ? 1.0 : -1.0;
    // With n = side · axis the tangent t is side · tSign times the other axis.
    const double sign = side * tSign;
    double along = sign * vt;
    roughAlongSurface(along, s, dv, laws.mu, laws.beta);
    vt = sign * along;
    return dv;
}

template <bool kFriction, bool kRough>
void wallsImpl(ParticleArrays& p, const WorldDef& def, StepContext& ctx, StepCounters& counters) {
    const double e = def.restitution, mu = def.friction;
    const std::size_t n = p.size();
    // The impulse sum depends on the order of its terms: one sequential sum per fixed block,
    // added in block order below (rule 2 of parallel.hpp), so any thread count gives the same
    // bits.
    const std::size_t blocks = parallel::blockCount(n);
    ctx.wallImpulseScratch.resize(blocks);
    ctx.wallHitScratch.resize(blocks);
    // Recorded per block and appended in block order, as the sums are, so the log is the same
    // for any thread count.
    const bool record = ctx.collisionLog != nullptr;
    if (record) ctx.collisionScratch.resize(blocks);
    parallel::forBlocks(ctx.threads, n, [&](std::size_t b, std::size_t begin, std::size_t end) {
        if (record) ctx.collisionScratch[b].clear();
        std::uint64_t hits = 0;
        double impulse = 0.0;
        const double* px = p.x.data();
        const double* py = p.y.data();
        const double* pr = p.radius.data();
        const double w = def.width, h = def.height;
        // Nearly every particle is inside, where wallAxis changes nothing on either axis. Test
        // runs of 16 without a branch per particle and visit a run one by one only if one of
        // them is out.
        constexpr std::size_t kRun = 16;
        for (std::size_t run = begin; run < end; run += kRun) {
            const std::size_t runEnd = std::min(end, run + kRun);
            // Inside on both axes <=> every margin below is >= 0 and the box is wider than
            // the disc (the same comparisons wallAxis makes, as differences folded with min).
            double margin = 1.0, room = 1.0;
            for (std::size_t i = run; i < runEnd; ++i) {
                const double r = pr[i], wr = w - r, hr = h - r;
                double a = px[i] - r, b2 = wr - px[i], c = py[i] - r, d = hr - py[i];
                double f = wr - r, g = hr - r;
                a = a < b2 ? a : b2;
                c = c < d ? c : d;
                a = a < c ? a : c;
                f = f < g ? f : g;
                margin = margin < a ? margin : a;
                room = room < f ? room : f;
            }
            const bool outside = !((margin >= 0.0) & (room > 0.0));
            if (!outside) continue;
            for (std::size_t i = run; i < runEnd; ++i) {
                const double r = pr[i];
                if (p.invMass[i] == 0.0) {
                    // A held particle is clamped into the box but its velocity is its owner's.
                    double vx = 0.0, vy = 0.0, vt = 0.0;
                    wallAxis<false>(p.x[i], vx, vt, r, def.width, e, mu);
                    wallAxis<false>(p.y[i], vy, vt, r, def.height, e, mu);
                    continue;
                }
                const Vec2 before(p.vx[i], p.vy[i]);
                double jx, jy;
                Vec2 between;
                if constexpr (kRough) {
                    const Spin s{p.omega[i], r, p.spinWeight(i)};
                    const RoughLaws laws{e, mu, def.tangentialRestitution};
                    jx = roughWallAxis(p.x[i], p.vx[i], p.vy[i], s, def.width, 1.0, laws);
                    between = Vec2(p.vx[i], p.vy[i]);
                    jy = roughWallAxis(p.y[i], p.vy[i], p.vx[i], s, def.height, -1.0, laws);
                } else {
                    jx = wallAxis<kFriction>(p.x[i], p.vx[i], p.vy[i], r, def.width, e, mu);
                    between = Vec2(p.vx[i], p.vy[i]);
                    jy = wallAxis<kFriction>(p.y[i], p.vy[i], p.vx[i], r, def.height, e, mu);
                }
                if (jx > 0.0 || jy > 0.0) {
                    hits += (jx > 0.0) + (jy > 0.0);
                    impulse += p.mass[i] * (jx + jy);
                    if (record) {
                        // The wall hit is the one the particle was moving towards; a corner is
                        // two records, x's rebound first.
                        const Vec2 after(p.vx[i], p.vy[i]);
                        auto wall = [&](WallSide low, WallSide high, double v, const Vec2& from,
                                        const Vec2& to) {
                            const WallSide side = v < 0.0 ? low : high;
                            ctx.collisionScratch[b].push_back(surfaceCollision(
                                ctx.collisionTime, Collision::With::Wall,
                                static_cast<std::uint32_t>(side), p.id[i], from, to, p.mass[i]));
                        };
                        if (jx > 0.0)
                            wall(WallSide::Left, WallSide::Right, before.x(), before, between);
                        if (jy > 0.0)
                            wall(WallSide::Top, WallSide::Bottom, between.y(), between, after);
                    }
                }
            }
        }
        ctx.wallHitScratch[b] = hits;
        ctx.wallImpulseScratch[b] = impulse;
    });
    std::uint64_t hits = 0;
    double impulse = 0.0;
    for (std::size_t b = 0; b < blocks; ++b) {
        hits += ctx.wallHitScratch[b];
        impulse += ctx.wallImpulseScratch[b];
    }
    counters.wallCollisions += hits;
    counters.wallImpulse += impulse;
    if (record) {
        for (std::size_t b = 0; b < blocks; ++b) {
            for (const Collision& c : ctx.collisionScratch[b])
                ctx.collisionLog->add(c);
        }
    }
}

}  // namespace

void walls(ParticleArrays& p, const WorldDef& def, StepContext& ctx, StepCounters& counters) {
    if (def.friction > 0.0 && p.rotation) {
        wallsImpl<true, true>(p, def, ctx, counters);
    } else if (def.friction > 0.0) {
        wallsImpl<true, false>(p, def, ctx, counters);
    } else {
        wallsImpl<false, false>(p, def, ctx, counters);
    }
}

}  // namespace psb::stages
