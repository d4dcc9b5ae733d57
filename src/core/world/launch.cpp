#include <particle_sandbox/launch.hpp>

#include <algorithm>
#include <cmath>

namespace psb {

namespace {

/// How many of the gaps before the newest sample measure the pointer's reporting spacing.
constexpr int kSpacingGaps = 3;
/// The window holds at least this many spacings...
constexpr double kSpacingsPerWindow = 1.5;
/// ...but never more than this many times the settings' window.
constexpr double kMaxWindowFactor = 4.0;

}  // namespace

namespace {

bool finite(const TrajectorySample& s) {
    return std::isfinite(s.time) && std::isfinite(s.position.x()) && std::isfinite(s.position.y());
}

/// One past the newest finite sample (0: none).
std::size_t newestEnd(std::span<const TrajectorySample> samples) {
    std::size_t last = samples.size();
    while (last > 0 && !finite(samples[last - 1]))
        --last;
    return last;
}

double windowFor(std::span<const TrajectorySample> samples, std::size_t last,
                 const LaunchSettings& settings) {
    // The window widens when the pointer reported sparsely: a page whose frames take longer
    // than the window delivers one move per frame, and the release, at the last move's spot,
    // would otherwise find no earlier sample inside the window and read as a hand at rest.
    // The spacing is the longest gap between the samples before the newest. The gap before the
    // newest counts only when the newest moved: a release where the last move left the pointer
    // comes after the pause a stopped hand makes, but a move is a report of motion, and a page
    // whose frames are slow coalesces a quick fling's moves into one or two (with no earlier
    // gap at all to measure the spacing by).
    double spacing = 0.0;
    const TrajectorySample& newest = samples[last - 1];
    const TrajectorySample* later = nullptr;
    for (std::size_t k = last - 1; k-- > 0;) {
        if (!finite(samples[k])) continue;
        if (samples[k].position != newest.position) later = &newest;
        break;
    }
    int gaps = 0;
    for (std::size_t k = last - 1; k-- > 0 && gaps < kSpacingGaps;) {
        if (!finite(samples[k])) continue;
        if (later != nullptr) {
            spacing = std::max(spacing, later->time - samples[k].time);
            ++gaps;
        }
        later = &samples[k];
    }
    return std::min(std::max(settings.window, kSpacingsPerWindow * spacing),
                    kMaxWindowFactor * settings.window);
}

}  // namespace

double launchWindow(std::span<const TrajectorySample> samples, const LaunchSettings& settings) {
    const std::size_t last = newestEnd(samples);
    return last == 0 ? settings.window : windowFor(samples, last, settings);
}

Vec2 launchVelocity(std::span<const TrajectorySample> samples, const LaunchSettings& settings) {
    const std::size_t last = newestEnd(samples);
    if (last == 0) return Vec2::Zero();
    const TrajectorySample& newest = samples[last - 1];
    const double window = windowFor(samples, last, settings);

    // Oldest finite sample still inside the window.
    const TrajectorySample* oldest = &newest;
    for (std::size_t k = last - 1; k-- > 0;) {
        if (!finite(samples[k])) continue;
        if (newest.time - samples[k].time > window) break;
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
