// The resolve and separate stages of the discrete step (see discrete_step.hpp).

#include <algorithm>
#include <cmath>

#include "contact/collision_capture.hpp"
#include "contact/contact.hpp"
#include "discrete/discrete_step.hpp"
#include "support/periodic_box.hpp"

namespace psb::stages {
namespace {

/// Unit normal from i to j and the centre distance. Coincident centres get coincidentNormal.
/// kPeriodic: measured between nearest images in `box` (support/periodic_box.hpp).
template <bool kPeriodic = false>
inline Normal contactNormal(const ParticleArrays& p, std::uint32_t i, std::uint32_t j,
                            double& distance, const periodic::Box& box = {}) {
    double dx = p.x[j] - p.x[i];
    double dy = p.y[j] - p.y[i];
    if constexpr (kPeriodic) {
        dx = box.imageX(dx);
        dy = box.imageY(dy);
    }
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

// kRecord: the world records collisions (ctx.collisionLog) or measures the pair virial
// (ctx.measureVirial); a separate instance, so that a world that does neither runs exactly the
// loop it ran before either existed. kRough: the particles turn and there is friction
// (contact.hpp's Rough family), likewise separate. kPeriodic: a periodic box, pairs measured
// between nearest images.
template <bool kFriction, bool kRough, bool kRecord, bool kPeriodic = false>
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
        const Normal n = contactNormal<kPeriodic>(p, i, j, d, ctx.box);
        deepest = std::max(deepest, p.radius[i] + p.radius[j] - d);

        [[maybe_unused]] const Vec2 iBefore(p.vx[i], p.vy[i]), jBefore(p.vx[j], p.vy[j]);
        bool hit;
        if constexpr (kRough) {
            hit = collideRoughDiscs(p.vx[i], p.vy[i], {p.omega[i], p.radius[i], p.spinWeight(i)},
                                    p.vx[j], p.vy[j], {p.omega[j], p.radius[j], p.spinWeight(j)},
                                    p.invMass[i], p.invMass[j], p.mass[i], p.mass[j], n,
                                    {e, mu, def.tangentialRestitution});
        } else {
            hit = collideDiscs<kFriction>(p.vx[i], p.vy[i], p.vx[j], p.vy[j], p.invMass[i],
                                          p.invMass[j], p.mass[i], p.mass[j], n, e, mu);
        }
        if (hit) {
            ++counters.collisions;
            if constexpr (kRecord) {
                if (ctx.collisionLog) {
                    ctx.collisionLog->add(pairCollision(
                        ctx.collisionTime, p.id[i], p.id[j], iBefore, Vec2(p.vx[i], p.vy[i]),
                        jBefore, Vec2(p.vx[j], p.vy[j]), p.invMass[i], p.mass[i], p.mass[j]));
                }
                if (ctx.measureVirial) {
                    // r_ij·J_ij with r_ij = −d n (the positions the stage found, overlapping)
                    // and J_ij = m_i Δv_i (a held i: what j received, reversed).
                    const Vec2 impulse =
                        p.invMass[i] > 0.0 ? Vec2(p.mass[i] * (Vec2(p.vx[i], p.vy[i]) - iBefore))
                                           : Vec2(-p.mass[j] * (Vec2(p.vx[j], p.vy[j]) - jBefore));
                    counters.pairVirial -= d * (n.x * impulse.x() + n.y * impulse.y());
                }
            }
        }
    }
    counters.maxOverlap = deepest;
}

template <bool kPeriodic>
void separateImpl(ParticleArrays& p, const StepContext& ctx) {
    for (std::size_t k = 0; k < ctx.pairs.size(); ++k) {
        prefetchPair(p, ctx.pairs, k);
        const ContactPair& c = ctx.pairs[k];
        const std::uint32_t i = c.i, j = c.j;
        double d;
        const Normal n = contactNormal<kPeriodic>(p, i, j, d, ctx.box);
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

/// Every combination of the laws, records kept or not, in a box with walls or a periodic one.
template <bool kPeriodic>
void resolveAny(ParticleArrays& p, const WorldDef& def, const StepContext& ctx,
                StepCounters& counters) {
    const bool record = ctx.collisionLog != nullptr || ctx.measureVirial;
    if (def.friction > 0.0 && p.rotation) {
        record ? resolveImpl<true, true, true, kPeriodic>(p, def, ctx, counters)
               : resolveImpl<true, true, false, kPeriodic>(p, def, ctx, counters);
    } else if (def.friction > 0.0) {
        record ? resolveImpl<true, false, true, kPeriodic>(p, def, ctx, counters)
               : resolveImpl<true, false, false, kPeriodic>(p, def, ctx, counters);
    } else {
        record ? resolveImpl<false, false, true, kPeriodic>(p, def, ctx, counters)
               : resolveImpl<false, false, false, kPeriodic>(p, def, ctx, counters);
    }
}

}  // namespace

void resolve(ParticleArrays& p, const WorldDef& def, const StepContext& ctx,
             StepCounters& counters) {
    ctx.periodic ? resolveAny<true>(p, def, ctx, counters)
                 : resolveAny<false>(p, def, ctx, counters);
}

void separate(ParticleArrays& p, const StepContext& ctx) {
    ctx.periodic ? separateImpl<true>(p, ctx) : separateImpl<false>(p, ctx);
}

}  // namespace psb::stages
