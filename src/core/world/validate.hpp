#pragma once
// Argument checks shared by the core's public entry points. Each throws psb::InvalidArgument
// with a message that names the function, the argument and the bad value. Numbers in messages
// are csv::number's shortest text that reads back as the same double (0.6, not
// 0.59999999999999998), as in the exports.

#include <cmath>
#include <limits>
#include <sstream>
#include <string>

#include <particle_sandbox/csv.hpp>
#include <particle_sandbox/error.hpp>
#include <particle_sandbox/math.hpp>

namespace psb::detail {

[[noreturn]] inline void fail(const char* where, const char* what, const std::string& problem) {
    std::ostringstream os;
    os << where << ": " << what << ' ' << problem;
    throw InvalidArgument(os.str());
}

inline std::string got(double v) {
    return "(got " + csv::number(v) + ")";
}

/// "[x, y]", each as csv::number writes it.
inline std::string pointText(const Vec2& v) {
    std::string s = "[";  // appended, not '+': GCC 12 warns wrongly on "[" + string
    s += csv::number(v.x());
    s += ", ";
    s += csv::number(v.y());
    s += ']';
    return s;
}

inline void requireFinite(double v, const char* where, const char* what) {
    if (!std::isfinite(v)) fail(where, what, "must be finite " + got(v));
}

inline void requireFinite(const Vec2& v, const char* where, const char* what) {
    if (!std::isfinite(v.x()) || !std::isfinite(v.y()))
        fail(where, what, "must be finite (got " + pointText(v) + ")");
}

inline void requirePositive(double v, const char* where, const char* what) {
    if (!std::isfinite(v) || !(v > 0.0)) fail(where, what, "must be finite and > 0 " + got(v));
}

/// A mass: finite, > 0, and not so small that its inverse (which the solver divides by and
/// multiplies with) overflows to infinity, i.e. at least the smallest normal double.
inline void requireMass(double v, const char* where, const char* what) {
    requirePositive(v, where, what);
    if (v < std::numeric_limits<double>::min()) {
        fail(where, what,
             "must be at least 2.2250738585072014e-308 so that its inverse is finite " + got(v));
    }
}

inline void requireInRange(double v, double lo, double hi, const char* where, const char* what) {
    if (!std::isfinite(v) || v < lo || v > hi) {
        fail(where, what,
             "must be in [" + csv::number(lo) + ", " + csv::number(hi) + "] " + got(v));
    }
}

}  // namespace psb::detail
