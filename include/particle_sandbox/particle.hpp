#pragma once
/// \file
/// Definition and snapshot of one particle.

#include <particle_sandbox/color.hpp>
#include <particle_sandbox/math.hpp>
#include <particle_sandbox/particle_id.hpp>

namespace psb {

/// The inertia factor k of a particle made without one: I = k m r² with k = 1/2, a uniform disc.
inline constexpr double kDefaultInertiaFactor = 0.5;
/// The smallest inertia factor a particle takes: contacts divide by k (a spin's share of an
/// impulse goes as 1/k), and a k of 1e-320 made them NaN. No solid body comes near it (a disc
/// with all its mass in a centre of a tenth of its radius has k = 0.005).
inline constexpr double kMinInertiaFactor = 0.001;

/// What a new particle is made of. Validated by World::add.
struct ParticleDef {
    Vec2 position = Vec2::Zero();  ///< centre, metres
    Vec2 velocity = Vec2::Zero();  ///< metres per second
    double mass = 1.0;             ///< kilograms, finite and >= DBL_MIN (so 1/mass is finite)
    double radius = 1.0;           ///< metres, finite and > 0
    Color color{};
    double angle = 0.0;            ///< radians, finite; positive turns +x toward +y
    double angularVelocity = 0.0;  ///< radians per second, finite; 0 if fixedRotation
    /// k in I = k m r², from kMinInertiaFactor to 1: 1/2 a uniform disc, 2/5 a ball, 1 a ring.
    double inertiaFactor = kDefaultInertiaFactor;
    bool fixedRotation = false;  ///< never turns (a sliding puck): contacts give it no spin
};

/// A copy of one particle's state, as World::get returns it.
struct Particle {
    ParticleId id;
    Vec2 position = Vec2::Zero();  ///< metres
    Vec2 velocity = Vec2::Zero();  ///< metres per second
    double mass = 1.0;             ///< kilograms
    double radius = 1.0;           ///< metres
    Color color{};
    double angle = 0.0;            ///< radians, positive turns +x toward +y
    double angularVelocity = 0.0;  ///< radians per second, positive turns +x toward +y
    double inertiaFactor = kDefaultInertiaFactor;  ///< k in I = k m r²
    bool fixedRotation = false;                    ///< never turns
};

}  // namespace psb
