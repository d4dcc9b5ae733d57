#pragma once
// The bins panel: a Galton board's bin counts as bars, against the binomial distribution its
// scene expects (a dot per bin) and the normal curve that approximates it (mean n p, standard
// deviation sqrt(n p (1 - p)), scaled to the balls counted), with a legend in plain words and a
// line saying how far the counts are from the curve (Pearson's chi-squared test at 1 %).
//
// What it says is computed without SDL (binHistogram), from the same counts it draws, so the
// words and the bars never disagree; the screen-text dump (F12) lists the same lines.

#include <cstdint>
#include <string>
#include <vector>

#include <SDL.h>

#include <particle_sandbox/bins.hpp>

#include "geometry_batch.hpp"

namespace psb::app {

class Font;

/// The panel's content for one frame.
struct BinHistogram {
    Bins bins;
    BinsMeasurement now;
    /// The legend, one line each: the bars, the binomial, the normal curve, the verdict.
    std::vector<std::string> legend;
};

/// The bins of `p` now, and the legend that describes them; `stillToDrop` balls are still in
/// the scene's droppers (counted in the legend, not yet anywhere on the board).
[[nodiscard]] BinHistogram binHistogram(const Bins& bins, const ParticleArrays& p,
                                        std::uint64_t stillToDrop = 0);

/// The normal approximation to Binomial(n, p) over `total` balls, as a count per bin at bin
/// position `k` (bins one unit wide): total · φ((k − n p) / σ) / σ, σ = sqrt(n p (1 − p)).
/// 0 when σ is 0.
[[nodiscard]] double normalCount(double k, const BinomialExpectation& b, double total);

/// "1/2" for 0.5, else the probability with up to three significant digits.
[[nodiscard]] std::string probabilityText(double p);

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
inline constexpr SDL_Color kBinBarColor{230, 160, 60, 255};
inline constexpr SDL_Color kBinomialDotColor{255, 255, 255, 255};
inline constexpr SDL_Color kNormalCurveColor{90, 200, 255, 255};

class BinHistogramPanel {
  public:
    /// Draws `h` in `box` (pixels, see PanelLayout).
    void draw(SDL_Renderer* renderer, const Font& font, const BinHistogram& h, const SDL_Rect& box);

  private:
    GeometryBatch boxes_, text_;
    std::vector<SDL_FPoint> curve_;
};

}  // namespace psb::app
