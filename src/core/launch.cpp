#include <particle_sandbox/launch.hpp>

#include <cmath>

namespace psb {

Vec2 launchVelocity(std::span<const TrajectorySample> samples, const LaunchSettings& settings) {
    const auto finite = [](const TrajectorySample& s) {
        return std::isfinite(s.time) && std::isfinite(s.position.x()) &&
               std::isfinite(s.position.y());
    };
    // Newest finite sample.
    std::size_t last = samples.size();
    while (last > 0 && !finite(samples[last - 1]))
        --last;
    if (last == 0) return Vec2::Zero();
    const TrajectorySample& newest = samples[last - 1];

    // Oldest finite sample still inside the window.
    const TrajectorySample* oldest = &newest;
    for (std::size_t k = last - 1; k-- > 0;) {
        if (!finite(samples[k])) continue;
        if (newest.time - samples[k].time > settings.window) break;
        oldest = &samples[k];
    }
    const double span = newest.time - oldest->time;
    if (!(span > 0.0)) return Vec2::Zero();
    const Vec2 displacement = newest.position - oldest->position;
    if (displacement.norm() < settings.minDistance) return Vec2::Zero();
    Vec2 v = displacement / span;
    if (settings.maxSpeed > 0.0 && v.norm() > settings.maxSpeed) {
        v *= settings.maxSpeed / v.norm();
    }
    return v;
}

}  // namespace psb
