#pragma once
// The app's two clocks, each converted in one place: SDL's millisecond ticks (event timestamps
// and SDL_GetTicks64, the pointer clock the session's hand uses) as seconds, and wall-clock
// durations of work (steps, drawing) in milliseconds.

#include <chrono>
#include <cstdint>

namespace psb::app {

/// SDL ticks (milliseconds) as seconds.
[[nodiscard]] inline double ticksToSeconds(std::uint64_t ticks) {
    return static_cast<double>(ticks) / 1000.0;
}

/// Milliseconds of wall-clock time since `t0`.
[[nodiscard]] inline double msSince(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace psb::app
