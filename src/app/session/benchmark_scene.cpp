#include "session/benchmark_scene.hpp"

#include <algorithm>
#include <numbers>

#include <particle_sandbox/scene_builders.hpp>

namespace psb::app {

Scene benchmarkScene(std::size_t count, std::uint32_t seed, bool turning, bool mixedMasses) {
    // The core's gas builder: equal discs on the generate block's jittered lattice.
    Scene s = scenes::gas({.count = std::max<std::size_t>(count, 1),
                           .radius = 2.0,
                           .packing = 0.2,
                           .mass = 1.0,
                           .temperature = 800.0,  // speeds of tens of m/s
                           .seed = seed});
    s.dt = 1.0 / 120.0;
    if (count == 0) s.particles.clear();
    if (turning) {
        // The gas has no friction: the spins stay as given, and the step is the gas's.
        for (std::size_t i = 0; i < s.particles.size(); ++i)
            s.particles[i].angularVelocity = (i % 2 == 0 ? 2.0 : -2.0) * std::numbers::pi;
    }
    if (mixedMasses) {
        for (std::size_t i = 0; i < s.particles.size(); ++i)
            s.particles[i].mass = 1.0 + static_cast<double>(i % 4);
    }
    return s;
}

}  // namespace psb::app
