#pragma once
// How the session's files word numbers in their notices, shared by session.cpp and the files
// that hold the rest of its member functions (session_*.cpp).

#include <cstdio>
#include <string>

namespace psb::app {

/// `format` with two numbers, for a notice.
[[nodiscard]] inline std::string fmt(const char* format, double a, double b) {
    char buf[128];
    std::snprintf(buf, sizeof buf, format, a, b);
    return buf;
}

/// A stepping speed (simulated per real second) for the HUD and messages: "x2", "x0.25".
[[nodiscard]] inline std::string speedText(double s) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "x%g", s);
    return buf;
}

}  // namespace psb::app
