// The session's value commands: what the control panel's sliders, checkboxes, fields and
// buttons set (command.hpp, "Values set directly"). Each validates its value, changes the world
// or the view, says what it did (or why not) and, when the world changed, counts as one user
// action; a command that `continues` a slider drag is part of the drag's action.

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <particle_sandbox/error.hpp>

#include "session/physics_controls.hpp"
#include "session/session.hpp"

namespace psb::app {

namespace {

std::string number(const char* format, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, format, v);
    return buf;
}

}  // namespace

std::string Session::modeRefusal(StepMode mode) const {
    return mode == StepMode::Exact ? exactRefusal_ : std::string();
}

void Session::setRestitution(const cmd::SetRestitution& c) {
    if (!(c.value >= 0.0 && c.value <= 1.0)) {
        say("Restitution must be between 0 and 1, got " + number("%g", c.value),
            Notice::Level::Warning);
        return;
    }
    if (world_.def().restitution == c.value) return;
    world_.setRestitution(c.value);
    if (!c.continues) log("Restitution " + number("%.2f", c.value));
    userAction("set restitution", c.continues);
}

void Session::setFriction(const cmd::SetFriction& c) {
    if (!(c.value >= 0.0 && std::isfinite(c.value))) {
        say("Friction must be a number >= 0, got " + number("%g", c.value), Notice::Level::Warning);
        return;
    }
    if (world_.def().friction == c.value) return;
    world_.setFriction(c.value);
    if (!c.continues) log("Friction " + number("%.2f", c.value));
    userAction("set friction", c.continues);
}

void Session::setGravity(const cmd::SetGravity& c) {
    if (c.on && !(c.g > 0.0 && c.g <= kMaxPanelGravity)) {
        say("Gravity must be above 0 and at most " + number("%g", kMaxPanelGravity) +
                " m/s\u00b2, got " + number("%g", c.g),
            Notice::Level::Warning);
        return;
    }
    const Vec2 g = c.on ? Vec2(0.0, c.g) : Vec2::Zero();
    if (world_.def().gravity == g) return;
    world_.setGravity(g);
    // A drag sends a value every frame: each is shown in place of the last, and the drag's
    // first is logged.
    notices_.push_back(
        {Notice::Level::Info, "Gravity " + gravityText(g), true, !c.continues, "gravity"});
    userAction("set gravity", c.continues);
}

void Session::setWalls(const cmd::SetWalls& c) {
    if (world_.def().walls == c.on) return;
    world_.setWalls(c.on);
    say(c.on ? "Walls on" : "Walls off: particles leave the box");
    userAction("set walls");
}

void Session::setMode(const cmd::SetMode& c) {
    SolverSettings s = world_.solver();
    s.mode = c.mode;
    if (c.mode == StepMode::Substep) s.substeps = std::clamp(c.substeps, 2, kMaxPanelSubsteps);
    if (s.mode == world_.solver().mode && s.substeps == world_.solver().substeps) return;
    if (const std::string why = modeRefusal(c.mode); !why.empty()) {
        say("The " + std::string(toString(c.mode)) + " mode is not available: " + why,
            Notice::Level::Warning);
        return;
    }
    try {
        world_.setSolver(s);
    } catch (const InvalidArgument& e) {
        say(std::string("Mode refused: ") + e.what(), Notice::Level::Warning);
        return;
    }
    accumulator_ = 0.0;
    say("Mode: " + modeName(world_.solver()));
    userAction("change mode");
}

