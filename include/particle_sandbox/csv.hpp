#pragma once
/// \file
/// Tables as text for spreadsheets: comma-separated for files (CSV), tab-separated for the
/// clipboard, with numbers written the way people read them. The app's exports and
/// particle-sim's CSV output both write through here.

#include <cstdint>
#include <initializer_list>
#include <span>
#include <string>
#include <string_view>

namespace psb::csv {

/// A number as a spreadsheet should read it: the shortest decimal that reads back as the same
/// double (std::to_chars), in plain notation for magnitudes from 10⁻⁴ to below 10⁶ (and 0), in
/// scientific notation outside (1.03e+12, never a 13-digit integer); "nan", "inf", "-inf" for
/// values that are not finite.
[[nodiscard]] std::string number(double value);

/// A time in seconds to at most 12 significant digits, trailing zeros dropped: a clock that
/// adds steps of 0.1 s reads 0.3, not 0.30000000000000004 (12 digits resolve a nanosecond
/// over 1000 s).
[[nodiscard]] std::string time(double seconds);

/// Between cells: a comma for a CSV file, a tab for the clipboard (a spreadsheet pastes each
/// value into a cell of its own).
enum class Separator : char { Comma = ',', Tab = '\t' };

/// A table written row by row into one string: the header first, then cells, each row ended
/// by endRow(). A cell holding the separator, a quote or a line break is quoted (RFC 4180).
class Table {
  public:
    Table(Separator separator, std::initializer_list<std::string_view> header);
    /// A header whose columns depend on the data (optional column groups).
    Table(Separator separator, std::span<const std::string_view> header);

    Table& text(std::string_view cell);
    Table& number(double value) { return text(csv::number(value)); }
    Table& time(double seconds) { return text(csv::time(seconds)); }
    Table& count(std::uint64_t value) { return text(std::to_string(value)); }
    /// An empty cell (a value that does not apply to this row).
    Table& none() { return text({}); }
    void endRow();

    [[nodiscard]] const std::string& str() const { return text_; }
    [[nodiscard]] std::size_t rows() const { return rows_; }  ///< the header not counted

  private:
    char separator_;
    bool rowStarted_ = false;
    std::size_t rows_ = 0;
    std::string text_;
};

}  // namespace psb::csv
