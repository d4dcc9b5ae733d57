#pragma once
// The text of the side column's charts (the plots, K; the speed histogram, D) fitted to their
// frames at any UI scale: a legend's entries wrapped within the frame, the room at the left for
// the y axis's tick labels as wide as the widest, and as many ticks as the plot's height has
// room for. Pure, measured through TextMeasure, so that the rule is tested without drawing;
// render/plot_chart.cpp and render/speed_chart.cpp draw what it says. At 200 % the charts'
// fixed pixel offsets cut the histogram's legend at the frame's right edge, the plots' tick
// labels at its left, and stacked four tick labels into a plot two lines high.

#include <algorithm>
#include <cstddef>
#include <string>
#include <vector>

#include "view/text_measure.hpp"

namespace psb::app {

/// Pixels between a chart's frame and its text.
inline constexpr int kChartPad = 8;

/// One line of a legend and the entry (its colour) it belongs to.
struct LegendLine {
    std::string text;
    std::size_t entry = 0;
};

/// `entries`, each wrapped at its spaces within a frame `width` pixels wide (kChartPad each
/// side), in order.
[[nodiscard]] std::vector<LegendLine> fitLegend(const TextMeasure& font,
                                                const std::vector<std::string>& entries, int width);

/// The pixels from a chart frame's left edge to its plot's y axis that hold `labels` (the tick
/// labels, right-aligned against the axis), the padding and the tick marks, and at least
/// `least`.
[[nodiscard]] int yAxisRoom(const TextMeasure& font, const std::vector<std::string>& labels,
                            int least = 0);

/// Where one plot of the plots' frame (K) goes, pixels down the window.
struct PlotRowPlace {
    float title = 0.f;  ///< the top of its title's line
    float top = 0.f;    ///< its y axis, from top to bottom
    float bottom = 0.f;
};
/// The plots' frame at `y`, `rows` plots of `rowHeight` pixels in a frame rows × rowHeight + 8
/// high, with text `lineHeight` high: each plot's title on its own line, its axis starting half
/// a line below it (the top tick label, centred on the axis's top, clear of the title: at 200 %
/// the title sat on the top number), and the time axis's labels and its caption "t (s)" on a
/// line below the last plot's bottom tick label.
struct PlotRowsPlace {
    std::vector<PlotRowPlace> rows;
    float timeLabels = 0.f;  ///< the top of the time axis's labels' line
};
[[nodiscard]] PlotRowsPlace plotRowsPlace(float y, int rows, float rowHeight, float lineHeight);

/// The most ticks (niceTicks' maxTicks) a y axis `pixels` high takes with its labels one
/// `lineHeight` high each clear of the next (centred on their ticks, the top and bottom ones
/// at the axis's ends): 5 where there is room, at least 1.
[[nodiscard]] int yTickCount(double pixels, int lineHeight);

/// The left edge of a time axis's label `width` pixels wide for the tick at `tick`: centred on
/// it, but never past `frameRight` less half the frame's padding (the last tick, "1.0", stands
/// at the axis's right end, and its label reached the frame's edge).
[[nodiscard]] inline float timeLabelLeft(float tick, float width, float frameRight) {
    return std::min(tick - width / 2.f, frameRight - kChartPad / 2.f - width);
}

/// Labelled ticks a plot's y axis keeps at least: its plots' rows are never shorter than
/// their room (kPlotRowMinHeight), where there are fewer plots instead.
inline constexpr int kPlotTicksLeast = 3;

}  // namespace psb::app
