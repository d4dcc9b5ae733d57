#pragma once
// The pointer clock, converted in one place: SDL's millisecond ticks (event timestamps and
// SDL_GetTicks64, the clock the session's hand uses) as seconds. Wall-clock durations of work
// are the session's (session/stopwatch.hpp).

#include <cstdint>

namespace psb::app {

/// SDL ticks (milliseconds) as seconds.
[[nodiscard]] inline double ticksToSeconds(std::uint64_t ticks) {
    return static_cast<double>(ticks) / 1000.0;
}

}  // namespace psb::app
