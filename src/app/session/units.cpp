#include "session/units.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace psb::app {

namespace {

/// Three significant figures of `v` in [1, 1000) or below: "4.04", "40.4", "404".
std::string threeFigures(double v) {
    char buf[64];
    if (v != 0.0 && std::isfinite(v)) {  // rounded first: 0.9997 is "1.00", not "1.000"
        const double unit = std::pow(10.0, std::floor(std::log10(std::abs(v))) - 2.0);
        v = std::round(v / unit) * unit;
    }
    const double a = std::abs(v);
    if (a >= 100.0 || a == 0.0) {
        std::snprintf(buf, sizeof buf, "%.0f", v);
    } else if (a >= 10.0) {
        std::snprintf(buf, sizeof buf, "%.1f", v);
    } else if (a >= 1.0) {
        std::snprintf(buf, sizeof buf, "%.2f", v);
    } else {
        // 0.00123: as many decimals as three significant figures need.
        const int decimals = std::min(12, 2 - static_cast<int>(std::floor(std::log10(a))));
        std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    }
    return buf;
}

/// `v` rounded to three significant figures, digits grouped: "40 400".
std::string grouped(double v) {
    const double a = std::abs(v);
    const int digits = static_cast<int>(std::floor(std::log10(a))) + 1;
    const double unit = std::pow(10.0, digits - 3);
    const double rounded = std::round(a / unit) * unit;
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.0f", rounded);
    std::string s = buf, out;
    const int n = static_cast<int>(s.size());
    for (int k = 0; k < n; ++k) {
        if (k > 0 && (n - k) % 3 == 0) out += ' ';
        out += s[static_cast<std::size_t>(k)];
    }
    return (v < 0.0 ? "-" : "") + out;
}

/// The digits of `n` raised, as a power is written: 14 -> "¹⁴", -7 -> "⁻⁷" (the panel's font
/// and the HUD's have them: the gui loads U+2070 to U+209F).
std::string superscript(int n) {
    static const char* const digits[10] = {"\u2070", "\u00b9", "\u00b2", "\u00b3", "\u2074",
                                           "\u2075", "\u2076", "\u2077", "\u2078", "\u2079"};
    std::string out = n < 0 ? "\u207b" : "";
    for (const char c : std::to_string(n < 0 ? -static_cast<long long>(n) : n))
        out += digits[c - '0'];
    return out;
}

/// The digits of a whole number's text grouped by thousands with spaces: "12190" -> "12 190".
std::string groupDigits(const std::string& whole) {
    const bool minus = !whole.empty() && whole[0] == '-';
    const std::string s = minus ? whole.substr(1) : whole;
    std::string out;
    const int n = static_cast<int>(s.size());
    for (int k = 0; k < n; ++k) {
        if (k > 0 && (n - k) % 3 == 0) out += ' ';
        out += s[static_cast<std::size_t>(k)];
    }
    return (minus ? "-" : "") + out;
}

/// `v` as three significant figures times a power of ten: "1.03 × 10²⁴".
std::string scientific(double v) {
    int power = static_cast<int>(std::floor(std::log10(std::abs(v))));
    // In two factors: 10^-323 alone is below the smallest double.
    double mantissa = v / std::pow(10.0, power / 2) / std::pow(10.0, power - power / 2);
    if (std::abs(std::stod(threeFigures(mantissa))) >= 10.0) {  // 9.996 rounds to 10.0
        ++power;
        mantissa /= 10.0;
    }
    return threeFigures(mantissa) + " \u00d7 10" + superscript(power);
}

}  // namespace

std::string plainNumber(double value, int significant) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*g", std::clamp(significant, 1, 17), value);
    const std::string text = buf;
    return text == "-0" ? "0" : text;
}

std::string fieldNumber(double value) {
    const double a = std::abs(value);
    if (!std::isfinite(value) || a < std::numeric_limits<double>::min()) {
        return plainNumber(value, 3);
    }
    // Where the readouts write a power of ten: the same three figures as a field reads them.
    if (a < 1e-6 || a >= 1e9) return plainNumber(value, 3);
    return threeFigures(value);
}

std::string pair(double x, double y, int decimals) {
    const auto one = [decimals](double v) {
        if (decimals < 0) return plainNumber(v, 3);
        char buf[64];
        std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
        return std::string(buf);
    };
    std::string s = "[";  // appended: GCC 12 warns wrongly (-Wrestrict) on a chain of +
    s += one(x);
    s += ",\u00a0";
    s += one(y);
    s += "]";
    return s;
}

