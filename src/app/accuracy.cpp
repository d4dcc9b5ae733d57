#include "accuracy.hpp"

#include <limits>

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

ModeSwitch switchToNextMode(World& world) {
    SolverSettings s = world.solver();
    s.mode = nextMode(s.mode);
    if (s.mode == StepMode::Substep && s.substeps < 2) s.substeps = kAppSubsteps;
    try {
        world.setSolver(s);
    } catch (const InvalidArgument& e) {
        return {false,
                "Mode refused (the world refused it); mode stays " + modeName(world.solver()),
                e.what()};
    }
    return {true, "Mode: " + modeName(world.solver()), {}};
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

double AccuracyMonitor::drift(double kineticEnergy) const {
    if (reference_ <= 0.0) return std::numeric_limits<double>::quiet_NaN();
    return (kineticEnergy - reference_) / reference_;
}

}  // namespace psb::app
