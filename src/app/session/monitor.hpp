#pragma once
// What the session measures as the world runs, for the HUD and the plots: the accuracy
// indicators (accuracy.hpp), the time series of the world's observables, sampled once a
// frame from the moment a scene opens, so that the plots have a history when switched on, and
// the gas instruments (gas_gauges.hpp).

#include <cstddef>
#include <cstdint>

#include <particle_sandbox/time_series.hpp>
#include <particle_sandbox/world.hpp>

#include "session/accuracy.hpp"
#include "session/gas_gauges.hpp"

namespace psb::app {

class Monitor {
  public:
    /// A world put in place (a scene opened, an undo): the indicators start over from it; a
    /// new scene (`newScene`) starts the series over too.
    void restart(const World& world, bool newScene);
    /// The user changed the world: the energy drift is measured from here on, and the state
    /// is measured again before it is drawn.
    void edited(const World& world);
    /// Before a frame's steps.
    void beginSteps(World& world) { accuracy_.beginSteps(world); }
    /// After a frame's steps.
    void endSteps(const World& world) { accuracy_.endSteps(world); }
    /// The frame's world as it will be drawn: its overlap measured when the steps' own
    /// detection did not see it, its observables sampled (and recorded when `record`: not a
    /// past frame shown).
    void frameDone(const World& world, bool record);
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
    AccuracyMonitor accuracy_;
    /// About 68 s of frames at 60 fps for the plots and the centre of mass path.
    static constexpr std::size_t kSeriesSamples = 4096;
    TimeSeries series_{kSeriesSamples};
    std::uint64_t collisions_ = 0;  ///< since the scene opened, for series_
    ObservablesSample now_;
    GasGauges gas_;
    bool changedSinceMeasure_ = true;  ///< the world changed other than by stepping
};

}  // namespace psb::app
