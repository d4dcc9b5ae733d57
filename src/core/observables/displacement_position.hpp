#pragma once
// The position a particle's displacement is measured from (MSD): one function, so that the
// periodic box's unwrapped position replaces the stored one in one line.

#include <cstddef>

#include <particle_sandbox/particle_arrays.hpp>
#include <particle_sandbox/world.hpp>

namespace psb::observables {

/// Particle `i`'s position for displacements, metres. In a box with walls no particle ever
/// wraps, so the stored position is the unwrapped one. With periodic boxes this must return the
/// unwrapped position (the world's accessor for it), or the MSD would jump by a box at each
/// crossing.
inline void displacementPosition(const World& /*world*/, const ParticleArrays& p, std::size_t i,
                                 double& x, double& y) {
    x = p.x[i];
    y = p.y[i];
}

}  // namespace psb::observables
