#pragma once
// The scene the frame-time benchmark draws.

#include <cstddef>
#include <cstdint>

#include <particle_sandbox/scene.hpp>

namespace psb::app {

/// `count` equal particles (radius 2 m, mass 1 kg) in a square box at an area fraction of 0.2,
/// never overlapping, at kT = 800 J (speeds of tens of m/s): psb::scenes::gas, stepped in
/// frames of 1/120 s (its dt). Used by the frame-time benchmark. `turning`: every particle
/// spins (one turn a second either way, at random), so that the world keeps rotation and each
/// disc draws its spin mark. `mixedMasses`: the masses are 1, 2, 3 and 4 kg in turn, so that
/// each disc is shaded by its mass (view/mass_shade.hpp).
[[nodiscard]] Scene benchmarkScene(std::size_t count, std::uint32_t seed = 1, bool turning = false,
                                   bool mixedMasses = false);

}  // namespace psb::app
