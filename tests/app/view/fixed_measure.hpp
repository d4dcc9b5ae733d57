#pragma once
// A stand-in for the HUD's font where a test needs text measured without SDL: every character
// (UTF-8 code point) 8 pixels wide, lines 17 pixels apart, about the 14 px DejaVu Sans Mono the
// app's HUD uses.

#include <string_view>

#include "view/text_measure.hpp"

namespace psb::app::test {

class FixedMeasure final : public TextMeasure {
  public:
    /// At `scale` × the size (the UI's scale): `scale` × 8 pixels a character, × 17 a line.
    explicit FixedMeasure(double scale = 1.0) : scale_(scale) {}
    [[nodiscard]] int lineHeight() const override { return static_cast<int>(17 * scale_); }
    [[nodiscard]] int measure(std::string_view text) const override {
        int n = 0;
        for (const char c : text)
            n += (static_cast<unsigned char>(c) & 0xC0) != 0x80;  // not a continuation byte
        return static_cast<int>(8 * scale_ * n);
    }

  private:
    double scale_;
};

}  // namespace psb::app::test
