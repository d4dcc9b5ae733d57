#pragma once
// A stand-in for the HUD's font where a test needs text measured without SDL: every character
// (UTF-8 code point) 8 pixels wide, lines 17 pixels apart, about the 14 px DejaVu Sans Mono the
// app's HUD uses.

#include <string_view>

#include "view/text_measure.hpp"

namespace psb::app::test {

class FixedMeasure final : public TextMeasure {
  public:
    [[nodiscard]] int lineHeight() const override { return 17; }
    [[nodiscard]] int measure(std::string_view text) const override {
        int n = 0;
        for (const char c : text)
            n += (static_cast<unsigned char>(c) & 0xC0) != 0x80;  // not a continuation byte
        return 8 * n;
    }
};

}  // namespace psb::app::test
