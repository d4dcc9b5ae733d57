#pragma once
// How the session's parts word numbers in their notices (notices.hpp), shared by their
// handlers' files.

#include <cstdio>
#include <string>

namespace psb::app {

/// `format` with its numbers (and C strings), for a notice.
template <class... Args>
[[nodiscard]] std::string fmt(const char* format, Args... args) {
    char buf[256];
    std::snprintf(buf, sizeof buf, format, args...);
    return buf;
}

/// A stepping speed (simulated per real second) for the HUD and messages: "x2", "x0.25".
[[nodiscard]] inline std::string speedText(double s) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "x%g", s);
    return buf;
}

}  // namespace psb::app
