#include "discrete_step.hpp"

#include "broad_phase_all_pairs.hpp"
#include "broad_phase_auto.hpp"
#include "parallel.hpp"
#include "stage_timer.hpp"

namespace psb::stages {

void applyGravity(ParticleArrays& p, const Vec2& gravity, double dt, int threads) {
    const double gx = gravity.x() * dt, gy = gravity.y() * dt;
    const std::size_t n = p.size();
    double* vx = p.vx.data();
    double* vy = p.vy.data();
    const double* w = p.invMass.data();
    parallel::forChunks(threads, parallel::chunksFor(threads, n), n,
                        [=](int, std::size_t begin, std::size_t end) {
                            for (std::size_t i = begin; i < end; ++i) {
                                // Kinematic particles (w == 0) are moved by their owner, not by
                                // forces.
                                const double k = w[i] > 0.0 ? 1.0 : 0.0;
                                vx[i] += k * gx;
                                vy[i] += k * gy;
                            }
                        });
}

void move(ParticleArrays& p, double dt, int threads, std::vector<ParticleStats>* bounds) {
    const std::size_t n = p.size();
    double* x = p.x.data();
    double* y = p.y.data();
    const double* vx = p.vx.data();
    const double* vy = p.vy.data();
    if (bounds) bounds->resize(parallel::blockCount(n));
    parallel::forBlocks(threads, n, [&](std::size_t b, std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) {
            x[i] += vx[i] * dt;
            y[i] += vy[i] * dt;
        }
        // Measured while the block is still in cache: one pass over memory, not two.
        if (bounds) measureBlock(p, begin, end, (*bounds)[b]);
    });
}

void findPairs(const ParticleArrays& p, StepContext& ctx) {
    ctx.pairs.clear();
    const bool statsFresh = ctx.statsFresh;
    ctx.statsFresh = false;
    if (p.size() < 2) {
        ctx.broadPhaseUsed = chooseBroadPhase(ctx.broadPhase, p, ParticleStats{});
        return;
    }
    const ParticleStats stats = statsFresh ? combineBlocks(ctx.statsScratch, p.size())
                                           : measureParticles(p, ctx.threads, ctx.statsScratch);
    ctx.broadPhaseUsed = chooseBroadPhase(ctx.broadPhase, p, stats);
    switch (ctx.broadPhaseUsed) {
        case BroadPhaseKind::Grid:
            ctx.grid.build(p, stats, ctx.threads);
            ctx.grid.findPairs(p, ctx.threads, ctx.pairs);
            break;
        case BroadPhaseKind::Quadtree:
            ctx.quadtree.build(p, stats, ctx.threads);
            ctx.quadtree.findPairs(p, ctx.threads, ctx.pairs);
            break;
        case BroadPhaseKind::Auto:  // resolved by chooseBroadPhase
        case BroadPhaseKind::AllPairs:
            findPairsAllPairs(p, ctx.pairs);
            break;
    }
}

void discreteStep(ParticleArrays& p, const WorldDef& def, double dt, StepContext& ctx,
                  StepProfile& profile, StepCounters& counters) {
    StageTimer total(profile.total);
    if (def.gravity.x() != 0.0 || def.gravity.y() != 0.0) {
        StageTimer t(profile.gravity);
        applyGravity(p, def.gravity, dt, ctx.threads);
    }
    {
        StageTimer t(profile.move);
        move(p, dt, ctx.threads, &ctx.statsScratch);
        ctx.statsFresh = p.size() > 0;
    }
    {
        StageTimer t(profile.findPairs);
        findPairs(p, ctx);
    }
    profile.pairs += ctx.pairs.size();
    {
        StageTimer t(profile.resolve);
        resolve(p, def, ctx, counters);
    }
    {
        StageTimer t(profile.separate);
        separate(p, ctx);
    }
    if (def.walls) {
        StageTimer t(profile.walls);
        walls(p, def, ctx, counters);
    }
    ++counters.steps;
}

}  // namespace psb::stages
