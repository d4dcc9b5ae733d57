#include "session/physics_controls.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace psb::app {

double steppedRestitution(double e, int direction) {
    // Snap to the grid, so that twenty presses from 1 land on 0 exactly, not on 1e-16.
    const double n = kRestitutionSteps;
    const double steps = std::round(e * n) + (direction < 0 ? -1.0 : 1.0);
    return std::clamp(steps / n, 0.0, 1.0);
}

cmd::SetRestitution restitutionStep(double e, int direction) {
    return {steppedRestitution(e, direction)};
}

Vec2 appGravity() {
    return {0.0, kEarthGravity};
}

cmd::SetGravity gravityToggle(const Vec2& gravity, const Vec2& sceneGravity) {
    if (gravity != Vec2::Zero()) return {false};
    if (sceneGravity == Vec2::Zero()) return {true, appGravity().norm()};
    return {true, sceneGravity.norm(), false, sceneGravity};
}

Vec2 gravityOf(const cmd::SetGravity& c) {
    if (!c.on) return Vec2::Zero();
    // Scaled by g / |direction|: the scene's own vector comes back bit for bit.
    return c.direction * (c.g / c.direction.norm());
}

StepMode nextMode(StepMode mode) {
    switch (mode) {
        case StepMode::Discrete:
            return StepMode::Substep;
        case StepMode::Substep:
            return StepMode::Exact;
        case StepMode::Exact:
            return StepMode::Discrete;
    }
    return StepMode::Discrete;
}

cmd::SetMode modeStep(const SolverSettings& solver) {
    return {nextMode(solver.mode), solver.substeps < 2 ? kAppSubsteps : solver.substeps};
}

std::string gravityText(const Vec2& g, const Axes& axes) {
    if (g == Vec2::Zero()) return "off";
    const Vec2 shown = axes.vector(g);
    char buf[64];
    std::snprintf(buf, sizeof buf, "[%.4g, %.4g] m/s\u00b2", shown.x(), shown.y());
    return buf;
}

std::string modeName(const SolverSettings& solver) {
    std::string name(toString(solver.mode));
    if (solver.mode == StepMode::Substep) name += " x" + std::to_string(solver.substeps);
    return name;
}

}  // namespace psb::app
