#include "session/particle_edit.hpp"
#include "session/units.hpp"

#include <cstdio>

#include <particle_sandbox/error.hpp>

namespace psb::app {

EditResult writeEdit(World& world, const CheckedEdit& edit, const Axes& axes) {
    if (!edit.passed()) return {false, edit.refusal};
    const ParticleId id = edit.id;
    const double mass = edit.values.mass, radius = edit.values.radius;
    const Vec2& position = edit.values.position;
    const Vec2& velocity = edit.values.velocity;
    const double omega = edit.values.omega, k = edit.values.inertiaFactor;
    const Vec2& wanted = edit.wanted;
    const Particle old = world.get(id);
    // The checks (edit_prompt.hpp) follow the setters' own rules, so none of them throws
    // half-way; the catch keeps that promise should the rules ever drift apart.
    try {
        world.setMass(id, mass);
        world.setRadius(id, radius);
        world.setPosition(id, position);
        world.setVelocity(id, velocity);
        // Only when changed: a world that keeps no rotation keeps none after an edit of the
        // rest.
        if (k != old.inertiaFactor) world.setInertiaFactor(id, k);
        if (omega != old.angularVelocity) world.setAngularVelocity(id, omega);
    } catch (const InvalidArgument& e) {
        world.setMass(id, old.mass);
        world.setRadius(id, old.radius);
        world.setPosition(id, old.position);
        world.setVelocity(id, old.velocity);
        if (k != old.inertiaFactor) world.setInertiaFactor(id, old.inertiaFactor);
        if (omega != old.angularVelocity) world.setAngularVelocity(id, old.angularVelocity);
        return {false, e.what()};
    }
    char buf[200];
    // At most three figures, as a person reads them ("radius 0.142857 m" before), and a
    // vector's parts joined by a space no line breaks at ("[-1, / 0]" wrapped over two lines).
    std::snprintf(buf, sizeof buf, "Edited particle %llu: mass %s kg, radius %s m, velocity %s m/s",
                  static_cast<unsigned long long>(particleNumber(id)), plainNumber(mass, 3).c_str(),
                  plainNumber(radius, 3).c_str(),
                  pair(velocity.x(), axes.up(velocity.y())).c_str());
    std::string message = buf;
    if (world.rotationInUse()) {
        std::snprintf(buf, sizeof buf, ", omega %s rad/s, k %s",
                      plainNumber(axes.spin(omega), 3).c_str(), plainNumber(k, 3).c_str());
        message += buf;
    }
    if (position != wanted) {
        message += "; moved to " + pair(position.x(), axes.y(position.y()), 2) +
                   " m to stay inside the walls";
    } else if (position != old.position) {
        // A move says where to (an edit of x or y would otherwise read as if nothing changed).
        message += "; now at " + pair(position.x(), axes.y(position.y())) + " m";
    }
    return {true, message};
}

EditResult applyEdit(World& world, ParticleId id, const std::array<std::string, kEditFields>& texts,
                     const Axes& axes) {
    return writeEdit(world, checkEdit(world, id, texts, axes), axes);
}

EditResult editParticleValue(World& world, ParticleId id, ParticleField field,
                             std::string_view text, const Axes& axes) {
    return writeEdit(world, checkValue(world, id, field, text, axes), axes);
}

}  // namespace psb::app
