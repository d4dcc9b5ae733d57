#pragma once
// The text of the side column's charts (the plots, K; the speed histogram, D) fitted to their
// frames at any UI scale: a legend's entries wrapped within the frame, the room at the left for
// the y axis's tick labels as wide as the widest, and as many ticks as the plot's height has
// room for. Pure, measured through TextMeasure, so that the rule is tested without drawing;
// render/plot_chart.cpp and render/speed_chart.cpp draw what it says. At 200 % the charts'
// fixed pixel offsets cut the histogram's legend at the frame's right edge, the plots' tick
// labels at its left, and stacked four tick labels into a plot two lines high.

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

/// The most ticks (niceTicks' maxTicks) a y axis `pixels` high takes with its labels one
/// `lineHeight` high each clear of the next: 4 where there is room, at least 1.
[[nodiscard]] int yTickCount(double pixels, int lineHeight);

}  // namespace psb::app
