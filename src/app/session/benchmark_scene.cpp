#include "session/benchmark_scene.hpp"

#include <algorithm>

#include <particle_sandbox/scene_builders.hpp>

namespace psb::app {

Scene benchmarkScene(std::size_t count, std::uint32_t seed) {
    // The core's gas builder: equal discs on the generate block's jittered lattice.
    Scene s = scenes::gas({.count = std::max<std::size_t>(count, 1),
                           .radius = 2.0,
                           .packing = 0.2,
                           .mass = 1.0,
                           .temperature = 800.0,  // speeds of tens of m/s
                           .seed = seed});
    s.dt = 1.0 / 120.0;
    if (count == 0) s.particles.clear();
    return s;
}

}  // namespace psb::app
