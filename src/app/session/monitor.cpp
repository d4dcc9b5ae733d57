#include "session/monitor.hpp"

#include <algorithm>
#include <cmath>

#include <particle_sandbox/diagnostics.hpp>

namespace psb::app {

int Monitor::sampleSteps(double dt) {
    if (!(dt > 0.0)) return 1;
    return static_cast<int>(std::max(1.0, std::round(kSampleSeconds / dt)));
}

std::size_t Monitor::rateSamples(double dt) {
    const double interval = sampleSteps(dt) * (dt > 0.0 ? dt : kSampleSeconds);
    return static_cast<std::size_t>(std::max(1.0, std::round(kRateSeconds / interval)));
}

double Monitor::rateWindow(double dt) {
    return static_cast<double>(rateSamples(dt)) * sampleSteps(dt) * dt;
}

ObservablesSample Monitor::measure(const World& world) const {
    ObservablesSample s = sampleObservables(world);
    // The accuracy monitor clears the world's counters before each frame's steps; the series
    // wants a running total.
    s.collisions = collisions_ + world.counters().collisions;
    return s;
}

void Monitor::followClock(const World& world) {
    if (series_.empty() || !(world.time() < series_.back().time)) return;
    series_.dropAfter(world.time());
    // The collisions between the last kept sample and the world's time (less than an
    // interval's) are not known again: the next rate misses them rather than counting the
    // undone future.
    collisions_ = series_.empty() ? 0 : series_.back().collisions;
}

void Monitor::restart(const World& world, bool newScene, double dt) {
    // The last world's figures (its deepest overlap) say nothing about this one.
    accuracy_ = AccuracyMonitor{};
    accuracy_.resetReference(monitoredEnergy(world));
    if (newScene) {
        dt_ = dt;
        series_ = TimeSeries(kSeriesSamples, rateSamples(dt));
        collisions_ = 0;
        series_.record(measure(world));
    } else {
        followClock(world);
    }
    now_ = sampleObservables(world);
    now_.collisions = collisions_;
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

bool Monitor::stepped(const World& world) {
    followClock(world);
    // On the grid of simulated time: the step count since t = 0 a multiple of sampleSteps, so
    // a world taken back (an undo) samples at the same instants as before.
    if (std::llround(world.time() / dt_) % sampleSteps(dt_) != 0) return false;
    series_.record(measure(world));
    return true;
}

bool Monitor::frameDone(World& world, bool record) {
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
    // Measured every frame (three compensated sums over the particles) for the HUD.
    now_ = measure(world);
    collisions_ += world.counters().collisions;
    if (!record) return false;
    gas_.sample(world);
    if (series_.empty() || series_.back().time != world.time()) return false;
    // At the last sample's instant (paused there, the set-up before Play, a held particle
    // moved after the step): the sample is the world as it is drawn, edits included.
    series_.record(now_);
    return true;
}

}  // namespace psb::app