std::string components(const Vec2& v) {
    // Built by appending: GCC 12 warns wrongly (-Wrestrict) on a chain of + from a literal.
    std::string s = "(";
    s += quantity(v.x(), "", false);
    s += ", ";
    s += quantity(v.y(), "", false);
    s += ")";
    return s;
}

std::string quantity(double value, const std::string& unit, bool prefix) {
    if (std::isnan(value)) return "n/a";
    if (std::isinf(value)) return std::string(value < 0.0 ? "-" : "") + "infinite";
    const std::string u = unit.empty() ? "" : " " + unit;
    // Below the smallest normal double is underflow, never a measured value (a velocity decayed
    // to 10^-323 m/s is at rest): "0", not "-3.46 × 10⁻³²³".
    if (std::abs(value) < std::numeric_limits<double>::min()) return "0" + u;
    const double a = std::abs(value);
    if (!prefix) {
        // Grouped digits up to a billion; beyond, or below a millionth, a power of ten (no
        // 31-digit number, no row of zeros).
        if (a >= 1e9 || a < 1e-6) return scientific(value) + u;
        return (a >= 1000.0 ? grouped(value) : threeFigures(value)) + u;
    }
    // Past the prefixes (exa, atto): a power of ten, not "1030000 EJ".
    if (a >= 999.5e18 || a < 0.9995e-18) return scientific(value) + u;
    static const char* const big[] = {"", "k", "M", "G", "T", "P", "E"};
    static const char* const small[] = {"", "m", "\u00b5", "n", "p", "f", "a"};
    int k = static_cast<int>(std::floor(std::log10(a) / 3.0));
    k = std::max(-6, std::min(6, k));
    double scaled = value / std::pow(1000.0, k);
    // Rounding may carry to 1000 ("999.7 k" -> "1.00 M").
    if (std::abs(std::stod(threeFigures(scaled))) >= 1000.0 && k < 6) {
        ++k;
        scaled /= 1000.0;
    }
    const char* p = k >= 0 ? big[k] : small[-k];
    return threeFigures(scaled) + " " + p + unit;
}

std::string withError(double value, double error, const std::string& unit) {
    const std::string u = unit.empty() ? "" : " " + unit;
    if (!(error > 0.0) || !std::isfinite(error) || !std::isfinite(value))
        return quantity(value, "", false) + " \u00b1 " + quantity(error, unit, false);
    // Two significant figures of the error, the value to the same decimal place.
    int decimals = 1 - static_cast<int>(std::floor(std::log10(error)));
    if (std::round(error * std::pow(10.0, decimals)) >= 100.0) --decimals;  // 0.996 -> 1.0
    if (decimals > 12 || decimals < -15) {
        return quantity(value, "", false) + " \u00b1 " + quantity(error, unit, false);
    }
    const auto text = [decimals](double v) {
        char buf[64];
        if (decimals >= 0) {
            std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
            const std::string t = buf;
            const std::size_t point = t.find('.');
            // Whole digits grouped as the readouts group them ("12 190.5").
            return groupDigits(t.substr(0, point)) +
                   (point == std::string::npos ? "" : t.substr(point));
        }
        const double step = std::pow(10.0, -decimals);
        std::snprintf(buf, sizeof buf, "%.0f", std::round(v / step) * step);
        return groupDigits(buf);
    };
    std::string v = text(value);
    if (v.find_first_not_of("-0. ") == std::string::npos) v = text(0.0);  // never "-0.00"
    return v + " \u00b1 " + text(error) + u;
}

std::string keptWords(double relativeChange) {
    if (std::isnan(relativeChange)) return "not measured";
    const double a = std::abs(relativeChange);
    if (a < 1e-15) return "kept exactly (to rounding)";
    if (a >= 1e-3) {
        char buf[64];
        std::snprintf(buf, sizeof buf, "changed by %s %%",
                      threeFigures(100.0 * relativeChange).c_str());
        return buf;
    }
    const int power = static_cast<int>(std::floor(-std::log10(a)));
    return "kept to 1 part in 10" + superscript(power);
}

std::string overlapWords(double overlap, double typicalRadius) {
    if (overlap > 1e-9 * typicalRadius)
        return "Particles overlap by up to " + quantity(overlap, "m");
    return overlap > 0.0 ? "No particles overlap (beyond rounding)" : "No particles overlap";
}

}  // namespace psb::app
