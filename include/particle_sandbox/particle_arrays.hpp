#pragma once
/// \file
/// Structure-of-arrays particle storage, as the core keeps it.

#include <cstddef>
#include <cstdint>
#include <vector>

#include <particle_sandbox/color.hpp>
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

    [[nodiscard]] std::size_t size() const { return x.size(); }
    [[nodiscard]] bool isKinematic(std::size_t i) const { return invMass[i] == 0.0; }
};

}  // namespace psb
