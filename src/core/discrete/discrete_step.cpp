#include "discrete/discrete_step.hpp"

#include <optional>

#include "broadphase/broad_phase_all_pairs.hpp"
#include "broadphase/broad_phase_auto.hpp"
#include "broadphase/particle_reorder.hpp"
#include "support/parallel.hpp"
#include "support/periodic_box.hpp"
#include "world/stage_timer.hpp"

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

void move(ParticleArrays& p, double dt, int threads, std::vector<ParticleStats>* bounds,
          const GridBroadPhase::MoveCells* cells) {
    const std::size_t n = p.size();
    double* x = p.x.data();
    double* y = p.y.data();
    const double* vx = p.vx.data();
    const double* vy = p.vy.data();
    if (bounds) bounds->resize(parallel::blockCount(n));
    parallel::forBlocks(threads, n, [&](std::size_t b, std::size_t begin, std::size_t end) {
        if (cells) {
            // The cell of each particle as it moves, under the grid's last plan.
            const GridBroadPhase::CellMap map = cells->map;
            std::uint32_t* cellOf = cells->cellOf;
            for (std::size_t i = begin; i < end; ++i) {
                x[i] += vx[i] * dt;
                y[i] += vy[i] * dt;
                cellOf[i] = map.cellOf(x[i], y[i]);
            }
        } else {
            for (std::size_t i = begin; i < end; ++i) {
                x[i] += vx[i] * dt;
                y[i] += vy[i] * dt;
            }
        }
        // Measured while the block is still in cache: one pass over memory, not two.
        if (bounds) measureBlock(p, begin, end, (*bounds)[b]);
    });
}

void turn(ParticleArrays& p, double dt) {
    if (!p.rotation) return;
    const std::size_t n = p.size();
    double* angle = p.angle.data();
    const double* omega = p.omega.data();
    for (std::size_t i = 0; i < n; ++i)
        angle[i] += omega[i] * dt;
}

void findPairs(const ParticleArrays& p, StepContext& ctx) {
    ctx.pairs.clear();
    const bool statsFresh = ctx.statsFresh, cellsFresh = ctx.cellsFresh;
    ctx.statsFresh = ctx.cellsFresh = false;
    if (p.size() < 2) {
        ctx.broadPhaseUsed = chooseBroadPhase(ctx.broadPhase, p, ParticleStats{});
        return;
    }
    const ParticleStats stats = statsFresh ? combineBlocks(ctx.statsScratch, p.size())
                                           : measureParticles(p, ctx.threads, ctx.statsScratch);
    ctx.broadPhaseUsed = chooseBroadPhase(ctx.broadPhase, p, stats);
    if (ctx.periodic) {
        switch (ctx.broadPhaseUsed) {
            case BroadPhaseKind::Grid:
                ctx.periodicGrid.build(p, ctx.box, stats, ctx.threads);
                ctx.periodicGrid.findPairs(p, ctx.threads, ctx.pairs);
                break;
            case BroadPhaseKind::Quadtree:
                ctx.quadtree.build(p, stats, ctx.threads);
                ctx.quadtree.findPairsPeriodic(p, ctx.box, ctx.threads, ctx.pairs);
                break;
            case BroadPhaseKind::Auto:
            case BroadPhaseKind::AllPairs:
                findPairsAllPairs(p, ctx.box, ctx.pairs);
                break;
        }
        return;
    }
    switch (ctx.broadPhaseUsed) {
        case BroadPhaseKind::Grid:
            ctx.grid.build(p, stats, ctx.threads, cellsFresh);
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

void wrap(ParticleArrays& p, const WorldDef& def, int threads) {
    const std::size_t n = p.size();
    double* x = p.x.data();
    double* y = p.y.data();
    double* ux = p.unwrapX.data();
    double* uy = p.unwrapY.data();
    const double w = def.width, h = def.height;
    parallel::forChunks(threads, parallel::chunksFor(threads, n), n,
                        [=](int, std::size_t begin, std::size_t end) {
                            for (std::size_t i = begin; i < end; ++i) {
                                periodic::wrapInto(x[i], ux[i], w);
                                periodic::wrapInto(y[i], uy[i], h);
                            }
                        });
}

void discreteStep(ParticleArrays& p, const WorldDef& def, double dt, StepContext& ctx,
                  StepProfile& profile, StepCounters& counters) {
    StageTimer total(profile.total);
    // Every stage is listed, in pipeline order, even when skipped.
    double& gravityMs = profile.stage("gravity");
    double& moveMs = profile.stage("move");
    double& findPairsMs = profile.stage("find pairs");
    double& resolveMs = profile.stage("resolve");
    double& separateMs = profile.stage("separate");
    double& obstaclesMs = profile.stage("obstacles");
    double& wallsMs = profile.stage("walls");
    ctx.periodic = def.periodic;
    ctx.box = {def.width, def.height};
    const bool obstaclesPresent = !def.obstacles.empty();
    if (obstaclesPresent) {
        StageTimer t(obstaclesMs);
        saveStartPositions(p, ctx);
    }
    if (def.gravity.x() != 0.0 || def.gravity.y() != 0.0) {
        StageTimer t(gravityMs);
        applyGravity(p, def.gravity, dt, ctx.threads);
    }
    {
        StageTimer t(moveMs);
        // While the grid is in use, move also writes each particle's cell under the grid's last
        // plan, which findPairs keeps while it fits (broad_phase_grid.hpp, plan reuse).
        const auto cells = ctx.broadPhaseUsed == BroadPhaseKind::Grid && !ctx.periodic
                               ? ctx.grid.cellsForMove(p.size())
                               : std::nullopt;
        move(p, dt, ctx.threads, &ctx.statsScratch, cells ? &*cells : nullptr);
        turn(p, dt);
        ctx.statsFresh = p.size() > 0;
        ctx.cellsFresh = cells.has_value();
    }
    {
        StageTimer t(findPairsMs);
        findPairs(p, ctx);
    }
    profile.pairs += ctx.pairs.size();
    {
        StageTimer t(resolveMs);
        resolve(p, def, ctx, counters);
    }
    {
        StageTimer t(separateMs);
        separate(p, ctx);
    }
    if (obstaclesPresent) {
        StageTimer t(obstaclesMs);
        obstacles(p, def, ctx, counters);
    }
    if (def.walls) {
        StageTimer t(wallsMs);
        walls(p, def, ctx, counters);
    }
    if (def.periodic) {
        StageTimer t(profile.stage("wrap"));
        wrap(p, def, ctx.threads);
    }
    ++counters.steps;
}

void discreteSteps(ParticleArrays& p, detail::IdTable& ids, const WorldDef& def, double dt,
                   int substeps, StepContext& ctx, unsigned& stepsUntilReorder,
                   StepProfile& profile, StepCounters& counters) {
    double& reorderMs = profile.stage("reorder");
    if (p.size() >= kReorderMinParticles) {
        if (stepsUntilReorder == 0) {
            StageTimer t(reorderMs);
            reorderByCell(p, ids, ctx);
            stepsUntilReorder = kReorderInterval;
        }
        --stepsUntilReorder;
    }
    const double h = dt / substeps;
    for (int k = 0; k < substeps; ++k) {
        // The last substep ends where World's clock will be.
        ctx.collisionTime = k + 1 == substeps ? ctx.stepStart + dt : ctx.stepStart + (k + 1) * h;
        discreteStep(p, def, h, ctx, profile, counters);
    }
    profile.total += reorderMs;
}

}  // namespace psb::stages
