#pragma once
// The records of collision_log.hpp, made from what a stepper knows at a contact: the velocities
// before and after, the masses. Shared by the discrete stages and the exact stepper.

#include <cstdint>

#include <particle_sandbox/collision_log.hpp>

namespace psb {

/// A pair's record. The impulse on a is m_a Δv_a; a held a (inverse mass 0, moved by its owner,
/// not by the contact) gives what b received, reversed: −m_b Δv_b.
[[nodiscard]] inline Collision pairCollision(double time, ParticleId a, ParticleId b,
                                             const Vec2& aBefore, const Vec2& aAfter,
                                             const Vec2& bBefore, const Vec2& bAfter,
                                             double aInverseMass, double aMass, double bMass) {
    Collision c;
    c.time = time;
    c.with = Collision::With::Particle;
    c.a = a;
    c.b = b;
    c.aBefore = aBefore;
    c.aAfter = aAfter;
    c.bBefore = bBefore;
    c.bAfter = bAfter;
    c.impulse =
        aInverseMass > 0.0 ? Vec2(aMass * (aAfter - aBefore)) : Vec2(-bMass * (bAfter - bBefore));
    return c;
}

/// A rebound off a wall (`where` a WallSide) or a fixed obstacle (`where` its index).
[[nodiscard]] inline Collision surfaceCollision(double time, Collision::With with,
                                                std::uint32_t where, ParticleId a,
                                                const Vec2& before, const Vec2& after,
                                                double mass) {
    Collision c;
    c.time = time;
    c.with = with;
    c.a = a;
    c.where = where;
    c.aBefore = before;
    c.aAfter = after;
    c.impulse = mass * (after - before);
    return c;
}

}  // namespace psb
