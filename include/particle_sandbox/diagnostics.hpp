#pragma once
/// \file
/// Conserved quantities, measured.

#include <particle_sandbox/math.hpp>
#include <particle_sandbox/particle_id.hpp>

namespace psb {

class World;

/// Total kinetic energy Σ ½ m |v|², joules. Summed with compensation so that it is reliable to
/// ~1e-15 relative even for a million particles.
[[nodiscard]] double kineticEnergy(const World& world);

/// Total gravitational potential energy Σ m g·(r_ref − r), joules: m g h for every particle,
/// h its height above the reference level, the side (or corner) of the box furthest along
/// gravity: with gravity (0, g) downwards (y points down) that is the floor, y = height, so a
/// particle at height h above the floor counts m·g·h and one on the floor m·g·r. Held particles
/// count like any other (as in kineticEnergy). 0 without gravity. Summed with compensation.
[[nodiscard]] double potentialEnergy(const World& world);

/// kineticEnergy + potentialEnergy: conserved by elastic collisions under gravity.
[[nodiscard]] double mechanicalEnergy(const World& world);

/// Total linear momentum Σ m v, kg·m/s.
[[nodiscard]] Vec2 momentum(const World& world);

/// Momentum m v of one particle, kg·m/s; throws InvalidArgument for a dead id.
[[nodiscard]] Vec2 momentum(const World& world, ParticleId id);

/// Centre of mass, metres (the box centre for an empty world).
[[nodiscard]] Vec2 centreOfMass(const World& world);

/// Deepest overlap r_i + r_j − |x_j − x_i| between any two particles of the current state,
/// metres; 0 when no two discs overlap. Uses the broadphase the discrete step would use (grid or
/// quadtree, about one step's pair search), so it is cheap enough to ask every frame. Unlike
/// StepCounters::maxOverlap, which records overlaps met by the step's collision detection, this
/// sees a pair however it came to overlap (placed, dragged, resized).
[[nodiscard]] double maxOverlap(const World& world);

/// Deepest overlap between any two particles right now, metres (all pairs; O(n²), for tests
/// and small worlds).
[[nodiscard]] double maxOverlapBruteForce(const World& world);

}  // namespace psb
