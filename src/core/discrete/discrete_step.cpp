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
          const GridBroadPhase::MoveCells* cells, const MoveWrap* wrap) {
    const std::size_t n = p.size();
    double* x = p.x.data();
    double* y = p.y.data();
    const double* vx = p.vx.data();
    const double* vy = p.vy.data();
    if (bounds) bounds->resize(parallel::blockCount(n));
    parallel::forBlocks(threads, n, [&](std::size_t b, std::size_t begin, std::size_t end) {
        if (wrap) {
            moveAndWrapBlock(p, dt, *wrap, cells, begin, end);
        } else if (cells) {
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
    const bool marksFresh = ctx.marksFresh;
    ctx.statsFresh = ctx.cellsFresh = ctx.marksFresh = false;
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
                ctx.periodicGrid.build(p, ctx.box, stats, ctx.threads, cellsFresh, marksFresh);
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

namespace {

/// Wraps particle i's centre into the box, keeping what it took off in the unwrap arrays and
/// moving the obstacles stage's start position with it.
inline void wrapOne(ParticleArrays& p, const MoveWrap& wrap, std::size_t i) {
    double& x = p.x[i];
    double& y = p.y[i];
    const double ox = x, oy = y;
    periodic::wrapInto(x, p.unwrapX[i], wrap.width);
    periodic::wrapInto(y, p.unwrapY[i], wrap.height);
    if (wrap.startX && (x != ox || y != oy)) {
        // The sweep against the obstacles starts where the centre started, moved with it.
        wrap.startX[i] += x - ox;
        wrap.startY[i] += y - oy;
    }
}

}  // namespace

void wrapBlock(ParticleArrays& p, const MoveWrap& wrap, std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i)
        wrapOne(p, wrap, i);
}

void moveAndWrapBlock(ParticleArrays& p, double dt, const MoveWrap& wrap,
                      const GridBroadPhase::MoveCells* cells, std::size_t begin, std::size_t end) {
    double* x = p.x.data();
    double* y = p.y.data();
    const double* vx = p.vx.data();
    const double* vy = p.vy.data();
    if (!wrap.marked) {
        for (std::size_t i = begin; i < end; ++i) {
            x[i] += vx[i] * dt;
            y[i] += vy[i] * dt;
        }
        wrapBlock(p, wrap, begin, end);
        if (cells) {
            for (std::size_t i = begin; i < end; ++i)
                cells->cellOf[i] = cells->map.cellOf(x[i], y[i]);
        }
        return;
    }
    // Per run of kMarkRun particles: one branch-free pass moves the centres and marks those
    // within `reach` of an edge or outside the box (it vectorises), then the few marked are
    // listed and wrapped. The marks are on the stack, a run's worth: they stay in cache.
    const double reach = wrap.reach, right = wrap.width - reach, top = wrap.height - reach;
    constexpr std::size_t kMarkRun = 256;
    double marks[kMarkRun];
    std::vector<std::uint32_t>& marked = wrap.marked[begin / parallel::kBlock];
    marked.clear();
    for (std::size_t run = begin; run < end; run += kMarkRun) {
        const std::size_t count = std::min(kMarkRun, end - run);
        {
            // Distinct arrays (a store could alias a coordinate otherwise, and the loop would
            // not vectorise).
            double* __restrict mx = x + run;
            double* __restrict my = y + run;
            const double* __restrict mvx = vx + run;
            const double* __restrict mvy = vy + run;
            double* __restrict mark = marks;
            for (std::size_t k = 0; k < count; ++k) {
                const double xi = mx[k] + mvx[k] * dt;
                const double yi = my[k] + mvy[k] * dt;
                mx[k] = xi;
                my[k] = yi;
                // Doubles, not booleans: with SSE2 only a compare of doubles that gives a
                // double vectorises. NaN is near no edge (and is not wrapped).
                mark[k] = (xi < reach ? 1.0 : 0.0) + (xi >= right ? 1.0 : 0.0) +
                          (yi < reach ? 1.0 : 0.0) + (yi >= top ? 1.0 : 0.0);
            }
        }
        for (std::size_t k = 0; k < count; ++k) {
            if (marks[k] == 0.0) continue;
            const std::size_t i = run + k;
            marked.push_back(static_cast<std::uint32_t>(i));
            wrapOne(p, wrap, i);
        }
    }
    if (cells) {
        const GridBroadPhase::CellMap map = cells->map;
        std::uint32_t* cellOf = cells->cellOf;
        for (std::size_t i = begin; i < end; ++i)
            cellOf[i] = map.cellOf(x[i], y[i]);
    }
}

void wrap(ParticleArrays& p, const WorldDef& def, int threads) {
    const std::size_t n = p.size();
    const MoveWrap w{def.width, def.height};
    parallel::forChunks(
        threads, parallel::chunksFor(threads, n), n,
        [&](int, std::size_t begin, std::size_t end) { wrapBlock(p, w, begin, end); });
}

void wrapPairs(ParticleArrays& p, const WorldDef& def, const std::vector<ContactPair>& pairs) {
    const MoveWrap wrap{def.width, def.height};
    for (const ContactPair& c : pairs) {
        wrapOne(p, wrap, c.i);
        wrapOne(p, wrap, c.j);
    }
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
        const bool grid = ctx.broadPhaseUsed == BroadPhaseKind::Grid;
        const auto cells = !grid          ? std::nullopt
                           : ctx.periodic ? ctx.periodicGrid.cellsForMove(p.size())
                                          : ctx.grid.cellsForMove(p.size());
        // In a periodic box, move wraps each centre as it moves it, so that the broadphase finds
        // the pairs inside the box as in a box with walls (broad_phase_periodic_grid.hpp).
        MoveWrap wrapping{def.width, def.height};
        if (obstaclesPresent) {
            wrapping.startX = ctx.startX.data();
            wrapping.startY = ctx.startY.data();
        }
        const auto marks =
            def.periodic && grid ? ctx.periodicGrid.marksForMove(p.size()) : std::nullopt;
        if (marks) {
            wrapping.reach = marks->reach;
            wrapping.marked = marks->marked;
        }
        move(p, dt, ctx.threads, &ctx.statsScratch, cells ? &*cells : nullptr,
             def.periodic ? &wrapping : nullptr);
        turn(p, dt);
        ctx.statsFresh = p.size() > 0;
        ctx.cellsFresh = cells.has_value();
        ctx.marksFresh = marks.has_value();
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
        // Only separate and obstacles move centres after move wrapped them: the pairs' discs,
        // or with obstacles every disc.
        StageTimer t(profile.stage("wrap"));
        obstaclesPresent ? wrap(p, def, ctx.threads) : wrapPairs(p, def, ctx.pairs);
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