void Session::setLaunchBody(const cmd::SetLaunchBody& c) {
    const WorldDef& d = world_.def();
    if (!(c.mass >= kMinLaunchMass && c.mass <= kMaxLaunchMass)) {
        say("Launch mass must be between " + number("%g", kMinLaunchMass) + " and " +
                number("%g", kMaxLaunchMass) + " kg, got " + number("%g", c.mass),
            Notice::Level::Warning);
        return;
    }
    const double maxRadius = 0.5 * std::min(d.width, d.height);
    if (!(c.radius >= 0.0 && c.radius <= maxRadius)) {
        say("Launch radius must be above 0 and at most half the box (" + number("%.3g", maxRadius) +
                " m), got " + number("%g", c.radius),
            Notice::Level::Warning);
        return;
    }
    const SpawnSettings before = spawn_;
    // The mass the panel shows is sent back with every change of the others: it stays the
    // scene's rule until it is changed.
    if (c.mass != spawn_.mass()) spawn_.fixedMass = c.mass;
    spawn_.fixedRadius = c.radius > 0.0 ? std::optional<double>(c.radius) : std::nullopt;
    spawn_.fixedColor = c.color;
    if (spawn_.mass() != before.mass() || spawn_.radius() != before.radius() ||
        spawn_.color() != before.color()) {
        remember("set new particles");
    }
    char buf[128];
    std::snprintf(buf, sizeof buf, "New particles: %g kg, radius %g m%s", spawn_.mass(),
                  spawn_.radius(), spawn_.fixedRadius ? "" : " (from the mass)");
    log(buf);
}

void Session::editParticle(const cmd::EditParticle& c) {
    if (prompt_.active() && prompt_.target() == c.id) closeEdit();
    const EditResult r = editParticleValue(world_, c.id, c.field, c.text);
    if (!r.applied) {
        editRefusal_ = r.message;
        say("Edit refused: " + r.message, Notice::Level::Warning);
        return;
    }
    editRefusal_.clear();
    say(r.message);
    userAction("edit particle");
}

void Session::select(ParticleId id) {
    if (id.isNull() || !world_.contains(id)) {
        if (selection_.id()) {
            selection_.clear();
            closeEdit();
        }
        return;
    }
    if (prompt_.target() != id) closeEdit();
    if (selection_.id() != id) editRefusal_.clear();
    selection_.select(id);
}

void Session::setShow(const cmd::SetShow& c) {
    using O = cmd::ShowOption;
    bool* flag = nullptr;
    switch (c.option) {
        case O::Arrows:
            flag = &view_.arrows;
            break;
        case O::Labels:
            flag = &view_.labels;
            break;
        case O::Momentum:
            flag = &view_.momentum;
            break;
        case O::Plots:
            flag = &view_.plots;
            break;
        case O::Speeds:
            flag = &view_.speeds;
            break;
        case O::Bins:
            flag = &view_.bins;
            break;
        case O::Profile:
            flag = &showProfile_;
            break;
    }
    if (flag == nullptr || *flag == c.on) return;
    *flag = c.on;
    // The side column's panels change what the box is fitted beside.
    if (fitted_ && (c.option == O::Plots || c.option == O::Speeds || c.option == O::Profile ||
                    c.option == O::Bins)) {
        fit();
    }
}

void Session::saveAs(const cmd::SaveAs& c) {
    if (c.path.empty()) {
        say("Save: type a file name first", Notice::Level::Warning);
        return;
    }
    std::string why;
    const std::optional<std::filesystem::path> named = saveFileName(c.path, why);
    if (!named) {
        // The panel's status line says so too, not the save before it.
        fileError_ = "Save: " + why;
        say(fileError_, Notice::Level::Warning);
        return;
    }
    std::filesystem::path path = *named;
    std::error_code ec;
    if (!c.overwrite && std::filesystem::exists(path, ec)) path = freeSavePath(path);
    options_.saveTo = path;
    saveTo(path);
}

void Session::rememberFile(const std::filesystem::path& file) {
    std::error_code ec;
    const auto full = std::filesystem::absolute(file, ec).lexically_normal();
    const std::filesystem::path f = ec ? file : full;
    recent_.erase(std::remove(recent_.begin(), recent_.end(), f), recent_.end());
    recent_.insert(recent_.begin(), f);
    if (recent_.size() > kRecentFiles) recent_.resize(kRecentFiles);
}

}  // namespace psb::app
