#pragma once
// Wall-clock durations of work (steps, drawing) in milliseconds, converted in one place: the
// session times its steps against a budget, the loop times its drawing.

#include <chrono>

namespace psb::app {

/// Milliseconds of wall-clock time since `t0`.
[[nodiscard]] inline double msSince(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace psb::app
