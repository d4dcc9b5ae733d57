// The resolve and separate stages of the discrete step (see discrete_step.hpp).

#include <algorithm>
#include <cmath>

#include "contact.hpp"
#include "discrete_step.hpp"

namespace psb::stages {
namespace {

/// Unit normal from i to j and the centre distance. Coincident centres get coincidentNormal.
inline Normal contactNormal(const ParticleArrays& p, std::uint32_t i, std::uint32_t j,
                            double& distance) {
    const double dx = p.x[j] - p.x[i];
    const double dy = p.y[j] - p.y[i];
    distance = std::sqrt(dx * dx + dy * dy);
    // A distance that is zero, or so small relative to the coordinates that dx/distance would
    // not be a unit vector, gives no usable direction.
    if (!(distance > 0.0) || !std::isfinite(dx / distance) || !std::isfinite(dy / distance)) {
        distance = 0.0;
        return coincidentNormal(p.id[i], p.id[j]);
    }
    return {dx / distance, dy / distance};
}

/// Pairs are sparse in storage (a gas has a few per hundred particles), so each one touches
/// fresh cache lines in every array; ask for them a few pairs ahead. A hint only: no effect on
/// results.
inline void prefetchPair(const ParticleArrays& p, const std::vector<ContactPair>& pairs,
                         std::size_t k) {
    constexpr std::size_t kAhead = 6;
    if (k + kAhead >= pairs.size()) return;
    for (const std::uint32_t i : {pairs[k + kAhead].i, pairs[k + kAhead].j}) {
        __builtin_prefetch(&p.x[i]);
        __builtin_prefetch(&p.y[i]);
        __builtin_prefetch(&p.vx[i]);
        __builtin_prefetch(&p.vy[i]);
        __builtin_prefetch(&p.invMass[i]);
        __builtin_prefetch(&p.radius[i]);
        __builtin_prefetch(&p.mass[i]);
    }
}

template <bool kFriction>
void resolveImpl(ParticleArrays& p, const WorldDef& def, const StepContext& ctx,
                 StepCounters& counters) {
    const double e = def.restitution;
    const double mu = def.friction;
    double deepest = counters.maxOverlap;
    for (std::size_t k = 0; k < ctx.pairs.size(); ++k) {
        prefetchPair(p, ctx.pairs, k);
        const ContactPair& c = ctx.pairs[k];
        const std::uint32_t i = c.i, j = c.j;
        double d;
        const Normal n = contactNormal(p, i, j, d);
        deepest = std::max(deepest, p.radius[i] + p.radius[j] - d);

        const double wi = p.invMass[i], wj = p.invMass[j];
        if (wi == 0.0 && wj == 0.0) continue;  // two held particles: nothing can give

        const double vni = p.vx[i] * n.x + p.vy[i] * n.y;
        const double vnj = p.vx[j] * n.x + p.vy[j] * n.y;
        // Only approaching pairs collide. A pair that overlaps but already separates was
        // resolved before (or was placed overlapping); swapping its velocities again is what
        // made the original's particles stick and chatter.
        if (vnj - vni >= 0.0) continue;

        double ni, nj;  // new normal components
        if (wi == 0.0) {
            ni = vni;
            nj = collideNormalWithKinematic(vni, vnj, e);
        } else if (wj == 0.0) {
            nj = vnj;
            ni = collideNormalWithKinematic(vnj, vni, e);
        } else {
            const NormalVelocities after = collideNormal(p.mass[i], p.mass[j], vni, vnj, e);
            ni = after.v1n;
            nj = after.v2n;
        }
        const double dvi = ni - vni, dvj = nj - vnj;
        p.vx[i] += dvi * n.x;
        p.vy[i] += dvi * n.y;
        p.vx[j] += dvj * n.x;
        p.vy[j] += dvj * n.y;

        if constexpr (kFriction) {
            // Coulomb friction on the tangential relative velocity: the impulse that would stop
            // the sliding, capped at mu times the normal impulse. The discs do not spin, so the
            // sticking limit is equal tangential velocities.
            const double jn = wj > 0.0 ? dvj / wj : -dvi / wi;  // normal impulse on j, >= 0
            const double tx = -n.y, ty = n.x;
            const double vt = (p.vx[j] - p.vx[i]) * tx + (p.vy[j] - p.vy[i]) * ty;
            const double limit = mu * jn;
            const double jt = std::clamp(-vt / (wi + wj), -limit, limit);
            p.vx[i] -= jt * wi * tx;
            p.vy[i] -= jt * wi * ty;
            p.vx[j] += jt * wj * tx;
            p.vy[j] += jt * wj * ty;
        }
        ++counters.collisions;
    }
    counters.maxOverlap = deepest;
}

}  // namespace

void resolve(ParticleArrays& p, const WorldDef& def, const StepContext& ctx,
             StepCounters& counters) {
    if (def.friction > 0.0) {
        resolveImpl<true>(p, def, ctx, counters);
    } else {
        resolveImpl<false>(p, def, ctx, counters);
    }
}

void separate(ParticleArrays& p, const StepContext& ctx) {
    for (std::size_t k = 0; k < ctx.pairs.size(); ++k) {
        prefetchPair(p, ctx.pairs, k);
        const ContactPair& c = ctx.pairs[k];
        const std::uint32_t i = c.i, j = c.j;
        double d;
        const Normal n = contactNormal(p, i, j, d);
        const double depth = p.radius[i] + p.radius[j] - d;
        if (!(depth > 0.0)) continue;  // an earlier push in this pass already separated it
        const double wi = p.invMass[i], wj = p.invMass[j];
        const double wsum = wi + wj;
        if (wsum == 0.0) continue;
        // Split by inverse mass: the centre of mass stays put, the heavy one barely moves.
        const double si = depth * (wi / wsum), sj = depth * (wj / wsum);
        p.x[i] -= si * n.x;
        p.y[i] -= si * n.y;
        p.x[j] += sj * n.x;
        p.y[j] += sj * n.y;
    }
}

}  // namespace psb::stages
