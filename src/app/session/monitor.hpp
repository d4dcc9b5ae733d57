#pragma once
// What the session measures as the world runs, for the HUD and the plots: the accuracy
// indicators (accuracy.hpp), the time series of the world's observables from the moment a
// scene opens, so that the plots have a history when switched on, and the gas instruments
// (gas_gauges.hpp).
//
// The series is sampled on simulated time, not per drawn frame: at t = 0 and after every
// sampleSteps(dt) steps of the scene's dt (about kSampleSeconds), whatever the frame rate, the
// time speed or a slow machine's dropped backlog, so the plots and the exported table hold the
// same rows at the same instants on any machine. Each sample's collision rate counts the
// collisions over the last rateSamples(dt) samples, about kRateSeconds of simulated time: one
// collision reads as 2 per second for half a second, not as 60 per second for one frame.

#include <cstddef>
#include <cstdint>

#include <particle_sandbox/time_series.hpp>
#include <particle_sandbox/world.hpp>

#include "session/accuracy.hpp"
#include "session/gas_gauges.hpp"

namespace psb::app {

class Monitor {
  public:
    /// Simulated seconds between samples, roughly: the interval is a whole number of steps.
    static constexpr double kSampleSeconds = 0.02;
    /// Simulated seconds the collision rate counts over, roughly: a whole number of intervals.
    static constexpr double kRateSeconds = 0.5;
    /// Steps of `dt` seconds between two samples: kSampleSeconds rounded to whole steps, at
    /// least one (every step of a scene whose dt is longer).
    [[nodiscard]] static int sampleSteps(double dt);
    /// Intervals between samples the collision rate spans: kRateSeconds in whole intervals.
    [[nodiscard]] static std::size_t rateSamples(double dt);
    /// The collision rate's window, s of simulated time: rateSamples(dt) intervals.
    [[nodiscard]] static double rateWindow(double dt);

    /// A world put in place (a scene opened, an undo): the indicators start over from it; a
    /// new scene (`newScene`, stepped `dt` seconds at a time) starts the series over too, with
    /// the world now as its first sample. A world whose clock went back (an undo) keeps the
    /// series up to its time.
    void restart(const World& world, bool newScene, double dt);
    /// The user changed the world: the energy drift is measured from here on, and the state
    /// is measured again before it is drawn.
    void edited(const World& world);
    /// Before a frame's steps.
    void beginSteps(World& world) { accuracy_.beginSteps(world); }
    /// After each step: true when it ended on a sample instant, the sample then series().back().
    bool stepped(const World& world);
    /// After a frame's steps.
    void endSteps(const World& world) { accuracy_.endSteps(world); }
    /// The frame's world as it will be drawn: its overlap measured when the steps' own
    /// detection did not see it, its observables measured. When `record` (not a past frame
    /// shown) and the world stands at the last sample's instant (paused at a sample, the set-up
    /// before Play), that sample becomes the world as it is drawn, edits included: true then,
    /// the sample series().back(). The gas gauges sample it (and may turn its virial counter
    /// on: gas_gauges.hpp).
    bool frameDone(World& world, bool record);
    /// A past frame shown: its observables, and the energy measured from it.
    void showFrame(const World& world);

    [[nodiscard]] const AccuracyMonitor& accuracy() const { return accuracy_; }
    /// A grab: the energy is measured from here on.
    void resetEnergy(const World& world);
    [[nodiscard]] const TimeSeries& series() const { return series_; }
    /// The world's observables as the last frame left them.
    [[nodiscard]] const ObservablesSample& observables() const { return now_; }
    /// The gas instruments over the frames recorded (gas_gauges.hpp).
    [[nodiscard]] const GasGauges& gas() const { return gas_; }

  private:
    /// The world's observables now, its collisions the running total (collisions_ plus the
    /// frame's so far).
    [[nodiscard]] ObservablesSample measure(const World& world) const;
    /// The world's clock went back: the samples after it are dropped, and the running total
    /// of collisions is the last kept sample's.
    void followClock(const World& world);

    AccuracyMonitor accuracy_;
    /// About 82 s of simulated time at 0.02 s a sample for the plots and the centre of mass
    /// path.
    static constexpr std::size_t kSeriesSamples = 4096;
    TimeSeries series_{kSeriesSamples};
    double dt_ = 1.0 / 60.0;        ///< the scene's step
    std::uint64_t collisions_ = 0;  ///< since the scene opened, to the frame's start
    ObservablesSample now_;
    GasGauges gas_;
    bool changedSinceMeasure_ = true;  ///< the world changed other than by stepping
};

}  // namespace psb::app
