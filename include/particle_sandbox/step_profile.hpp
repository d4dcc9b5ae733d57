#pragma once
/// \file
/// What a step did and where its time went.

#include <cstdint>

namespace psb {

/// Wall-clock milliseconds spent in each stage of the last call to World::step, summed over its
/// substeps. A stage the world skipped (no gravity, no walls, ...) reads 0.
struct StepProfile {
    double gravity = 0.0;
    double move = 0.0;
    double findPairs = 0.0;
    double resolve = 0.0;
    double separate = 0.0;
    double walls = 0.0;
    double obstacles = 0.0;  ///< particles against fixed obstacles (skipped without any)
    double reorder = 0.0;  ///< sorting storage by grid cell (every few steps in large worlds)
    double total = 0.0;
    std::uint64_t pairs = 0;  ///< overlapping pairs the broadphase found (summed over substeps)
};

/// Running totals since the world was made (or since resetCounters).
struct StepCounters {
    std::uint64_t steps = 0;       ///< calls of the discrete step (substeps count each)
    std::uint64_t collisions = 0;  ///< particle–particle collisions resolved (approaching pairs)
    std::uint64_t wallCollisions = 0;  ///< wall rebounds (outward-moving particle turned inward)
    double wallImpulse = 0.0;          ///< sum of |normal impulse| delivered by walls, kg·m/s
    double maxOverlap = 0.0;           ///< deepest pair overlap found by detection, metres
    std::uint64_t events = 0;          ///< exact mode: events processed (collisions, walls, cells)
    std::uint64_t obstacleCollisions = 0;  ///< rebounds off fixed obstacles (pegs, segments)
};

}  // namespace psb
