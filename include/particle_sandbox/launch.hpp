#pragma once
/// \file
/// Turning a mouse trajectory into a launch velocity.

#include <span>

#include <particle_sandbox/math.hpp>

namespace psb {

/// One sample of a drag: where the pointer was (world metres) and when (seconds).
struct TrajectorySample {
    double time = 0.0;
    Vec2 position = Vec2::Zero();
};

/// How a drag becomes a velocity.
struct LaunchSettings {
    double window = 0.1;  ///< only samples this many seconds before the last one count
    double minDistance =
        0.0;  ///< a displacement over the window shorter than this launches at rest, metres
    double maxSpeed = 0.0;  ///< if > 0, the speed is clamped to this, m/s
};

/// Velocity (m/s) of the recent part of a drag: displacement between the oldest sample inside
/// the window and the newest, divided by their time difference. Where the pointer reported
/// sparsely (gaps between the samples before the newest longer than the window, as in a page
/// drawing slow frames, which delivers one move per frame; the gap before the newest counts too
/// when the newest moved), the window widens to 1.5 times the longest of the last three such
/// gaps, up to 4 times `window`: a hand cannot be seen to stop in less time than its pointer
/// takes to report. Zero when there are fewer than
/// two samples, when the time span is zero, or when the displacement is below minDistance.
/// Samples must be in non-decreasing time order; non-finite samples are ignored.
[[nodiscard]] Vec2 launchVelocity(std::span<const TrajectorySample> samples,
                                  const LaunchSettings& settings = {});

/// The window launchVelocity measures over for `samples`, seconds: `settings.window`, widened
/// where the pointer reported sparsely (see launchVelocity). A pointer that has not reported for
/// longer than this after its newest sample has been seen to stop.
[[nodiscard]] double launchWindow(std::span<const TrajectorySample> samples,
                                  const LaunchSettings& settings = {});

}  // namespace psb
