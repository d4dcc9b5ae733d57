#include "session/accuracy.hpp"

#include <limits>

#include <particle_sandbox/diagnostics.hpp>
#include <particle_sandbox/error.hpp>

namespace psb::app {

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

std::string modeName(const SolverSettings& solver) {
    std::string name(toString(solver.mode));
    if (solver.mode == StepMode::Substep) name += " x" + std::to_string(solver.substeps);
    return name;
}

double monitoredEnergy(const World& world) {
    return world.def().gravity == Vec2::Zero() ? kineticEnergy(world) : mechanicalEnergy(world);
}

std::string exactModeRefusal(const World& world) {
    // The world decides; an empty world with the same box and obstacles asks it cheaply.
    SolverSettings s = world.solver();
    s.mode = StepMode::Exact;
    try {
        World probe(world.def());
        probe.setSolver(s);
    } catch (const InvalidArgument& e) {
        return e.what();
    }
    return {};
}

ModeSwitch switchToNextMode(World& world) {
    ModeSwitch r;
    const StepMode start = world.solver().mode;
    std::string reasons;
    for (StepMode m = nextMode(start); m != start; m = nextMode(m)) {
        SolverSettings s = world.solver();
        s.mode = m;
        if (s.mode == StepMode::Substep && s.substeps < 2) s.substeps = kAppSubsteps;
        try {
            world.setSolver(s);
        } catch (const InvalidArgument& e) {
            const std::string name(toString(m));
            r.skipped += (r.skipped.empty() ? "" : ", ") + name;
            reasons += (reasons.empty() ? "" : "; ") + name + " skipped: the world refused it";
            r.detail += (r.detail.empty() ? "" : " | ") + name + ": " + e.what();
            continue;
        }
        r.changed = true;
        r.message = "Mode: " + modeName(world.solver());
        if (!reasons.empty()) r.message += " (" + reasons + ")";
        return r;
    }
    r.message = "Mode stays " + modeName(world.solver()) + " (" + reasons + ")";
    return r;
}

void AccuracyMonitor::resetReference(double kineticEnergy) {
    reference_ = kineticEnergy;
}

void AccuracyMonitor::beginSteps(World& world) {
    world.resetCounters();
}

void AccuracyMonitor::endSteps(const World& world) {
    const StepCounters& c = world.counters();
    if (c.steps == 0) return;  // nothing stepped (paused): keep the last figures
    overlap_ = c.maxOverlap;
    eventsPerStep_ = static_cast<double>(c.events) / static_cast<double>(c.steps);
}

void AccuracyMonitor::measureState(const World& world) {
    stateOverlap_ = maxOverlap(world);
}

double AccuracyMonitor::drift(double kineticEnergy) const {
    if (reference_ <= 0.0) return std::numeric_limits<double>::quiet_NaN();
    return (kineticEnergy - reference_) / reference_;
}

}  // namespace psb::app
