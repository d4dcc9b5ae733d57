#include <particle_sandbox/csv.hpp>
#include <particle_sandbox/detail/float_chars.hpp>

#include <charconv>
#include <cmath>

namespace psb::csv {
namespace {

std::string notFinite(double value) {
    if (std::isnan(value)) return "nan";
    return value > 0.0 ? "inf" : "-inf";
}

}  // namespace

std::string number(double value) {
    if (!std::isfinite(value)) return notFinite(value);
    char buffer[64];
    const double size = std::abs(value);
    // Shortest round trip in either notation: plain where a reader takes in the digits at a
    // glance, scientific where plain would be a long run of zeros.
    const std::chars_format format = (size == 0.0 || (size >= 1e-4 && size < 1e6))
                                         ? std::chars_format::fixed
                                         : std::chars_format::scientific;
    const auto [end, ec] = psb::detail::toChars(buffer, buffer + sizeof buffer, value, format);
    if (ec != std::errc{}) return notFinite(value);  // never for a finite double in 64 chars
    return std::string(buffer, end);
}

std::string time(double seconds) {
    if (!std::isfinite(seconds)) return notFinite(seconds);
    char buffer[64];
    // %g's rule with 12 significant digits: trailing zeros dropped, scientific only past 10¹².
    const auto [end, ec] = psb::detail::toChars(buffer, buffer + sizeof buffer, seconds,
                                                std::chars_format::general, 12);
    if (ec != std::errc{}) return notFinite(seconds);
    std::string text(buffer, end);
    return text == "-0" ? "0" : text;
}

Table::Table(Separator separator, std::initializer_list<std::string_view> header)
    : Table(separator, std::span<const std::string_view>(header.begin(), header.size())) {}

Table::Table(Separator separator, std::span<const std::string_view> header)
    : separator_(static_cast<char>(separator)) {
    for (const std::string_view name : header)
        text(name);
    endRow();
    rows_ = 0;
}

Table& Table::text(std::string_view cell) {
    if (rowStarted_) text_ += separator_;
    rowStarted_ = true;
    if (cell.find_first_of(std::string_view("\"\n\r")) == std::string_view::npos &&
        cell.find(separator_) == std::string_view::npos) {
        text_ += cell;
        return *this;
    }
    text_ += '"';
    for (const char c : cell) {
        if (c == '"') text_ += '"';
        text_ += c;
    }
    text_ += '"';
    return *this;
}

void Table::endRow() {
    text_ += '\n';
    rowStarted_ = false;
    ++rows_;
}

}  // namespace psb::csv
