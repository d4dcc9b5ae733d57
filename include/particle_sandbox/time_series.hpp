#pragma once
/// \file
/// The observables of a world sampled over time: energy, momentum, centre of mass, collisions.

#include <cstddef>
#include <cstdint>
#include <vector>

#include <particle_sandbox/math.hpp>

namespace psb {

class World;

/// What a world looked like at one instant.
struct ObservablesSample {
    double time = 0.0;                 ///< simulated time, s (World::time)
    double kineticEnergy = 0.0;        ///< Σ ½ m |v|², J
    double potentialEnergy = 0.0;      ///< gravitational, J (diagnostics.hpp; 0 without gravity)
    double rotationalEnergy = 0.0;     ///< Σ ½ I ω², J (0 in a world without rotation)
    double angularMomentum = 0.0;      ///< orbital + spin about the origin, kg·m²/s
    Vec2 momentum = Vec2::Zero();      ///< Σ m v, kg·m/s
    Vec2 centreOfMass = Vec2::Zero();  ///< m (the box centre for an empty world)
    std::uint64_t collisions = 0;      ///< particle–particle collisions so far (StepCounters)
    /// Collisions per simulated second over the series' rate window ending at this sample (the
    /// last TimeSeries::rateSamples() intervals between samples), 1/s; NaN, no value, while
    /// the series does not yet reach that far back (its first sample at least).
    double collisionRate = 0.0;
};

/// The observables of `world` now, with collisionRate 0. The sums are compensated (see
/// diagnostics.hpp), so a conserved energy stays flat to ~1e-15 relative in the series.
[[nodiscard]] ObservablesSample sampleObservables(const World& world);

/// The most recent `capacity` samples of a world's observables, oldest first: a ring buffer
/// allocated once, so recording allocates nothing.
///
/// A series belongs to one run of one world. When the world's clock or collision counter goes
/// backwards (a new world, or StepCounters reset), record() starts the series afresh rather
/// than join two runs with a nonsense rate.
///
/// The collision rate of a sample counts the collisions over its last `rateSamples` intervals:
/// with samples at fixed instants of simulated time (every N steps, as particle-sim and the
/// app take them) that is a fixed window of simulated time, long enough that one collision
/// reads as 1/window per second rather than as 1/interval.
class TimeSeries {
  public:
    /// `capacity` samples (>= 1; 0 is taken as 1), each sample's collision rate over the last
    /// `rateSamples` intervals (1 to capacity - 1; at least 1).
    explicit TimeSeries(std::size_t capacity, std::size_t rateSamples = 1);

    /// Appends the world's observables, dropping the oldest sample when full. Returns false and
    /// appends nothing when the world's time equals the last sample's (no step since: a paused
    /// app samples every frame, and a zero interval has no rate); the last sample then becomes
    /// the state now, its rate kept, so that a world set up before it runs starts its plots
    /// from the set-up, not from the empty box it began as.
    bool record(const World& world);
    /// Appends `s` as record() would; its collisionRate is recomputed from the previous sample.
    bool record(ObservablesSample s);
    /// Drops the samples later than `time`, s (the world went back in time: an undo, a run
    /// carried on from a past frame); what is kept, rates included, stands.
    void dropAfter(double time);
    void clear();

    [[nodiscard]] std::size_t size() const { return size_; }
    [[nodiscard]] std::size_t capacity() const { return buffer_.size(); }
    [[nodiscard]] bool empty() const { return size_ == 0; }
    /// Intervals between samples the collision rate spans.
    [[nodiscard]] std::size_t rateSamples() const { return rateSamples_; }
    /// Sample `k`, 0 = the oldest kept; k < size().
    [[nodiscard]] const ObservablesSample& operator[](std::size_t k) const {
        return buffer_[(first_ + k) % buffer_.size()];
    }
    [[nodiscard]] const ObservablesSample& back() const { return (*this)[size_ - 1]; }
    /// Samples recorded since the last clear, including those the ring has dropped.
    [[nodiscard]] std::uint64_t recorded() const { return recorded_; }

  private:
    std::vector<ObservablesSample> buffer_;
    std::size_t first_ = 0;
    std::size_t size_ = 0;
    std::uint64_t recorded_ = 0;
    std::size_t rateSamples_ = 1;
};

}  // namespace psb
