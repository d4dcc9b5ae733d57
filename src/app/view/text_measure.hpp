#pragma once
// How the view measures text without drawing it. The layout sizes its boxes, wraps lines and
// pages the help by these two numbers; the drawing layer's font (render/text.hpp) provides them,
// so the view needs no SDL and a test can measure with a stand-in.

#include <string_view>

namespace psb::app {

class TextMeasure {
  public:
    virtual ~TextMeasure() = default;

    /// Distance between baselines, pixels.
    [[nodiscard]] virtual int lineHeight() const = 0;
    /// Width of `text` (UTF-8) in pixels.
    [[nodiscard]] virtual int measure(std::string_view text) const = 0;

  protected:
    TextMeasure() = default;
    TextMeasure(const TextMeasure&) = default;
    TextMeasure& operator=(const TextMeasure&) = default;
};

}  // namespace psb::app
