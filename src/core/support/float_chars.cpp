#include <particle_sandbox/detail/float_chars.hpp>

#if !(defined(__cpp_lib_to_chars) && __cpp_lib_to_chars >= 201611L)

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <system_error>

namespace psb::detail {

namespace {

std::to_chars_result put(char* first, char* last, const std::string& text) {
    if (static_cast<std::size_t>(last - first) < text.size()) {
        return {last, std::errc::value_too_large};
    }
    std::memcpy(first, text.data(), text.size());
    return {first + text.size(), std::errc{}};
}

/// The fewest significant digits that read back as `value` (finite, > 0), and the decimal
/// exponent of the first: value = 0.DIGITS × 10^(exponent + 1).
void shortestDigits(double value, std::string& digits, int& exponent) {
    char buf[40];
    for (int precision = 0; precision <= 17; ++precision) {
        std::snprintf(buf, sizeof buf, "%.*e", precision, value);
        if (std::strtod(buf, nullptr) == value || precision == 17) break;
    }
    const char* e = std::strchr(buf, 'e');
    exponent = std::atoi(e + 1);
    digits.clear();
    for (const char* p = buf; p != e; ++p)
        if (*p != '.') digits += *p;
    while (digits.size() > 1 && digits.back() == '0')
        digits.pop_back();
}

std::string scientific(const std::string& digits, int exponent) {
    std::string s(1, digits[0]);
    if (digits.size() > 1) s += "." + digits.substr(1);
    char e[8];
    std::snprintf(e, sizeof e, "e%c%02d", exponent < 0 ? '-' : '+', std::abs(exponent));
    return s + e;
}

std::string fixed(const std::string& digits, int exponent) {
    const int n = static_cast<int>(digits.size());
    if (exponent < 0)
        return "0." + std::string(static_cast<std::size_t>(-exponent - 1), '0') + digits;
    if (exponent + 1 >= n)
        return digits + std::string(static_cast<std::size_t>(exponent + 1 - n), '0');
    return digits.substr(0, static_cast<std::size_t>(exponent + 1)) + "." +
           digits.substr(static_cast<std::size_t>(exponent + 1));
}

std::string special(double value) {
    if (std::isnan(value)) return std::signbit(value) ? "-nan" : "nan";
    if (std::isinf(value)) return value < 0 ? "-inf" : "inf";
    return std::signbit(value) ? "-0" : "0";
}

enum class Choice { Shortest, Fixed, Scientific };

std::to_chars_result shortest(char* first, char* last, double value, Choice choice) {
    if (!std::isfinite(value) || value == 0.0) {
        std::string s = special(value);
        if (value == 0.0 && choice == Choice::Scientific) s += "e+00";
        return put(first, last, s);
    }
    std::string digits;
    int exponent = 0;
    shortestDigits(std::abs(value), digits, exponent);
    const std::string f = fixed(digits, exponent), e = scientific(digits, exponent);
    const std::string& text = choice == Choice::Fixed        ? f
                              : choice == Choice::Scientific ? e
                                                             : (f.size() <= e.size() ? f : e);
    return put(first, last, (value < 0 ? "-" : "") + text);
}

}  // namespace

std::to_chars_result toChars(char* first, char* last, double value) {
    return shortest(first, last, value, Choice::Shortest);
}

std::to_chars_result toChars(char* first, char* last, double value, std::chars_format format) {
    if (format == std::chars_format::fixed) return shortest(first, last, value, Choice::Fixed);
    if (format == std::chars_format::scientific) {
        return shortest(first, last, value, Choice::Scientific);
    }
    return shortest(first, last, value, Choice::Shortest);
}

std::to_chars_result toChars(char* first, char* last, double value, std::chars_format format,
                             int precision) {
    const char* spec = format == std::chars_format::fixed        ? "%.*f"
                       : format == std::chars_format::scientific ? "%.*e"
                                                                 : "%.*g";
    char buf[400];
    std::snprintf(buf, sizeof buf, spec, precision, value);
    return put(first, last, buf);
}

std::from_chars_result fromChars(const char* first, const char* last, double& value) {
    // std::from_chars takes no whitespace, '+' or hexadecimal "0x" here.
    const std::string text(first, last);
    const bool hex = text.find_first_of("xX") != std::string::npos;
    if (text.empty() || std::isspace(static_cast<unsigned char>(text[0])) || text[0] == '+' ||
        hex) {
        return {first, std::errc::invalid_argument};
    }
    errno = 0;
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (end == text.c_str()) return {first, std::errc::invalid_argument};
    const char* stop = first + (end - text.c_str());
    if (errno == ERANGE && std::isinf(v)) return {stop, std::errc::result_out_of_range};
    value = v;
    return {stop, std::errc{}};
}

}  // namespace psb::detail

#endif
