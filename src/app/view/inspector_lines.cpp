#include "view/inspector_lines.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "session/units.hpp"

namespace psb::app {

namespace {

/// The prompt's fields, the active one marked, and the last refusal.
void editLines(std::vector<std::string>& lines, const EditPrompt& prompt) {
    char buf[160];
    for (int k = 0; k < kEditFields; ++k) {
        const auto f = static_cast<EditField>(k);
        const bool active = f == prompt.field();
        std::snprintf(buf, sizeof buf, "%s %-6s %s%s %s", active ? ">" : " ", fieldName(f),
                      prompt.text(f).c_str(), active ? "_" : "", fieldUnit(f));
        lines.emplace_back(buf);
    }
    if (!prompt.error().empty()) lines.push_back("Refused: " + prompt.error());
}

/// How the prompt's fields are edited: its keys, or on a touch screen (whose keyboard has no Tab
/// nor Esc) its Enter and a tap that leaves it.
const char* editHint(bool touch) {
    return touch ? "Edit  Enter: apply  tap empty space: cancel"
                 : "Edit  Tab: next  Enter: apply  Esc: cancel";
}

}  // namespace

SpinReading spinReading(const Particle& p, const Axes& axes) {
    const double inertia = p.inertiaFactor * p.mass * p.radius * p.radius;
    return {0.5 * p.mass * p.velocity.squaredNorm(),
            0.5 * inertia * p.angularVelocity * p.angularVelocity,
            axes.spin(p.angularVelocity) * 60.0 / (2.0 * std::numbers::pi)};
}

std::vector<std::string> inspectorLines(const Particle& p, const EditPrompt& prompt, bool readings,
                                        bool rotation, const Axes& axes, bool touch) {
    char buf[160];
    std::vector<std::string> lines;
    const auto line = [&](const char* format, auto... values) {
        std::snprintf(buf, sizeof buf, format, values...);
        lines.emplace_back(buf);
    };
    const Vec2 velocity = axes.vector(p.velocity), momentum = p.mass * velocity;
    const auto n = [](double v) { return quantity(v, "", false); };  // "-40 400", "0.00200"
    const auto pair = [&](const char* name, const Vec2& v, const char* unit) {
        lines.push_back(std::string(name) + "(" + n(v.x()) + ", " + n(v.y()) + ") " + unit);
    };
    line("Particle %llu", static_cast<unsigned long long>(particleNumber(p.id)));
    const bool editing = prompt.active() && prompt.target() == p.id;
    if (editing && !readings) {
        lines.emplace_back(editHint(touch));
        editLines(lines, prompt);
        return lines;
    }
    pair("position        ", axes.point(p.position), "m");
    pair("velocity        ", velocity, "m/s");
    lines.push_back("speed           " + quantity(p.velocity.norm(), "m/s", false));
    pair("momentum        ", momentum, "kg m/s");
    const SpinReading spin = spinReading(p, axes);
    if (rotation) {
        // The overlay's font has Latin-1 only: words, not Greek letters.
        if (p.fixedRotation) {
            lines.emplace_back("turning         fixed rotation (never turns)");
        } else {
            lines.push_back("angular velocity " +
                            quantity(axes.spin(p.angularVelocity), "rad/s", false) + " = " +
                            quantity(spin.revPerMin, "rev/min", false));
        }
        lines.push_back("kinetic energy  " + quantity(spin.translational, "J") + " translation");
        lines.push_back("                " + quantity(spin.rotational, "J") + " rotation");
    } else {
        lines.push_back("kinetic energy  " + quantity(spin.translational, "J"));
    }
    lines.push_back("mass            " + quantity(p.mass, "kg", false));
    lines.push_back("radius          " + quantity(p.radius, "m", false));
    if (rotation) {
        line("inertia factor  k = %.3g (I = k m r\u00b2)", p.inertiaFactor);
    }
    if (!editing) {
        // No Enter on a touch screen: the panel's fields edit the particle.
        lines.emplace_back(touch ? "Edit: the panel's Selected particle" : "Enter: edit");
        return lines;
    }
    lines.emplace_back("");
    lines.emplace_back(editHint(touch));
    editLines(lines, prompt);
    return lines;
}

}  // namespace psb::app
