#pragma once
// The plots panel (the K key): total kinetic energy (J), momentum px and py (kg m/s) and the
// collision rate (1/s, counted over a window of simulated time its title states) against
// simulated time, from the app's TimeSeries. The rate's line starts where the series first
// reaches a whole window back.
//
// Each y range is fitted to the data but never narrower than a floor tied to the quantity's
// own size: 1 % of the mean kinetic energy, 1 % of the momentum scale √(2 M E) (the largest
// |Σ m v| the energy allows), so a conserved quantity drawn with rounding noise of 1e-15 is a
// flat line in the middle of its plot instead of full-height wiggles; an inelastic gas's energy
// visibly steps down.

#include <functional>
#include <string>
#include <vector>

#include <SDL.h>

#include <particle_sandbox/time_series.hpp>

#include "render/geometry_batch.hpp"
#include "view/palette.hpp"
#include "view/pixel_rect.hpp"
#include "view/plot_scale.hpp"

namespace psb::app {

class Font;

/// A panel's box in pixels (as floats) and the font's line height.
struct ChartFrame {
    float x = 0, y = 0, w = 0, h = 0, lineHeight = 0;
};
/// Starts a panel in `box`: empties both batches and puts the panel's translucent background in
/// `boxes`, in `colours`.
[[nodiscard]] ChartFrame beginChart(const Font& font, const PixelRect& box, GeometryBatch& boxes,
                                    GeometryBatch& text, const Palette& colours);

/// The ticks and labels of a y axis over [lo, hi] (axisTicks, at most `maxTicks`) left of
/// x = `left`: a tick mark and its label at the pixel row `row(v)` of each tick value v.
void layoutYTicks(const Font& font, double lo, double hi, float left,
                  const std::function<float(double)>& row, GeometryBatch& marks,
                  GeometryBatch& labels, const Palette& colours, int maxTicks = 4);
/// The labels layoutYTicks writes for [lo, hi] with at most `maxTicks` ticks.
[[nodiscard]] std::vector<std::string> yTickLabels(double lo, double hi, int maxTicks = 4);

class PlotChart {
  public:
    /// Draws the plots `which` (0 energy, 1 px, 2 py, 3 rate: plotsChosen; empty: all four),
    /// one a row, each `rowHeight` pixels (title and axis included), in `box` (pixels, see
    /// PanelLayout); `totalMass` (kg) sets the momentum plots' floor; `rateWindow` (s) names
    /// the rate's window in its title (the brief title, plotTitle, where the full one is wider
    /// than the frame); `yUp`: py upward (the y up option); `lineWidth` pixels
    /// (chartLineWidth). Nothing but the frame when `series` has fewer than 2 samples.
    void draw(SDL_Renderer* renderer, const Font& font, const TimeSeries& series,
              const PixelRect& box, int rowHeight, double totalMass, double rateWindow,
              const Palette& colours = palette(Theme::Dark), bool yUp = false,
              float lineWidth = 1.f, const std::vector<int>& which = {});

  private:
    GeometryBatch boxes_, text_, thick_;  // thick_: the curves wider than a pixel
    std::vector<SDL_FPoint> line_;
};

}  // namespace psb::app
