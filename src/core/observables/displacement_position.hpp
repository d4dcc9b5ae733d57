#pragma once
// The position a particle's displacement is measured from (MSD): the unwrapped centre, the one
// that moved continuously since the particle was added (ParticleArrays::unwrapX, unwrapY).

#include <cstddef>

#include <particle_sandbox/particle_arrays.hpp>
#include <particle_sandbox/world.hpp>

namespace psb::observables {

/// Particle `i`'s position for displacements, metres: its stored centre plus what a periodic
/// box's wraps took off it, so that the MSD does not jump by a box at each crossing. In a box
/// with walls nothing wraps and the unwrap arrays are empty.
inline void displacementPosition(const World& /*world*/, const ParticleArrays& p, std::size_t i,
                                 double& x, double& y) {
    const bool wrapped = !p.unwrapX.empty();
    x = p.x[i] + (wrapped ? p.unwrapX[i] : 0.0);
    y = p.y[i] + (wrapped ? p.unwrapY[i] : 0.0);
}

}  // namespace psb::observables
