#pragma once
// What the user takes away from a run as tables (data_tables.hpp): the run's observables from
// its start, the samples the plots show (monitor.hpp: on simulated time, with their collision
// rates); and, while the user records, the chosen
// particles' trajectories and their collisions (the world's collision log, collision_log.hpp).
//
// Records follow the world's history: when its clock goes back (an undo, a reset, carrying on
// from a past frame) what was recorded after the new time is dropped, so a table never holds
// two futures. A recording that has stopped is over: it stays whole, to export, whatever the
// world's clock does after, until the next recording starts (only the run's series follows);
// a scene opened stops it and keeps it too, with the box it was recorded in (its heights count
// from that box's floor).

#include <cstddef>
#include <optional>
#include <vector>

#include <particle_sandbox/collision_log.hpp>
#include <particle_sandbox/time_series.hpp>
#include <particle_sandbox/trajectory.hpp>
#include <particle_sandbox/world.hpp>

namespace psb::app {

class DataRecorder {
  public:
    /// Samples kept of the run; beyond it every other one is dropped (and the spacing doubles):
    /// 2^20 samples are 5.8 hours of simulated time at 0.02 s a sample.
    static constexpr std::size_t kMaxRunSamples = std::size_t{1} << 20;
    /// Collisions kept while recording; recording stops when it is reached.
    static constexpr std::size_t kMaxCollisions = 1'000'000;
    /// Particles recorded at most when none is selected (all of them).
    static constexpr std::size_t kMaxAllParticles = 100;
    /// Steps between trajectory samples: 1 (every step) to this.
    static constexpr int kMaxEvery = 1000;

    /// A world put in place (a scene opened, Restart, an undo to another scene): the run's
    /// series starts over and recording stops; what was recorded stays, to export, until the
    /// next recording starts (a preset's key dropped it without a word).
    void restartRun();
    /// A sample of the run (Monitor::stepped, Monitor::frameDone), appended to the run's
    /// series; at the same time as the last sample (paused), in its place. One earlier than the
    /// last drops the run's later samples, and those of the recording while it goes on.
    void sample(const ObservablesSample& s);

    /// Starts recording `ids` every `every` steps (clamped to [1, kMaxEvery]), with their state
    /// now as the first sample; what an earlier recording held is dropped.
    void start(const World& world, std::vector<ParticleId> ids, int every);
    void stop();
    [[nodiscard]] bool recording() const { return recording_; }
    /// Why recording stopped by itself (a limit reached), once; empty otherwise.
    [[nodiscard]] std::string takeStopReason();

    /// The collisions the world should record for the recording (none when not recording):
    /// the chosen particles'. The instruments merge it with what the collision card wants.
    [[nodiscard]] std::optional<CollisionLog> collisionsWanted() const;
    /// Around each step of the world: before it, what was recorded after the world's time is
    /// dropped (an undo or a step back took the clock back); after it, `heard` (the step's
    /// collision records, perhaps of more particles than the recording's) joins the log, and
    /// the trajectory is sampled every `every` steps.
    void beforeStep(const World& world);
    void afterStep(const World& world, const std::vector<Collision>& heard);

    [[nodiscard]] const std::vector<ObservablesSample>& run() const { return run_; }
    [[nodiscard]] const Trajectory& trajectory() const { return trajectory_; }
    [[nodiscard]] const std::vector<Collision>& collisions() const { return collisions_; }
    [[nodiscard]] int every() const { return every_; }
    /// The box the recording was made in: its height, metres (y up counts from its floor), and
    /// whether its discs turned (the trajectories' ω column). A scene opened since keeps them.
    [[nodiscard]] double recordedHeight() const { return recordedHeight_; }
    [[nodiscard]] bool recordedRotation() const { return recordedRotation_; }

  private:
    void dropRunAfter(double time);
    /// The recording's trajectory samples and collisions after `time`.
    void dropAfter(double time);

    std::vector<ObservablesSample> run_;
    std::size_t runStride_ = 1;  ///< samples per kept sample (doubles at each thinning)
    std::size_t runSkipped_ = 0;
    bool recording_ = false;
    int every_ = 1;
    int stepsToSample_ = 0;
    Trajectory trajectory_;
    std::vector<Collision> collisions_;
    double recordedHeight_ = 0.0;
    bool recordedRotation_ = false;
    std::string stopReason_;
};

}  // namespace psb::app
