#include "session/physics_controls.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <particle_sandbox/error.hpp>

namespace psb::app {

double steppedRestitution(double e, int direction) {
    // Snap to the grid, so that twenty presses from 1 land on 0 exactly, not on 1e-16.
    const double steps = std::round(e / kRestitutionStep) + (direction < 0 ? -1.0 : 1.0);
    return std::clamp(steps * kRestitutionStep, 0.0, 1.0);
}

ControlChange stepRestitution(World& world, int direction) {
    const double before = world.def().restitution;
    const double e = steppedRestitution(before, direction);
    world.setRestitution(e);
    char buf[64];
    std::snprintf(buf, sizeof buf, "Restitution %.2f", e);
    return {e != before, buf};
}

Vec2 appGravity() {
    return {0.0, kEarthGravity};
}

std::string gravityText(const Vec2& g) {
    if (g == Vec2::Zero()) return "off";
    char buf[64];
    std::snprintf(buf, sizeof buf, "[%.4g, %.4g] m/s\u00b2", g.x(), g.y());
    return buf;
}

ControlChange toggleGravity(World& world, const Vec2& sceneGravity) {
    if (world.def().gravity != Vec2::Zero()) {
        world.setGravity(Vec2::Zero());
        return {true, "Gravity off"};
    }
    const Vec2 g = sceneGravity != Vec2::Zero() ? sceneGravity : appGravity();
    try {
        world.setGravity(g);
    } catch (const InvalidArgument& e) {
        return {false, std::string("Gravity refused: ") + e.what()};
    }
    return {true, "Gravity " + gravityText(g)};
}

}  // namespace psb::app
