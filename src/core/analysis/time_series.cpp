#include <particle_sandbox/time_series.hpp>

#include <algorithm>
#include <limits>

#include <particle_sandbox/diagnostics.hpp>
#include <particle_sandbox/world.hpp>

namespace psb {

ObservablesSample sampleObservables(const World& world) {
    ObservablesSample s;
    s.time = world.time();
    s.kineticEnergy = kineticEnergy(world);
    s.potentialEnergy = potentialEnergy(world);
    s.rotationalEnergy = rotationalEnergy(world);
    s.angularMomentum = angularMomentum(world);
    s.momentum = momentum(world);
    s.centreOfMass = centreOfMass(world);
    s.collisions = world.counters().collisions;
    return s;
}

TimeSeries::TimeSeries(std::size_t capacity, std::size_t rateSamples)
    : buffer_(std::max<std::size_t>(capacity, 1)),
      rateSamples_(
          std::clamp<std::size_t>(rateSamples, 1, std::max<std::size_t>(capacity, 2) - 1)) {}

bool TimeSeries::record(const World& world) {
    return record(sampleObservables(world));
}

bool TimeSeries::record(ObservablesSample s) {
    s.collisionRate = std::numeric_limits<double>::quiet_NaN();
    if (size_ > 0) {
        ObservablesSample& last = buffer_[(first_ + size_ - 1) % buffer_.size()];
        if (s.time == last.time && s.collisions == last.collisions) {
            // No step since, but the world may have been edited (particles placed or given
            // their velocities before Play): the sample of this instant is the state as now.
            s.collisionRate = last.collisionRate;
            last = s;
            return false;
        }
        if (s.time <= last.time || s.collisions < last.collisions) {
            clear();  // another run: its first sample has no interval
        } else if (size_ >= rateSamples_) {
            // The window's start: rateSamples_ samples back from the one being added.
            const ObservablesSample& start = (*this)[size_ - rateSamples_];
            s.collisionRate =
                static_cast<double>(s.collisions - start.collisions) / (s.time - start.time);
        }
    }
    if (size_ < buffer_.size()) {
        buffer_[(first_ + size_) % buffer_.size()] = s;
        ++size_;
    } else {
        buffer_[first_] = s;
        first_ = (first_ + 1) % buffer_.size();
    }
    ++recorded_;
    return true;
}

void TimeSeries::dropAfter(double time) {
    while (size_ > 0 && back().time > time) {
        --size_;
        --recorded_;
    }
}

void TimeSeries::clear() {
    first_ = 0;
    size_ = 0;
    recorded_ = 0;
}

}  // namespace psb
