#pragma once
// The bins chart of a Galton board (view/bin_histogram.hpp): the counts as bars, the binomial's
// expected counts as dots, the normal curve as a line, under the legend in the bars' colours.

#include <string>
#include <vector>

#include <SDL.h>

#include "render/geometry_batch.hpp"
#include "view/bin_histogram.hpp"
#include "view/palette.hpp"
#include "view/pixel_rect.hpp"

namespace psb::app {

class Font;

/// Where the chart goes in a panel of `x`, `width`, `boxBottom` (pixels) under a legend that
/// ends at `legendBottom`: the plot's axes, the y axis caption ("balls") on its own line above
/// the plot, and the x axis caption (`xTitle`) on the line under the bin numbers, right-aligned
/// but never left of the box. The two captions are on different lines at every size.
struct BinChartLayout {
    float left = 0, right = 0, top = 0, bottom = 0;
    SDL_FRect yCaption{}, xCaption{};
    /// Whether the plot has room to be drawn at all.
    [[nodiscard]] bool fits() const { return bottom > top + 10; }
};
[[nodiscard]] BinChartLayout binChartLayout(const Font& font, float x, float width,
                                            float legendBottom, float boxBottom,
                                            const std::string& yTitle, const std::string& xTitle);

/// Colours, for the tests to look for.

class BinChart {
  public:
    /// Draws `h` in `box` (pixels, see PanelLayout).
    void draw(SDL_Renderer* renderer, const Font& font, const BinHistogram& h, const PixelRect& box,
              const Palette& colours = palette(Theme::Dark), float lineWidth = 1.f);

  private:
    GeometryBatch boxes_, text_, thick_;  // thick_: the curves wider than a pixel
    std::vector<SDL_FPoint> curve_;
};

}  // namespace psb::app
