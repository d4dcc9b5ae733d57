#pragma once
// The numbers of a chart's axes: a y range fitted to the data, tick values at round steps and
// their labels. The charts (render/plot_chart.hpp) draw with them; kept apart from the drawing
// so that they are tested as plain numbers and strings.

#include <string>
#include <vector>

namespace psb::app {

/// A plot's y range, in the quantity's unit.
struct PlotRange {
    double lo = 0.0;
    double hi = 1.0;
};

/// [dataMin, dataMax] widened symmetrically to at least `minSpan` (> 0), then rounded out to
/// tick steps (see niceTicks).
[[nodiscard]] PlotRange plotRange(double dataMin, double dataMax, double minSpan);

/// Tick values in [lo, hi]: multiples of 1, 2 or 5 × 10^k, at most `maxTicks` of them.
[[nodiscard]] std::vector<double> niceTicks(double lo, double hi, int maxTicks);
/// The step niceTicks uses.
[[nodiscard]] double niceStep(double lo, double hi, int maxTicks);

/// A y axis's labelled ticks and the step their labels are written to (tickLabel).
struct AxisTicks {
    std::vector<double> values;
    double step = 1.0;
};
/// The ticks of a y axis over [lo, hi] that has room for `most` labels: niceTicks' (at most
/// `most`), and never fewer than 3 where there is room for 3 (a row of the plots read one
/// number, "3.50", at 200 %): round steps that give 3 to `most`, else [lo, hi]'s ends and
/// middle.
[[nodiscard]] AxisTicks axisTicks(double lo, double hi, int most);

/// `v` with as many significant digits as a tick `step` needs, with an SI prefix outside
/// [1e-3, 1e5): 4038789 with step 20000 -> "4.04M"; 0.5 -> "0.5"; 2e-5 -> "20u".
[[nodiscard]] std::string tickLabel(double v, double step);

/// The collision rate plot's title, naming the window of simulated time it counts over
/// (Monitor::rateWindow): "collisions/s, last 0.5 s".
[[nodiscard]] std::string collisionRateTitle(double windowSeconds);

/// The plots (K), in their order on screen: kinetic energy, momentum px and py, collision rate.
inline constexpr int kPlotCount = 4;
/// The title of plot `plot` (0-3, as kPlotCount orders them) for a rate counted over
/// `windowSeconds`: "momentum px (kg m/s)"; `brief`, the form for a plot in a narrow column
/// (four side by side under the box at 200 %): "px (kg m/s)", "coll./s, 0.5 s".
[[nodiscard]] std::string plotTitle(int plot, double windowSeconds, bool brief = false);

}  // namespace psb::app
