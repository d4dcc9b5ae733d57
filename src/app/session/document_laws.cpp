// The document's world: its laws and stepping mode, what the control panel's sliders and
// checkboxes and the keys that step a value (physics_controls.hpp) set, and the Physics
// section's Heat, Cool, Squeeze and Expand. Each validates its value, changes the world, says
// what it did (or why not) and counts as one user action; a command that `continues` a slider
// drag is part of the drag's action, and its value replaces the last on screen (the notice's
// topic) without filling the log.

#include <algorithm>
#include <cmath>

#include <particle_sandbox/error.hpp>

#include "session/box_resize.hpp"
#include "session/document.hpp"
#include "session/edit_prompt.hpp"
#include "session/edit_report.hpp"
#include "session/notices.hpp"
#include "session/physics_controls.hpp"
#include "session/scene_view.hpp"
#include "session/session_text.hpp"
#include "session/sim_clock.hpp"
#include "session/units.hpp"

namespace psb::app {

void Document::handle(const cmd::SetRestitution& c, Context& x) {
    if (!(c.value >= 0.0 && c.value <= 1.0)) {
        x.notices.say(fmt("Restitution must be between 0 and 1, got %g", c.value),
                      Notice::Level::Warning);
        return;
    }
    if (world.def().restitution == c.value) return;
    world.setRestitution(c.value);
    x.notices.add({Notice::Level::Info, fmt("Restitution %.2f", c.value), true, !c.continues, "e"});
    x.edit.userAction("set restitution", c.continues);
}

void Document::handle(const cmd::SetFriction& c, Context& x) {
    if (!(c.value >= 0.0 && std::isfinite(c.value))) {
        x.notices.say(fmt("Friction must be a number >= 0, got %g", c.value),
                      Notice::Level::Warning);
        return;
    }
    if (world.def().friction == c.value) return;
    world.setFriction(c.value);
    x.notices.add({Notice::Level::Info, fmt("Friction %.2f", c.value), true, !c.continues, "mu"});
    x.edit.userAction("set friction", c.continues);
}

void Document::handle(const cmd::SetTangentialRestitution& c, Context& x) {
    if (!(c.value >= -1.0 && c.value <= 1.0)) {
        x.notices.say(fmt("Tangential restitution must be between -1 and 1, got %g", c.value),
                      Notice::Level::Warning);
        return;
    }
    if (world.def().tangentialRestitution == c.value) return;
    world.setTangentialRestitution(c.value);
    x.notices.add({Notice::Level::Info, fmt("Tangential restitution %.2f", c.value), true,
                   !c.continues, "beta"});
    x.edit.userAction("set tangential restitution", c.continues);
}

void Document::handle(const cmd::ScaleSpeeds& c, Context& x) {
    if (!(c.factor > 0.0 && c.factor <= 10.0)) {
        x.notices.say(fmt("Speeds can be scaled by more than 0 and at most 10, got %g", c.factor),
                      Notice::Level::Warning);
        return;
    }
    World& w = world;
    const ParticleArrays& p = w.particles();
    double fastest = 0.0;
    std::vector<ParticleId> free;
    for (std::size_t i = 0; i < p.size(); ++i) {
        if (p.isKinematic(i)) continue;  // the hand holds it
        free.push_back(p.id[i]);
        fastest = std::max(fastest, std::hypot(p.vx[i], p.vy[i]));
    }
    if (free.empty() || fastest == 0.0) {
        x.notices.say(
            "Nothing moves: heating scales speeds, and every speed is zero (launch or fling "
            "some first)",
            Notice::Level::Warning);
        return;
    }
    const double limit = kMaxEditSpeedBoxes * std::max(w.def().width, w.def().height);
    if (fastest * c.factor > limit) {
        x.notices.say(
            fmt("Not heated: the fastest particle would move at %s, over %g box sizes a second",
                quantity(fastest * c.factor, "m/s").c_str(), kMaxEditSpeedBoxes),
            Notice::Level::Warning);
        return;
    }
    for (const ParticleId id : free)
        w.setVelocity(id, c.factor * w.get(id).velocity);
    x.notices.say(fmt("%s: every speed x%.3g, the temperature (mean kinetic energy) x%.3g",
                      c.factor >= 1.0 ? "Heated" : "Cooled", c.factor, c.factor * c.factor));
    x.edit.userAction(c.factor >= 1.0 ? "heat" : "cool");
}

void Document::handle(const cmd::ResizeBox& c, Context& x) {
    const World& w = world;
    const double width = w.def().width, height = w.def().height;
    if (!(c.width >= kMinBoxSide && c.width <= kMaxBoxSide && c.height >= kMinBoxSide &&
          c.height <= kMaxBoxSide)) {
        x.notices.say(fmt("The box must be %g m to %g m each way, got %g m x %g m", kMinBoxSide,
                          kMaxBoxSide, c.width, c.height),
                      Notice::Level::Warning);
        return;
    }
    if (!w.obstacles().empty() || !w.droppers().empty()) {
        x.notices.say(
            "Not resized: this scene's walls, pegs and spouts are fixed in the box; a box "
            "without them (the gas) can be squeezed",
            Notice::Level::Warning);
        return;
    }
    if (c.width == width && c.height == height) return;
    auto resized = resizedBox(w, c.width, c.height);
    if (const auto* why = std::get_if<std::string>(&resized)) {
        x.notices.say("Not resized: " + *why, Notice::Level::Warning);
        return;
    }
    world = std::move(std::get<World>(resized));
    x.notices.say(fmt("Box %s x %s: the area x%.3g, the particles moved with it, their speeds kept",
                      quantity(c.width, "m").c_str(), quantity(c.height, "m").c_str(),
                      (c.width * c.height) / (width * height)));
    // The view stays as it was, so that the walls are seen to move in or out.
    x.edit.userAction(c.width * c.height < width * height ? "squeeze the box" : "expand the box");
}

void Document::handle(const cmd::SetGravity& c, Context& x) {
    if (c.on && !(c.g > 0.0 && c.g <= kMaxPanelGravity)) {
        x.notices.say(
            fmt("Gravity must be above 0 and at most %g m/s\u00b2, got %g", kMaxPanelGravity, c.g),
            Notice::Level::Warning);
        return;
    }
    if (c.on && !(std::isfinite(c.direction.x()) && std::isfinite(c.direction.y()) &&
                  c.direction != Vec2::Zero())) {
        x.notices.say("Gravity needs a direction", Notice::Level::Warning);
        return;
    }
    const Vec2 g = gravityOf(c);
    const Vec2 before = world.def().gravity;
    if (before == g) return;
    try {
        world.setGravity(g);
    } catch (const InvalidArgument& e) {
        x.notices.say(std::string("Gravity refused: ") + e.what(), Notice::Level::Warning);
        return;
    }
    x.notices.add({Notice::Level::Info, "Gravity " + gravityText(g, x.view.axes(world.def())), true,
                   !c.continues, "gravity"});
    // Turning it on or off is a switch, an entry of its own; a new strength is a setting, and
    // a burst of them is one (undo_history.hpp, "Coalescing").
    const bool switched = (before == Vec2::Zero()) != (g == Vec2::Zero());
    x.edit.userAction(switched ? "switch gravity" : "set gravity", c.continues);
}

void Document::handle(const cmd::SetWalls& c, Context& x) {
    if (world.def().walls == c.on) return;
    world.setWalls(c.on);
    x.notices.say(c.on ? "Walls on" : "Walls off: particles leave the box");
    x.edit.userAction("set walls");
}

void Document::handle(const cmd::SetMode& c, Context& x) {
    SolverSettings s = world.solver();
    s.mode = c.mode;
    if (c.mode == StepMode::Substep) s.substeps = std::clamp(c.substeps, 2, kMaxSubsteps);
    if (s.mode == world.solver().mode && s.substeps == world.solver().substeps) return;
    try {
        world.setSolver(s);
    } catch (const InvalidArgument& e) {
        x.notices.say(std::string("Mode refused: ") + e.what(), Notice::Level::Warning);
        return;
    }
    x.clock.restart();
    x.notices.say("Mode: " + modeName(world.solver()));
    x.edit.userAction("change mode");
}

}  // namespace psb::app
