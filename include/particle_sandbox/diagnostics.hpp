#pragma once
/// \file
/// Conserved quantities, measured.

#include <particle_sandbox/math.hpp>
#include <particle_sandbox/particle_id.hpp>

namespace psb {

class World;

/// Total kinetic energy of translation Σ ½ m |v|², joules. Summed with compensation so that it
/// is reliable to ~1e-15 relative even for a million particles.
[[nodiscard]] double kineticEnergy(const World& world);

/// Total kinetic energy of rotation Σ ½ I ω² with I = k m r², joules; 0 in a world that keeps
/// no rotation (World::rotationInUse). Summed with compensation.
[[nodiscard]] double rotationalEnergy(const World& world);

/// Total angular momentum about `point` (metres): orbital Σ m (r − point) × v plus spin Σ I ω,
/// kg·m²/s, with a × b = a_x b_y − a_y b_x, so that it has the sign of ω: positive turns +x
/// toward +y (clockwise on a screen whose y points down). About the box's top-left corner
/// (the origin) by default. Summed with compensation.
[[nodiscard]] double angularMomentum(const World& world, const Vec2& point = Vec2::Zero());

/// Rotational energy Σ ½ I ω² of one particle, joules; throws InvalidArgument for a dead id.
[[nodiscard]] double rotationalEnergy(const World& world, ParticleId id);

/// Total gravitational potential energy Σ m g·(r_ref − r), joules: m g h for every particle,
/// h its height above the reference level, the side (or corner) of the box furthest along
/// gravity: with gravity (0, g) downwards (y points down) that is the floor, y = height, so a
/// particle at height h above the floor counts m·g·h and one on the floor m·g·r. Held particles
/// count like any other (as in kineticEnergy). 0 without gravity. Summed with compensation.
[[nodiscard]] double potentialEnergy(const World& world);

/// kineticEnergy + rotationalEnergy + potentialEnergy: conserved by elastic collisions under
/// gravity, and by rolling without slipping.
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
