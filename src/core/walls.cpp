// The wall stage of the discrete step (see discrete_step.hpp).

#include <algorithm>
#include <cmath>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "contact.hpp"
#include "discrete_step.hpp"
#include "parallel.hpp"

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

/// Whether any particle of [begin, end) may be outside the box (or as wide as it) on either
/// axis: the comparisons wallAxis makes, negated so that a NaN counts as outside. Nearly every
/// run is inside, so this test is the wall stage's whole cost; GCC does not vectorise the
/// boolean reduction for baseline x86-64, hence SSE2 (part of every x86-64) two particles at a
/// time, with the same test in scalar form for the tail and for other machines.
bool anyOutside(const ParticleArrays& p, const WorldDef& def, std::size_t begin, std::size_t end) {
    const double* px = p.x.data();
    const double* py = p.y.data();
    const double* pr = p.radius.data();
    const double w = def.width, h = def.height;
    std::size_t i = begin;
    bool out = false;
#if defined(__SSE2__)
    const __m128d zero = _mm_setzero_pd(), vw = _mm_set1_pd(w), vh = _mm_set1_pd(h);
    __m128d bad = zero;
    for (; i + 2 <= end; i += 2) {
        const __m128d r = _mm_loadu_pd(pr + i), x = _mm_loadu_pd(px + i), y = _mm_loadu_pd(py + i);
        const __m128d wr = _mm_sub_pd(vw, r), hr = _mm_sub_pd(vh, r);
        bad = _mm_or_pd(bad, _mm_cmpnge_pd(_mm_sub_pd(x, r), zero));
        bad = _mm_or_pd(bad, _mm_cmpnge_pd(_mm_sub_pd(wr, x), zero));
        bad = _mm_or_pd(bad, _mm_cmpnge_pd(_mm_sub_pd(y, r), zero));
        bad = _mm_or_pd(bad, _mm_cmpnge_pd(_mm_sub_pd(hr, y), zero));
        bad = _mm_or_pd(bad, _mm_cmpngt_pd(_mm_sub_pd(wr, r), zero));
        bad = _mm_or_pd(bad, _mm_cmpngt_pd(_mm_sub_pd(hr, r), zero));
    }
    out = _mm_movemask_pd(bad) != 0;
#endif
    for (; i < end; ++i) {
        const double r = pr[i], x = px[i], y = py[i];
        out |= !(x - r >= 0.0) || !(w - r - x >= 0.0) || !(y - r >= 0.0) || !(h - r - y >= 0.0) ||
               !(w - r - r > 0.0) || !(h - r - r > 0.0);
    }
    return out;
}

template <bool kFriction>
void wallsImpl(ParticleArrays& p, const WorldDef& def, StepContext& ctx, StepCounters& counters) {
    const double e = def.restitution, mu = def.friction;
    const std::size_t n = p.size();
    // Runs move() found outside, plus the runs of every particle the separate stage may have
    // pushed: only those can hold a particle outside now.
    const bool runsFresh =
        ctx.wallRunsFresh && ctx.wallRuns.size() == (n + kWallRun - 1) / kWallRun;
    ctx.wallRunsFresh = false;
    if (runsFresh) {
        for (const ContactPair& pair : ctx.pairs) {
            ctx.wallRuns[pair.i / kWallRun] = 1;
            ctx.wallRuns[pair.j / kWallRun] = 1;
        }
    }
    const std::uint8_t* flagged = runsFresh ? ctx.wallRuns.data() : nullptr;
    // The impulse sum depends on the order of its terms: one sequential sum per fixed block,
    // added in block order below (rule 2 of parallel.hpp), so any thread count gives the same
    // bits.
    const std::size_t blocks = parallel::blockCount(n);
    ctx.wallImpulseScratch.resize(blocks);
    ctx.wallHitScratch.resize(blocks);
    parallel::forBlocks(ctx.threads, n, [&](std::size_t b, std::size_t begin, std::size_t end) {
        std::uint64_t hits = 0;
        double impulse = 0.0;
        // Nearly every particle is inside, where wallAxis changes nothing on either axis. Runs
        // of kWallRun particles are tested without a branch per particle (or were flagged by
        // move) and visited one by one only if one of them may be out.
        for (std::size_t run = begin; run < end; run += kWallRun) {
            const std::size_t runEnd = std::min(end, run + kWallRun);
            // A run flagged only because one of its particles was in a pair is usually inside:
            // the vectorised test is cheaper than visiting its particles.
            if (flagged && flagged[run / kWallRun] == 0) continue;
            if (!anyOutside(p, def, run, runEnd)) continue;
            for (std::size_t i = run; i < runEnd; ++i) {
                const double r = p.radius[i];
                if (p.invMass[i] == 0.0) {
                    // A held particle is clamped into the box but its velocity is its owner's.
                    double vx = 0.0, vy = 0.0, vt = 0.0;
                    wallAxis<false>(p.x[i], vx, vt, r, def.width, e, mu);
                    wallAxis<false>(p.y[i], vy, vt, r, def.height, e, mu);
                    continue;
                }
                const double jx =
                    wallAxis<kFriction>(p.x[i], p.vx[i], p.vy[i], r, def.width, e, mu);
                const double jy =
                    wallAxis<kFriction>(p.y[i], p.vy[i], p.vx[i], r, def.height, e, mu);
                if (jx > 0.0 || jy > 0.0) {
                    hits += (jx > 0.0) + (jy > 0.0);
                    impulse += p.mass[i] * (jx + jy);
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
}

}  // namespace

void flagRunsOutside(const ParticleArrays& p, const WorldDef& def, std::size_t begin,
                     std::size_t end, std::uint8_t* runs) {
    for (std::size_t run = begin; run < end; run += kWallRun) {
        runs[run / kWallRun] = anyOutside(p, def, run, std::min(end, run + kWallRun)) ? 1 : 0;
    }
}

void walls(ParticleArrays& p, const WorldDef& def, StepContext& ctx, StepCounters& counters) {
    if (def.friction > 0.0) {
        wallsImpl<true>(p, def, ctx, counters);
    } else {
        wallsImpl<false>(p, def, ctx, counters);
    }
}

}  // namespace psb::stages
