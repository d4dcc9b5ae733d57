#pragma once
// Reordering particle storage by grid cell, for memory locality.
//
// The broadphases read the positions of a particle's neighbours. In insertion order those sit
// anywhere in memory, and at 10^5–10^6 particles nearly every neighbour read misses the cache.
// Every kReorderInterval steps (from kReorderMinParticles particles up) World sorts its storage
// by grid cell, so that neighbours in space are neighbours in memory; particles drift only a
// fraction of a cell between reorders.
//
// The permutation is the grid's counting-sort order, computed from the state alone (not from the
// broadphase in use), and it is applied in place by following its cycles, so it needs no second
// copy of the arrays. Every moved particle's id is relocated in the IdTable: ids stay valid,
// storage indices (and so the order in which overlapping particles are drawn) change.

#include <cstddef>

#include <particle_sandbox/detail/id_table.hpp>
#include <particle_sandbox/particle_arrays.hpp>
#include <particle_sandbox/world.hpp>

#include "world/step_context.hpp"

namespace psb {

// kReorderMinParticles and kReorderInterval are public (world.hpp): benchmarks time whole
// intervals.

/// Sorts `p` by grid cell in place and relocates every moved id in `ids`. Uses ctx's grid as
/// scratch (its pair lists are invalid afterwards until the next build).
void reorderByCell(ParticleArrays& p, detail::IdTable& ids, StepContext& ctx);

}  // namespace psb
