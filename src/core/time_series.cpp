#include <particle_sandbox/time_series.hpp>

#include <algorithm>

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

TimeSeries::TimeSeries(std::size_t capacity) : buffer_(std::max<std::size_t>(capacity, 1)) {}

bool TimeSeries::record(const World& world) {
    return record(sampleObservables(world));
}

bool TimeSeries::record(ObservablesSample s) {
    s.collisionRate = 0.0;
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
        } else {
            s.collisionRate =
                static_cast<double>(s.collisions - last.collisions) / (s.time - last.time);
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

void TimeSeries::clear() {
    first_ = 0;
    size_ = 0;
    recorded_ = 0;
}

}  // namespace psb
