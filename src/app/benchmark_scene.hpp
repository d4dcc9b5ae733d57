#pragma once
// The world the frame-time benchmark draws.

#include <cstddef>
#include <cstdint>

#include <particle_sandbox/world.hpp>

namespace psb::app {

/// `count` equal particles (radius 2 m, mass 1 kg) on a jittered lattice in a square box sized
/// for an area fraction of about 0.2, never overlapping, with random velocities up to 50 m/s.
/// Used by the frame-time benchmark.
[[nodiscard]] World benchmarkWorld(std::size_t count, std::uint32_t seed = 1);

}  // namespace psb::app
