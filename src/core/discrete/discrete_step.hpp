#pragma once
// The discrete step: the original program's one-move-one-collision-pass step, done right.
//
//   (reorder*) then, per substep:
//   ┌───────────┐   ┌──────┐   ┌────────────┐   ┌─────────┐   ┌──────────┐   ┌───────┐
//   │ gravity*  │ → │ move │ → │ find pairs │ → │ resolve │ → │ separate │ → │ walls*│
//   └───────────┘   └──────┘   └────────────┘   └─────────┘   └──────────┘   └───────┘
//   v += g·dt       r += v·dt   broadphase +     impulses on    push overlaps  clamp into
//                   θ += ω·dt†  overlap test     approaching    apart by       the box, set
//                                                pairs only     inverse mass   velocity sign
//   (* skipped when the world has no gravity / no walls; friction math is compiled out of
//    resolve and walls when the friction coefficient is zero.)
//
// Periodic boxes (WorldDef::periodic). Move brings every centre it moves back into
// [0, width) × [0, height) and adds what it took off to the particle's unwrapped offset
// (ParticleArrays::unwrapX, unwrapY); the walls stage gives way to `wrap`, which does the same
// for the discs separate (or obstacles) pushed over an edge. Find pairs, resolve and separate
// measure every pair between nearest images (support/periodic_box.hpp), and the broadphases
// find pairs across the edges (the box grid inside the box and strips along the edges,
// broad_phase_periodic_grid.hpp; the quadtree's images; all-pairs). Each is a separate instance or
// path, so a world that is not periodic runs exactly the code it ran before periodic boxes existed.
//   († only in a world that keeps rotation. With friction and rotation, resolve, obstacles
//    and walls run the rough contacts of contact.hpp, which turn the discs: rolling is what
//    those contact passes make of a disc pressed onto a surface, step after step.)
//
// Obstacles. A world with fixed obstacles runs one more stage, `obstacles`, between separate
// and walls: it sweeps each particle's move of the step against the pegs and segments near it
// and pushes it out of them (discrete_obstacles.cpp). A world without obstacles skips it, and
// the copy of the start positions it needs, entirely.
//
// Why walls come last. The original bounced off walls before resolving pairs, so the overlap
// push could leave a particle outside the box. Running the wall stage after every stage that
// moves particles guarantees that no particle ends a step outside the box. The price is that
// a wall clamp can re-create a small overlap, which the next step's separate stage removes.
//
// Order dependence. Pairs are resolved one after another (Gauss–Seidel), so with three or more
// particles in mutual contact the result depends on the order. We do not hide this with a
// simultaneous (Jacobi) solve, which would conserve momentum but not energy and would get
// Newton's cradle wrong. Instead the order is fixed: pairs are visited in ascending (i, j)
// storage order whatever broadphase found them, so the same state always gives the same result.
// A pair is resolved only while approaching, so visiting a pair after a neighbour already
// turned it around does nothing, and restitution e = 1 conserves kinetic energy exactly
// (to rounding) in every order.

#include <particle_sandbox/detail/id_table.hpp>
#include <particle_sandbox/particle_arrays.hpp>
#include <particle_sandbox/step_profile.hpp>
#include <particle_sandbox/world_def.hpp>

#include "world/step_context.hpp"

