#pragma once
// Small helpers shared by the core tests.

#include <cmath>

#include <particle_sandbox/world.hpp>

namespace psb::test {

/// A world with walls off and the given restitution: pair tests that must not see a wall.
inline World openWorld(double restitution = 1.0, double friction = 0.0) {
    WorldDef def;
    def.width = 1e6;
    def.height = 1e6;
    def.walls = false;
    def.restitution = restitution;
    def.friction = friction;
    return World(def);
}

inline double relErr(double got, double want) {
    const double scale = std::max(std::abs(want), 1e-300);
    return std::abs(got - want) / scale;
}

}  // namespace psb::test
