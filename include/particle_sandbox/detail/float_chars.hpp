#pragma once
// Doubles to text and back as std::to_chars and std::from_chars do them (shortest round trip,
// no locale), also where the standard library has them for integers only: the web build's
// (Emscripten 3.1's libc++) lacks the floating-point overloads. Where the standard library has
// them these forward to it; otherwise float_chars.cpp does the same with snprintf and strtod,
// searching for the fewest digits that read back as the same double.

#include <charconv>

namespace psb::detail {

#if defined(__cpp_lib_to_chars) && __cpp_lib_to_chars >= 201611L

inline std::to_chars_result toChars(char* first, char* last, double value) {
    return std::to_chars(first, last, value);
}
inline std::to_chars_result toChars(char* first, char* last, double value,
                                    std::chars_format format) {
    return std::to_chars(first, last, value, format);
}
inline std::to_chars_result toChars(char* first, char* last, double value, std::chars_format format,
                                    int precision) {
    return std::to_chars(first, last, value, format, precision);
}
inline std::from_chars_result fromChars(const char* first, const char* last, double& value) {
    return std::from_chars(first, last, value);
}

#else

/// Shortest round trip, fixed or scientific whichever is shorter.
std::to_chars_result toChars(char* first, char* last, double value);
/// Shortest round trip in `format` (fixed or scientific).
std::to_chars_result toChars(char* first, char* last, double value, std::chars_format format);
/// `precision` digits in `format` (general: printf's %g).
std::to_chars_result toChars(char* first, char* last, double value, std::chars_format format,
                             int precision);
/// A decimal number, no leading whitespace or '+'.
std::from_chars_result fromChars(const char* first, const char* last, double& value);

#endif

}  // namespace psb::detail
