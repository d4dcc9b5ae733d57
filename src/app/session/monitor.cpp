#include "session/monitor.hpp"

#include <particle_sandbox/diagnostics.hpp>

namespace psb::app {

void Monitor::restart(const World& world, bool newScene) {
    // The last world's figures (its deepest overlap) say nothing about this one.
    accuracy_ = AccuracyMonitor{};
    accuracy_.resetReference(monitoredEnergy(world));
    if (newScene) {
        series_.clear();
        collisions_ = 0;
    }
    now_ = sampleObservables(world);
    changedSinceMeasure_ = true;
    gas_.restart(newScene);
}

void Monitor::edited(const World& world) {
    accuracy_.resetReference(monitoredEnergy(world));
    changedSinceMeasure_ = true;
    gas_.restart();
}

void Monitor::resetEnergy(const World& world) {
    accuracy_.resetReference(monitoredEnergy(world));
}

void Monitor::showFrame(const World& world) {
    changedSinceMeasure_ = true;
    gas_.restart();
    now_ = sampleObservables(world);
    accuracy_.resetReference(monitoredEnergy(world));
}

void Monitor::frameDone(const World& world, bool record) {
    // The state as drawn is measured when the steps' own detection did not see it: nothing
    // stepped (paused, or a held particle moved), the exact mode (its events meet overlaps only
    // at collisions), or the user changed the world since. Running in discrete or substep mode
    // the steps' maximum already bounds it, and a broadphase pass a frame would cost ~2 ms at
    // 5·10⁴ particles.
    if (world.counters().steps == 0 || world.solver().mode == StepMode::Exact ||
        changedSinceMeasure_) {
        accuracy_.measureState(world);
        changedSinceMeasure_ = false;
    } else {
        accuracy_.clearState();
    }
    // Always recorded (three compensated sums over the particles), so the plots and the centre
    // of mass path have a history the moment they are switched on. The accuracy monitor clears
    // the world's counters before each frame's steps; the series wants a running total.
    collisions_ += world.counters().collisions;
    now_ = sampleObservables(world);
    now_.collisions = collisions_;
    if (record) {
        series_.record(now_);
        gas_.sample(world);
    }
}

}  // namespace psb::app
