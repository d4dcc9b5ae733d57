#include "session/edit_prompt.hpp"
#include "session/units.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <system_error>

#include <particle_sandbox/detail/float_chars.hpp>

namespace psb::app {

namespace {

/// An edit of `id` refused, saying `why`.
CheckedEdit refused(ParticleId id, std::string why) {
    CheckedEdit e;
    e.id = id;
    e.refusal = std::move(why);
    return e;
}

std::string_view trim(std::string_view s) {
    while (!s.empty() && s.front() == ' ')
        s.remove_prefix(1);
    while (!s.empty() && s.back() == ' ')
        s.remove_suffix(1);
    return s;
}

/// The number in `text`, or nullopt with `why` set.
std::optional<double> parseNumber(const std::string& name, std::string_view text,
                                  std::string& why) {
    const std::string_view t = trim(text);
    if (t.empty()) {
        why = name + ": empty, expected a number";
        return std::nullopt;
    }
    // from_chars takes no leading '+'; a user may well type one.
    const std::string_view digits = t.front() == '+' ? t.substr(1) : t;
    double v = 0.0;
    const auto [end, ec] = detail::fromChars(digits.data(), digits.data() + digits.size(), v);
    if (ec == std::errc::result_out_of_range) {
        why = name + ": " + std::string(t) + " is out of range";
        return std::nullopt;
    }
    if (ec != std::errc() || end != digits.data() + digits.size()) {
        why = name + ": '" + std::string(t) + "' is not a number";
        return std::nullopt;
    }
    if (!std::isfinite(v)) {
        why = name + ": must be a finite number, got " + std::string(t);
        return std::nullopt;
    }
    return v;
}

}  // namespace

const char* fieldName(ParticleField f) {
    switch (f) {
        case ParticleField::X:
            return "x";
        case ParticleField::Y:
            return "y";
        case ParticleField::Vx:
            return "vx";
        case ParticleField::Vy:
            return "vy";
        case ParticleField::Mass:
            return "mass";
        case ParticleField::Radius:
            return "radius";
        case ParticleField::Omega:
            return "omega";
        case ParticleField::Inertia:
            return "k";
    }
    return "?";
}

const char* fieldName(EditField f) {
    switch (f) {
        case EditField::Mass:
            return "mass";
        case EditField::Radius:
            return "radius";
        case EditField::Vx:
            return "vx";
        case EditField::Vy:
            return "vy";
        case EditField::Omega:
            return "omega";
        case EditField::Inertia:
            return "k";
    }
    return "?";
}

const char* fieldUnit(EditField f) {
    switch (f) {
        case EditField::Mass:
            return "kg";
        case EditField::Radius:
            return "m";
        case EditField::Vx:
        case EditField::Vy:
            return "m/s";
        case EditField::Omega:
            return "rad/s";
        case EditField::Inertia:
            return "(I = k m r\u00b2)";
    }
    return "";
}

void EditPrompt::open(const Particle& p, const Axes& axes) {
    active_ = true;
    fresh_ = true;
    target_ = p.id;
    field_ = EditField::Mass;
    texts_ = {plainNumber(p.mass),
              plainNumber(p.radius),
              plainNumber(p.velocity.x()),
              plainNumber(axes.up(p.velocity.y())),
              plainNumber(axes.spin(p.angularVelocity)),
              plainNumber(p.inertiaFactor)};
    error_.clear();
}

void EditPrompt::close() {
    active_ = false;
    target_ = kNullParticle;
    error_.clear();
}

void EditPrompt::nextField() {
    field_ = static_cast<EditField>((static_cast<int>(field_) + 1) % kEditFields);
    fresh_ = true;
}

void EditPrompt::previousField() {
    field_ = static_cast<EditField>((static_cast<int>(field_) + kEditFields - 1) % kEditFields);
    fresh_ = true;
}

void EditPrompt::type(std::string_view text) {
    std::string& t = texts_[static_cast<std::size_t>(field_)];
    for (const char c : text) {
        if (c < 32 || c > 126) continue;
        if (fresh_) {
            t.clear();
            fresh_ = false;
        }
        if (t.size() < kMaxLength) t.push_back(c);
    }
}

void EditPrompt::backspace() {
    std::string& t = texts_[static_cast<std::size_t>(field_)];
    if (!t.empty()) t.pop_back();
    fresh_ = false;
}

CheckedEdit checkEdit(const World& world, ParticleId id,
                      const std::array<std::string, kEditFields>& texts, const Axes& axes) {
    if (!world.contains(id)) return refused(id, "the particle no longer exists");
    std::array<double, kEditFields> v{};
    for (int k = 0; k < kEditFields; ++k) {
        std::string why;
        const auto f = static_cast<EditField>(k);
        const auto parsed = parseNumber(fieldName(f), texts[static_cast<std::size_t>(k)], why);
        if (!parsed) return refused(id, why);
        v[static_cast<std::size_t>(k)] = *parsed;
    }
    EditedValues e = valuesOf(world.get(id));
    e.mass = v[0];
    e.radius = v[1];
    // Typed as shown: the axes' conversions are their own inverses.
    e.velocity = axes.vector(Vec2(v[2], v[3]));
    e.omega = axes.spin(v[4]);
    e.inertiaFactor = v[5];
    return check(world, id, e, axes);
}

EditedValues valuesOf(const Particle& p) {
    return {p.mass, p.radius, p.position, p.velocity, p.angularVelocity, p.inertiaFactor};
}

CheckedEdit checkValue(const World& world, ParticleId id, ParticleField field,
                       std::string_view text, const Axes& axes) {
    if (!world.contains(id)) return refused(id, "the particle no longer exists");
    std::string why;
    const auto value = parseNumber(fieldName(field), text, why);
    if (!value) return refused(id, why);
    const Particle p = world.get(id);
    EditedValues e = valuesOf(p);
    const WorldDef& def = world.def();
    const auto inside = [&](double v, double extent) -> std::optional<CheckedEdit> {
        if (def.walls && (v < p.radius || v > extent - p.radius)) {
            return refused(id, std::string(fieldName(field)) + ": " + plainNumber(v) +
                                   " m is outside the box (from " + plainNumber(p.radius) + " to " +
                                   plainNumber(extent - p.radius) + " m for this radius)");
        }
        return std::nullopt;
    };
    switch (field) {
        case ParticleField::X:
            if (auto refusal = inside(*value, def.width)) return *refusal;
            e.position.x() = *value;
            break;
        case ParticleField::Y:
            // The box's range of heights is the same counted up or down.
            if (auto refusal = inside(*value, def.height)) return *refusal;
            e.position.y() = axes.y(*value);
            break;
        case ParticleField::Vx:
            e.velocity.x() = *value;
            break;
        case ParticleField::Vy:
            e.velocity.y() = axes.up(*value);
            break;
        case ParticleField::Mass:
            e.mass = *value;
            break;
        case ParticleField::Radius:
            e.radius = *value;
            break;
        case ParticleField::Omega:
            e.omega = axes.spin(*value);
            break;
        case ParticleField::Inertia:
            e.inertiaFactor = *value;
            break;
    }
    return check(world, id, e, axes);
}

CheckedEdit check(const World& world, ParticleId id, const EditedValues& values, const Axes& axes) {
    const WorldDef& def = world.def();
    const double mass = values.mass, radius = values.radius;
    const Vec2& wanted = values.position;
    const Vec2& velocity = values.velocity;
    const double omega = values.omega, k = values.inertiaFactor;

    if (!(mass >= std::numeric_limits<double>::min())) {
        return refused(id, "mass: must be > 0 kg, got " + plainNumber(mass));
    }
    if (!(radius > 0.0)) return refused(id, "radius: must be > 0 m, got " + plainNumber(radius));
    const double maxSpeed = kMaxEditSpeedBoxes * std::max(def.width, def.height);
    if (!(velocity.norm() <= maxSpeed)) {
        return refused(id, "velocity: " + plainNumber(velocity.norm()) + " m/s is faster than " +
                               plainNumber(maxSpeed) + " m/s (" + plainNumber(kMaxEditSpeedBoxes) +
                               " box sizes per second)");
    }
    if (!std::isfinite(0.5 * mass * velocity.squaredNorm())) {
        return refused(id, "mass and velocity: the kinetic energy would overflow");
    }
    if (!(k >= kMinInertiaFactor && k <= 1.0)) {
        return refused(id,
                       "k: the inertia factor must be from 0.001 to 1 (1/2 a disc, 2/5 a ball, "
                       "1 a ring), got " +
                           plainNumber(k));
    }
    // The rim's speed, as a speed: a disc that turns a thousand times across the box per second
    // turns many times in one step.
    if (!(std::abs(omega) * radius <= maxSpeed)) {
        return refused(id, "omega: the rim would move at " + plainNumber(std::abs(omega) * radius) +
                               " m/s, faster than " + plainNumber(maxSpeed) + " m/s (" +
                               plainNumber(kMaxEditSpeedBoxes) + " box sizes per second)");
    }
    if (!std::isfinite(0.5 * k * mass * radius * radius * omega * omega)) {
        return refused(id, "mass and omega: the rotational energy would overflow");
    }
    if (def.walls && (2.0 * radius > def.width || 2.0 * radius > def.height)) {
        return refused(id, "radius: " + plainNumber(radius) + " m does not fit in the " +
                               plainNumber(def.width) + " x " + plainNumber(def.height) + " m box");
    }

    const Particle old = world.get(id);
    if (old.fixedRotation && omega != 0.0) {
        return refused(id,
                       "omega: particle " + std::to_string(particleNumber(id)) +
                           " has fixed rotation (it never turns), so its angular velocity stays 0");
    }
    Vec2 position = wanted;
    if (def.walls) {
        position = {std::clamp(position.x(), radius, def.width - radius),
                    std::clamp(position.y(), radius, def.height - radius)};
    }
    if (radius > old.radius || position != old.position) {
        const ParticleArrays& p = world.particles();
        for (std::size_t j = 0; j < p.size(); ++j) {
            if (p.id[j] == id) continue;
            const Vec2 c(p.x[j], p.y[j]);
            const double before = old.radius + p.radius[j] - (old.position - c).norm();
            const double after = radius + p.radius[j] - (position - c).norm();
            if (after > 0.0 && after > before) {
                char buf[160];
                std::snprintf(buf, sizeof buf, "%s would overlap the particle at [%.2f, %.2f] m",
                              wanted != old.position
                                  ? "position: the new place"
                                  : ("radius: " + plainNumber(radius) + " m").c_str(),
                              c.x(), axes.y(c.y()));
                return refused(id, buf);
            }
        }
    }

    CheckedEdit passed;
    passed.id = id;
    passed.values = values;
    passed.values.position = position;
    passed.wanted = wanted;
    return passed;
}

}  // namespace psb::app
