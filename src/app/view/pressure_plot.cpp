#include "view/pressure_plot.hpp"

#include <algorithm>
#include <cmath>

#include "session/units.hpp"

namespace psb::app {

PressurePlot pressurePlot(const std::deque<GasHistoryPoint>& history, double span) {
    PressurePlot plot;
    if (history.size() < 2) return plot;
    plot.t1 = history.back().time;
    plot.t0 = std::max(history.front().time, plot.t1 - span);
    auto first = std::find_if(history.begin(), history.end(),
                              [&](const GasHistoryPoint& p) { return p.time >= plot.t0; });
    // A point whose predictions are not numbers (never from a valid world) is left out.
    const auto drawable = [](const GasHistoryPoint& p) {
        return std::isfinite(p.idealPressure) && std::isfinite(p.hardDiskPressure) &&
               (!p.pressure || (std::isfinite(*p.pressure) && std::isfinite(p.pressureError)));
    };
    double top = 0.0;
    for (auto it = first; it != history.end(); ++it) {
        if (!drawable(*it)) continue;
        top = std::max({top, it->idealPressure, it->hardDiskPressure});
        if (it->pressure) top = std::max(top, *it->pressure + it->pressureError);
    }
    if (!(std::isfinite(top) && top > 0.0) || !(plot.t1 > plot.t0)) return plot;
    // Room above the highest line, and a round number at the top.
    const double step = std::pow(10.0, std::floor(std::log10(1.15 * top)));
    plot.top = std::ceil(1.15 * top / step) * step;
    const auto at = [&](double t, double p) {
        return Vec2((t - plot.t0) / (plot.t1 - plot.t0), std::clamp(p / plot.top, 0.0, 1.0));
    };
    bool inStretch = false;
    for (auto it = first; it != history.end(); ++it) {
        if (!drawable(*it)) continue;
        plot.hardDisk.push_back(at(it->time, it->hardDiskPressure));
        plot.ideal.push_back(at(it->time, it->idealPressure));
        if (!it->pressure) {
            inStretch = false;
            continue;
        }
        if (!inStretch) {
            plot.measured.emplace_back();
            plot.measuredLow.emplace_back();
            plot.measuredHigh.emplace_back();
            inStretch = true;
        }
        plot.measured.back().push_back(at(it->time, *it->pressure));
        plot.measuredLow.back().push_back(at(it->time, *it->pressure - it->pressureError));
        plot.measuredHigh.back().push_back(at(it->time, *it->pressure + it->pressureError));
    }
    return plot;
}

std::string pressurePlotLine(const std::deque<GasHistoryPoint>& history) {
    if (history.empty()) return {};
    const GasHistoryPoint& now = history.back();
    std::string s = "Pressure plot: t = ";
    s += quantity(history.front().time, "s");
    s += " to ";
    s += quantity(now.time, "s");
    s += ", ";
    s += std::to_string(history.size());
    s += " points; now measured ";
    if (now.pressure) {
        s += withError(*now.pressure, now.pressureError, "N/m");
    } else {
        s += "(window too short)";
    }
    s += ", hard discs ";
    s += quantity(now.hardDiskPressure, "N/m", false);
    s += ", ideal gas ";
    s += quantity(now.idealPressure, "N/m", false);
    return s;
}

PlotScaleLabels plotScaleLabels(float height, float font) {
    const float air = std::max(2.f, 0.2f * font);
    PlotScaleLabels l;
    l.x = air + 1.f;
    l.top = air;
    l.bottom = std::max(l.top + font, height - font - air);
    return l;
}

}  // namespace psb::app
