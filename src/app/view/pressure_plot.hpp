#pragma once
// The pressure plot of the gas instruments (session/gas_gauges.hpp): the pressure measured on
// the walls with its error band, beside the hard-disk and the ideal-gas values, over simulated
// time. This is the plot's content in unit coordinates (0 to 1 across, 0 at the bottom to 1 at
// the top) with its axes' ranges; the panel's Readouts draw it and the text F12 writes lists
// its latest point.

#include <deque>
#include <string>
#include <vector>

#include <particle_sandbox/math.hpp>

#include "session/gas_gauges.hpp"

namespace psb::app {

struct PressurePlot {
    double t0 = 0.0, t1 = 0.0;  ///< s, the time axis
    double top = 0.0;           ///< N/m at the top of the plot (the bottom is 0)
    /// Lines in unit coordinates. The measured one has breaks where the window was too short
    /// for a value (after an edit): one polyline per stretch.
    std::vector<std::vector<Vec2>> measured;
    std::vector<std::vector<Vec2>> measuredLow, measuredHigh;  ///< ± one standard error
    std::vector<Vec2> hardDisk, ideal;

    [[nodiscard]] bool empty() const { return hardDisk.size() < 2; }
};

/// The plot of `history`'s points within the last `span` seconds.
[[nodiscard]] PressurePlot pressurePlot(const std::deque<GasHistoryPoint>& history,
                                        double span = 60.0);

/// Where the plot's scale labels go in its frame, pixels from the frame's top-left: the top's
/// value and the bottom's 0, each a line of text `font` pixels high, clear of the frame's
/// lines (drawn a pixel or more thick as the UI grows) by a fifth of a line. At 200 % the "0
/// N/m" stood on the frame's bottom line and the top's value under its top line.
struct PlotScaleLabels {
    float x = 0.f;       ///< both labels' left edge
    float top = 0.f;     ///< the top label's top edge
    float bottom = 0.f;  ///< the bottom label's top edge
};
[[nodiscard]] PlotScaleLabels plotScaleLabels(float height, float font);

/// "Pressure plot: t = 1.00 s to 13.0 s, 49 points; now measured 12.2 ± 0.21 N/m, hard discs
/// 11.9 N/m, ideal gas 8.36 N/m" (the latest point), or empty when there is none.
[[nodiscard]] std::string pressurePlotLine(const std::deque<GasHistoryPoint>& history);

}  // namespace psb::app