namespace psb::stages {

// The element-wise stages (gravity, move, walls, and the broadphases' per-particle passes) run
// on ctx.threads threads; resolve and separate are sequential. parallel.hpp says why the result
// does not depend on the thread count.

void applyGravity(ParticleArrays& p, const Vec2& gravity, double dt, int threads = 1);
/// A periodic box for move() to wrap the centres into as it moves them.
struct MoveWrap {
    double width = 0.0, height = 0.0;  ///< metres
    /// The obstacles stage's start positions (saveStartPositions), moved with their centres
    /// when those wrap, or null.
    double* startX = nullptr;
    double* startY = nullptr;
    /// Where to list, one list per block of parallel::forBlocks, the particles whose centres
    /// are within `reach` metres of an edge or outside the box, for the periodic grid's strips
    /// (PeriodicGridBroadPhase::marksForMove); or null. A non-finite centre is near no edge:
    /// it is not wrapped either.
    std::vector<std::uint32_t>* marked = nullptr;
    double reach = 0.0;
};

/// Moves every particle by v·dt. With `wrap`, brings each centre back into the periodic box
/// (as wrap() does); with `bounds`, also measures the moved particles per block (for
/// combineBlocks), and with `cells`, writes each particle's grid cell: all while the particle
/// is in cache, saving the broadphase passes over memory.
void move(ParticleArrays& p, double dt, int threads = 1,
          std::vector<ParticleStats>* bounds = nullptr,
          const GridBroadPhase::MoveCells* cells = nullptr, const MoveWrap* wrap = nullptr);
/// Turns every particle by ω·dt, in a world that keeps rotation (ParticleArrays::rotation;
/// nothing otherwise). Timed with move: a particle's angle moves as its centre does.
void turn(ParticleArrays& p, double dt);
/// Fills ctx.pairs with the overlapping pairs in ascending (i, j) order, using the broadphase
/// ctx.broadPhase asks for (Auto resolved by broad_phase_auto.hpp); records the one used in
/// ctx.broadPhaseUsed. Uses the bounds and grid cells move() wrote when ctx.statsFresh and
/// ctx.cellsFresh say they are of these positions.
void findPairs(const ParticleArrays& p, StepContext& ctx);
/// Velocity impulses for every approaching pair in ctx.pairs; updates collision counters and
/// the deepest overlap seen.
void resolve(ParticleArrays& p, const WorldDef& def, const StepContext& ctx,
             StepCounters& counters);
/// Pushes each overlapping pair of ctx.pairs apart along its normal, the push split by inverse
/// mass so that momentum-weighted position (the centre of mass) does not move. Positions only:
/// velocities, and so kinetic energy, are untouched.
void separate(ParticleArrays& p, const StepContext& ctx);
/// Clamps every particle into the box and makes outward velocity components inward (scaled by
/// e). A particle already moving inward keeps its velocity.
void walls(ParticleArrays& p, const WorldDef& def, StepContext& ctx, StepCounters& counters);

/// Periodic boxes: wraps every centre into [0, width) × [0, height), keeping what it took off
/// in the unwrap arrays.
void wrap(ParticleArrays& p, const WorldDef& def, int threads = 1);
/// Moves particles [begin, end) by v·dt and wraps them, marking and writing cells as `wrap`
/// and `cells` ask (move's periodic path).
void moveAndWrapBlock(ParticleArrays& p, double dt, const MoveWrap& wrap,
                      const GridBroadPhase::MoveCells* cells, std::size_t begin, std::size_t end);
/// wrap() for particles [begin, end), moving the start positions `wrap` names with them.
void wrapBlock(ParticleArrays& p, const MoveWrap& wrap, std::size_t begin, std::size_t end);
/// wrap() for the discs of `pairs` only: after move wrapped every centre, separate moves no
/// others.
void wrapPairs(ParticleArrays& p, const WorldDef& def, const std::vector<ContactPair>& pairs);

/// Copies the positions at the start of the step into ctx.startX/startY, where the obstacles
/// stage's sweep begins.
void saveStartPositions(const ParticleArrays& p, StepContext& ctx);
/// Particles against the world's fixed obstacles (discrete_obstacles.cpp says how): sweeps each
/// particle's move since saveStartPositions, stops it at its first contact, pushes it out of
/// overlaps and turns its velocity into an obstacle around with the walls' law. Never moves a
/// centre through a segment or (with walls) out of the box.
void obstacles(ParticleArrays& p, const WorldDef& def, StepContext& ctx, StepCounters& counters);

/// Runs the stages above in order for one step of `dt` seconds, timing each into `profile`
/// (added to what it holds, so substeps accumulate).
void discreteStep(ParticleArrays& p, const WorldDef& def, double dt, StepContext& ctx,
                  StepProfile& profile, StepCounters& counters);

/// One World::step in the discrete or substep mode: the storage reorder when it is due
/// (particle_reorder.hpp; counted in calls of this function, stepsUntilReorder is the world's
/// state), then `substeps` discrete steps of dt / substeps.
void discreteSteps(ParticleArrays& p, detail::IdTable& ids, const WorldDef& def, double dt,
                   int substeps, StepContext& ctx, unsigned& stepsUntilReorder,
                   StepProfile& profile, StepCounters& counters);

}  // namespace psb::stages
