#pragma once
// A small gas for the session's tests: 40 discs in the default 700 m box, moving every way.

#include <cmath>

#include <particle_sandbox/world.hpp>

namespace psb::app {

[[nodiscard]] inline World gasWorld(Vec2 gravity = Vec2::Zero()) {
    WorldDef def;  // 700 m × 700 m, walls on
    def.gravity = gravity;
    World w(def);
    for (int k = 0; k < 40; ++k) {
        ParticleDef d;
        d.position = {40.0 + 60.0 * (k % 10), 60.0 + 80.0 * (k / 10)};
        d.velocity = {std::cos(k) * 80.0, std::sin(k) * 80.0};
        d.radius = 8.0;
        d.mass = 1.0 + k % 3;
        w.add(d);
    }
    return w;
}

}  // namespace psb::app
