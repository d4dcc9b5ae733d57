#pragma once
/// \file
/// Definition and snapshot of one particle.

#include <particle_sandbox/color.hpp>
#include <particle_sandbox/math.hpp>
#include <particle_sandbox/particle_id.hpp>

namespace psb {

/// What a new particle is made of. Validated by World::add.
struct ParticleDef {
    Vec2 position = Vec2::Zero();  ///< centre, metres
    Vec2 velocity = Vec2::Zero();  ///< metres per second
    double mass = 1.0;             ///< kilograms, finite and >= DBL_MIN (so 1/mass is finite)
    double radius = 1.0;           ///< metres, finite and > 0
    Color color{};
};

/// A copy of one particle's state, as World::get returns it.
struct Particle {
    ParticleId id;
    Vec2 position = Vec2::Zero();  ///< metres
    Vec2 velocity = Vec2::Zero();  ///< metres per second
    double mass = 1.0;             ///< kilograms
    double radius = 1.0;           ///< metres
    Color color{};
};

}  // namespace psb
