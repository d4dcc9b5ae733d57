#pragma once
// Accuracy metrics of a time-stepped run, measured against the exact (event-driven) run of the
// same scene for the same simulated time.
//
// Missed collisions. The discrete step moves every particle in a straight line over the step
// (x += v·h, after gravity) and only then looks for overlapping pairs. For each pair and each
// (sub)step, with d0 the centre-to-centre vector at the start, D = (v_j − v_i)·h its change
// over the move and σ = r_i + r_j, the pair is a *missed collision* in that step when
//   - it did not touch at the start:                |d0| ≥ σ,
//   - it does not overlap at the end of the move:   |d0 + D| ≥ σ (so detection cannot see it),
//   - and its straight-line relative path came within σ: min over s in [0, 1] of |d0 + s·D| < σ.
// Since the minimum then lies strictly inside the step, the pair is receding at the end of the
// move, so the next step cannot catch it either: it tunnelled through (or grazed) its partner.
// A pair that overlaps at the end of the move is *detected*; its depth σ − |d0 + D|, divided by
// the smaller radius, is the overlap the step has to repair.
//
// Cost: pairs are found by sweep-and-prune on the x extent of each particle's swept disc, so a
// step costs O(N log N + K), K the pairs whose swept extents overlap in x.

#include <cstdint>
#include <vector>

#include <particle_sandbox/math.hpp>
#include <particle_sandbox/particle_arrays.hpp>

namespace psb::cli {

/// What one discrete move of h seconds does to the pairs, from the state before the step.
struct MoveCheck {
    std::uint64_t missed = 0;           ///< pairs that crossed within σ unseen (definition above)
    std::uint64_t detected = 0;         ///< pairs overlapping at the end of the move
    double maxOverlapOverRadius = 0.0;  ///< deepest detected overlap / smaller radius
};

/// Checks the straight-line move of h seconds that a discrete step would make from state `p`
/// (velocities first changed by gravity·h, as the step does). Kinematic particles move too.
[[nodiscard]] MoveCheck checkMove(const ParticleArrays& p, double h, const Vec2& gravity);

/// The totals of a time-stepped or exact run, the inputs of the error measures.
struct RunTotals {
    double simTime = 0.0;      ///< seconds
    double wallSeconds = 0.0;  ///< time spent in World::step only
    double cpuSeconds = 0.0;   ///< process CPU time of the stepping (NaN: not measured)
    std::uint64_t particles = 0;
    std::uint64_t steps = 0;       ///< discrete (sub)steps, or exact frames
    std::uint64_t collisions = 0;  ///< particle–particle
    std::uint64_t wallCollisions = 0;
    std::uint64_t missed = 0;  ///< summed MoveCheck::missed (0 for exact)
    double maxOverlapOverRadius = 0.0;
    double kineticEnergyInitial = 0.0;  ///< joules
    double kineticEnergyFinal = 0.0;    ///< joules
    double wallImpulse = 0.0;           ///< kg·m/s, summed over the run
    double wallLength = 0.0;            ///< perimeter of the box, metres (0: no walls)
    std::vector<Vec2> finalPositions;   ///< every particle's centre at the end, storage order
    double smallestRadius = 0.0;        ///< metres
};

/// Wall pressure: wall impulse per unit time per unit wall length, N/m. NaN without walls or
/// without simulated time.
[[nodiscard]] double wallPressure(const RunTotals& r);

/// The errors of `run` against `exact` (same scene, same simulated time).
struct ErrorMeasures {
    double collisionRatio = 0.0;  ///< collisions / exact collisions (NaN if exact has none)
    std::uint64_t missed = 0;     ///< missed collisions (MoveCheck)
    double maxOverlapOverRadius = 0.0;
    /// |KE(T) − KE_exact(T)| / KE(0): the energy the stepping gained or lost that the exact run
    /// did not. With e = 1 it is the drift; with e < 1 the error in the cooling. NaN if KE(0) = 0.
    double kineticEnergyError = 0.0;
    double pressureRatio = 0.0;  ///< wall pressure / exact wall pressure (NaN if exact's is 0)
    /// The farthest any particle ends from where the exact run puts it, over the smallest
    /// radius: the trajectory error of a scene with a closed form (a disc rolling down a slope,
    /// slipping then rolling on a floor); in a gas, where trajectories part after a few
    /// collisions, only a sign of chaos. NaN if the runs' particles do not match.
    double positionErrorOverRadius = 0.0;
    double wallSecondsPerSimSecond = 0.0;
    double cpuSecondsPerSimSecond = 0.0;  ///< the same in CPU time: less sensitive to load
    double nsPerParticleStep = 0.0;       ///< wall ns / (particles × steps)
};

[[nodiscard]] ErrorMeasures compareToExact(const RunTotals& run, const RunTotals& exact);

}  // namespace psb::cli
