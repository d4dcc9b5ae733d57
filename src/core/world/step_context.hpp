#pragma once
// Per-step scratch, kept between steps so that a steady-state step allocates nothing.

#include <array>
#include <cstdint>
#include <vector>

#include <particle_sandbox/collision_log.hpp>
#include <particle_sandbox/solver_settings.hpp>

#include "broadphase/broad_phase_grid.hpp"
#include "broadphase/broad_phase_periodic_grid.hpp"
#include "broadphase/broad_phase_quadtree.hpp"
#include "broadphase/contact_pair.hpp"
#include "broadphase/particle_stats.hpp"
#include "obstacles/obstacle_grid.hpp"
#include "support/periodic_box.hpp"

namespace psb {

struct StepContext {
    int threads = 1;  ///< threads the parallel stages may use (>= 1)
    BroadPhaseKind broadPhase = BroadPhaseKind::Auto;          ///< as the solver settings ask
    BroadPhaseKind broadPhaseUsed = BroadPhaseKind::AllPairs;  ///< what the last step used
    std::vector<ContactPair> pairs;
    GridBroadPhase grid;
    QuadtreeBroadPhase quadtree;
    // A periodic box (WorldDef::periodic), set by the step: pairs are found and measured
    // between nearest images, and the grid is the one whose cells wrap.
    bool periodic = false;
    periodic::Box box;
    PeriodicGridBroadPhase periodicGrid;
    std::vector<ParticleStats> statsScratch;  ///< per-block bounds
    bool statsFresh = false;  ///< statsScratch describes the current positions (set by move)
    bool cellsFresh = false;  ///< move wrote the grid's cells for the current positions
    bool marksFresh = false;  ///< move marked the centres near the periodic box's edges
    std::vector<double> wallImpulseScratch;
    std::vector<std::uint64_t> wallHitScratch;
    // The obstacles stage (discrete_obstacles.cpp); untouched in a world without obstacles.
    ObstacleGrid obstacleGrid;
    std::vector<double> startX, startY;  ///< positions at the start of the step
    /// Per storage slot, a disc that no obstacle's surface and no wall enters
    /// (discrete_obstacles.cpp): a fact about the obstacles and the box, whichever particle the
    /// slot holds. Radius < 0: none yet.
    std::vector<float> freeX, freeY, freeRadius;
    std::array<double, 3> freeBox{};  ///< width, height, walls (1 or 0) the discs were made in
    std::vector<std::vector<std::uint32_t>> obstacleCandidates;  ///< one list per block
    std::vector<std::vector<std::uint32_t>> obstacleNearby;      ///< box queries, per block
    std::vector<std::uint64_t> obstacleFallbackScratch;  ///< box queries last step, per block
    std::vector<std::uint64_t> obstacleHitScratch;
    std::vector<std::uint64_t> obstacleWallHitScratch;  ///< wall rebounds the stage made
    std::vector<double> obstacleWallImpulseScratch;
    // Recording collisions (collision_log.hpp): null when the world records none, and then the
    // stages do exactly what they do without it.
    CollisionLog* collisionLog = nullptr;
    /// Add each pair collision's r_ij·J_ij to StepCounters::pairVirial (World::setMeasureVirial).
    bool measureVirial = false;
    double stepStart = 0.0;      ///< World::time() when the step began, seconds
    double collisionTime = 0.0;  ///< the end of the substep being run, seconds
    std::vector<std::vector<Collision>> collisionScratch;  ///< per block: walls and obstacles
};

}  // namespace psb
