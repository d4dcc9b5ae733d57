#include "session/accuracy.hpp"

#include <limits>

#include <particle_sandbox/diagnostics.hpp>

namespace psb::app {

double monitoredEnergy(const World& world) {
    // The energy of turning counts too (0 in a world that keeps no rotation).
    return world.def().gravity == Vec2::Zero() ? kineticEnergy(world) + rotationalEnergy(world)
                                               : mechanicalEnergy(world);
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
