#pragma once
/// \file
/// The paths of chosen particles: their position and velocity sampled over time, for a
/// position–time graph. The app records one while the user asks; particle-sim --track writes
/// one.

#include <cstddef>
#include <vector>

#include <particle_sandbox/math.hpp>
#include <particle_sandbox/particle_id.hpp>

namespace psb {

class World;

/// One particle's state at one instant.
struct TrajectoryPoint {
    double time = 0.0;  ///< simulated seconds (World::time)
    ParticleId id;
    Vec2 position = Vec2::Zero();  ///< m
    Vec2 velocity = Vec2::Zero();  ///< m/s
    double angularVelocity = 0.0;  ///< rad/s
};

/// The samples of chosen particles, oldest first; at one instant, in the order the ids were
/// chosen. Bounded: once it holds `maxSamples` samples it records no more (full()).
class Trajectory {
  public:
    /// About 100 MB of samples: an hour of one particle at every step of 1/60 s is 216,000.
    static constexpr std::size_t kDefaultMaxSamples = 2'000'000;

    explicit Trajectory(std::vector<ParticleId> ids = {},
                        std::size_t maxSamples = kDefaultMaxSamples);

    /// Appends the state of each chosen particle that `world` holds (a removed one is skipped).
    /// A world whose clock went back (an undo, a reset) first drops the samples after its time:
    /// the record follows the world's history. Returns false, recording nothing, when full or
    /// when the world's time is that of the last samples (nothing stepped).
    bool record(const World& world);
    /// Drops the samples after `time` (seconds).
    void dropAfter(double time);
    void clear() { samples_.clear(); }

    [[nodiscard]] const std::vector<ParticleId>& ids() const { return ids_; }
    [[nodiscard]] const std::vector<TrajectoryPoint>& samples() const { return samples_; }
    [[nodiscard]] bool full() const { return samples_.size() + ids_.size() > maxSamples_; }

  private:
    std::vector<ParticleId> ids_;
    std::size_t maxSamples_;
    std::vector<TrajectoryPoint> samples_;
};

}  // namespace psb
