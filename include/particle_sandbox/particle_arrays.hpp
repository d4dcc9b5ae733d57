#pragma once
/// \file
/// Structure-of-arrays particle storage, as the core keeps it.

#include <cstddef>
#include <cstdint>
#include <vector>

#include <particle_sandbox/color.hpp>
#include <particle_sandbox/particle.hpp>
#include <particle_sandbox/particle_id.hpp>

namespace psb {

/// Hot data first (positions, velocities, inverse masses, radii), cold data last. Index i of
/// every array is the same particle; indices are dense (0..size-1) and change when a particle is
/// removed (the last one moves into the hole), so outside the core reach particles through
/// `id[i]` and World's id-based API. World hands out only a const reference to this struct.
struct ParticleArrays {
    std::vector<double> x, y;     ///< centre, metres
    std::vector<double> vx, vy;   ///< velocity, metres per second
    std::vector<double> invMass;  ///< 1 / mass, 1/kg; 0 for a kinematic (held) particle
    std::vector<double> radius;   ///< metres
    std::vector<double> mass;     ///< kilograms (kept even while kinematic)
    std::vector<Color> color;
    std::vector<ParticleId> id;  ///< the stable id of the particle stored at each index

    /// Rotation, kept only while `rotation` is true (then each array has size() entries; else
    /// all are empty and every particle has angle 0, angular velocity 0, inertia factor
    /// kDefaultInertiaFactor and turns freely). A scene without friction and without spin never
    /// needs them, and its steps never read them. Positive angles and angular velocities turn
    /// +x toward +y (clockwise on a screen whose y points down).
    bool rotation = false;
    std::vector<double> angle;                ///< radians
    std::vector<double> omega;                ///< angular velocity, radians per second
    std::vector<double> inertiaFactor;        ///< k in I = k m r², 0.001 to 1
    std::vector<std::uint8_t> fixedRotation;  ///< 1: never turns (omega stays 0)

    /// Periodic boxes (WorldDef::periodic): what the wraps across the edges have taken off each
    /// centre, metres, kept only while `periodic` is true (then each array has size() entries;
    /// else both are empty). The unwrapped centre, the one that moved continuously since the
    /// particle was added, is (x[i] + unwrapX[i], y[i] + unwrapY[i]); a displacement between
    /// two instants is the difference of unwrapped centres (World::unwrappedPosition).
    bool periodic = false;
    std::vector<double> unwrapX, unwrapY;

    [[nodiscard]] std::size_t size() const { return x.size(); }
    [[nodiscard]] bool isKinematic(std::size_t i) const { return invMass[i] == 0.0; }
    /// 1/k, or 0 for a particle that never turns: the share of a tangential impulse that goes
    /// into its spin (contact.hpp). Requires `rotation`.
    [[nodiscard]] double spinWeight(std::size_t i) const {
        return fixedRotation[i] ? 0.0 : 1.0 / inertiaFactor[i];
    }
};

}  // namespace psb
