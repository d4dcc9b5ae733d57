#include <particle_sandbox/trajectory.hpp>

#include <algorithm>

#include <particle_sandbox/world.hpp>

namespace psb {

Trajectory::Trajectory(std::vector<ParticleId> ids, std::size_t maxSamples)
    : ids_(std::move(ids)), maxSamples_(maxSamples) {}

bool Trajectory::record(const World& world) {
    const double now = world.time();
    if (!samples_.empty() && samples_.back().time > now) dropAfter(now);
    if (!samples_.empty() && samples_.back().time == now) return false;
    if (full()) return false;
    for (const ParticleId id : ids_) {
        if (!world.contains(id)) continue;
        const Particle p = world.get(id);
        samples_.push_back({now, id, p.position, p.velocity, p.angularVelocity});
    }
    return true;
}

void Trajectory::dropAfter(double time) {
    const auto later = std::find_if(samples_.begin(), samples_.end(),
                                    [time](const TrajectoryPoint& s) { return s.time > time; });
    samples_.erase(later, samples_.end());
}

}  // namespace psb
