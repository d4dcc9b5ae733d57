#include "render/plot_chart.hpp"

#include "render/polyline.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "render/sdl_color.hpp"
#include "render/text.hpp"
#include "view/chart_text.hpp"

namespace psb::app {

ChartFrame beginChart(const Font& font, const PixelRect& box, GeometryBatch& boxes,
                      GeometryBatch& text, const Palette& colours) {
    boxes.clear();
    text.clear();
    const ChartFrame f{static_cast<float>(box.x), static_cast<float>(box.y),
                       static_cast<float>(box.w), static_cast<float>(box.h),
                       static_cast<float>(font.lineHeight())};
    boxes.quad(f.x, f.y, f.x + f.w, f.y + f.h, sdlColor(colours.panel));
    return f;
}

std::vector<std::string> yTickLabels(double lo, double hi, int maxTicks) {
    std::vector<std::string> labels;
    const AxisTicks ticks = axisTicks(lo, hi, maxTicks);
    for (const double t : ticks.values)
        labels.push_back(tickLabel(t, ticks.step));
    return labels;
}

void layoutYTicks(const Font& font, double lo, double hi, float left,
                  const std::function<float(double)>& row, GeometryBatch& marks,
                  GeometryBatch& labels, const Palette& colours, int maxTicks) {
    const SDL_Color axis = sdlColor(colours.axis), grey = sdlColor(colours.tickText);
    const float lh = static_cast<float>(font.lineHeight());
    const AxisTicks ticks = axisTicks(lo, hi, maxTicks);
    for (const double t : ticks.values) {
        const float y = row(t);
        marks.quad(left - 4, y, left - 1, y + 1, axis);
        const std::string label = tickLabel(t, ticks.step);
        font.layout(label, left - 6 - static_cast<float>(font.measure(label)), y - lh / 2, grey,
                    labels);
    }
}

void PlotChart::draw(SDL_Renderer* renderer, const Font& font, const TimeSeries& series,
                     const PixelRect& box, int rowHeight, double totalMass, double rateWindow,
                     const Palette& colours, bool yUp, float lineWidth,
                     const std::vector<int>& which) {
    boxes_.clear();
    text_.clear();
    std::vector<int> chosen;
    for (const int k : which)
        if (k >= 0 && k < kPlotCount) chosen.push_back(k);
    if (which.empty()) chosen = {0, 1, 2, 3};
    if (chosen.empty()) return;
    const int rows = static_cast<int>(chosen.size());
    const float lh = static_cast<float>(font.lineHeight());
    const float x = static_cast<float>(box.x), y = static_cast<float>(box.y);
    const float width = static_cast<float>(box.w), rowH = static_cast<float>(rowHeight);
    boxes_.quad(x, y, x + width, y + static_cast<float>(box.h), sdlColor(colours.panel));
    const SDL_Color axis = sdlColor(colours.axis), grey = sdlColor(colours.tickText);

    struct Plot {
        std::string title;
        double (*value)(const ObservablesSample&);
        SDL_Color color;
        double sign = 1.0;  ///< -1: py with y up (the world's y points down)
    };
    const Plot all[4] = {
        {"", [](const ObservablesSample& s) { return s.kineticEnergy; },
         sdlColor(colours.energyPlot)},
        {"", [](const ObservablesSample& s) { return s.momentum.x(); }, sdlColor(colours.pxPlot)},
        {"", [](const ObservablesSample& s) { return s.momentum.y(); }, sdlColor(colours.pyPlot),
         yUp ? -1.0 : 1.0},
        {"", [](const ObservablesSample& s) { return s.collisionRate; },
         sdlColor(colours.ratePlot)},
    };
    std::vector<Plot> plots;
    std::vector<int> kinds;
    for (const int k : chosen) {
        Plot p = all[k];
        // The brief title where the full one would run past the frame (four side by side).
        p.title = plotTitle(k, rateWindow);
        if (static_cast<float>(font.measure(p.title) + 2 * kChartPad) > width)
            p.title = plotTitle(k, rateWindow, true);
        plots.push_back(std::move(p));
        kinds.push_back(k);
    }
    const std::size_t n = series.size();
    double meanEnergy = 0.0;
    for (std::size_t k = 0; k < n; ++k)
        meanEnergy += series[k].kineticEnergy;
    if (n > 0) meanEnergy /= static_cast<double>(n);
    const double momentumScale = std::sqrt(2.0 * std::max(totalMass, 0.0) * meanEnergy);
    const double t0 = n > 0 ? series[0].time : 0.0;
    const double t1 = n > 1 ? series.back().time : t0 + 1.0;

    // Each row's range first: the y axis stands as far in as the widest tick label needs (78
    // pixels at 100 %; at 200 % a "-1.50" ran out of the frame's left edge), and a row keeps
    // only the ticks its height has room for.
    // Each plot's title on its own line, clear of its top tick label (view/chart_text.hpp).
    const PlotRowsPlace place = plotRowsPlace(y, rows, rowH, lh);
    const PlotRowPlace& shortest = place.rows.back();
    const int ticks = yTickCount(shortest.bottom - shortest.top, font.lineHeight());
    PlotRange ranges[4];
    std::size_t firsts[4] = {n, n, n, n};
    std::vector<std::string> labels;
    for (int k = 0; k < rows && n >= 2; ++k) {
        const Plot& pl = plots[static_cast<std::size_t>(k)];
        // A sample without a value (the rate before a whole window has run) is left out.
        std::size_t first = 0;
        while (first < n && std::isnan(pl.value(series[first])))
            ++first;
        double lo = first < n ? pl.sign * pl.value(series[first]) : 0.0, hi = lo;
        for (std::size_t s = first; s < n; ++s) {
            const double v = pl.sign * pl.value(series[s]);
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        }
        PlotRange& r = ranges[k];
        if (kinds[static_cast<std::size_t>(k)] == 0) {
            r = plotRange(lo, hi, 0.01 * std::max(std::abs(meanEnergy), 1e-300));
        } else if (kinds[static_cast<std::size_t>(k)] < 3) {
            r = plotRange(lo, hi, 0.01 * std::max(momentumScale, 1e-300));
        } else {
            r = plotRange(0.0, std::max(hi, 1.0), 1.0);  // a rate starts at 0
        }
        firsts[k] = first;
        for (std::string& l : yTickLabels(r.lo, r.hi, ticks))
            labels.push_back(std::move(l));
    }
    // The time axis's caption stands left of its first label ("0", centred on the axis).
    labels.push_back("t (s)  ");
    const float left = x + static_cast<float>(yAxisRoom(font, labels, 78));
    const float right = x + width - 8;                     // plot area, pixels
    std::vector<std::pair<SDL_Color, std::size_t>> lines;  // colour, end index in line_
    line_.clear();
    for (int k = 0; k < rows; ++k) {
        const Plot& pl = plots[static_cast<std::size_t>(k)];
        const PlotRowPlace& row = place.rows[static_cast<std::size_t>(k)];
        const float top = row.top, bottom = row.bottom;
        // The title from the frame's padding: from the axis, a long one ran past its right edge.
        font.layout(pl.title, x + kChartPad, row.title, sdlTextColor(pl.color, colours.panel),
                    text_);
        // Axes: left and bottom, grey.
        boxes_.quad(left - 1, top, left, bottom, axis);
        boxes_.quad(left - 1, bottom, right, bottom + 1, axis);
        if (n < 2) continue;
        const PlotRange& r = ranges[k];
        const std::size_t first = firsts[k];
        const auto sy = [&](double v) {
            return bottom - static_cast<float>((v - r.lo) / (r.hi - r.lo)) * (bottom - top);
        };
        const auto sx = [&](double t) {
            return left + static_cast<float>((t - t0) / (t1 - t0)) * (right - left);
        };
        layoutYTicks(font, r.lo, r.hi, left, sy, boxes_, text_, colours, ticks);
        for (std::size_t s = first; s < n; ++s)
            line_.push_back({sx(series[s].time), sy(pl.sign * pl.value(series[s]))});
        lines.emplace_back(pl.color, line_.size());
    }
    // The time axis of the last plot carries the labels: simulated seconds.
    if (n >= 2) {
        const float bottom = place.rows.back().bottom;
        const double step = niceStep(t0, t1, 4);
        for (const double t : niceTicks(t0, t1, 4)) {
            const float tx = left + static_cast<float>((t - t0) / (t1 - t0)) * (right - left);
            boxes_.quad(tx, bottom + 1, tx + 1, bottom + 4, axis);
            const std::string label = tickLabel(t, step);
            font.layout(label,
                        timeLabelLeft(tx, static_cast<float>(font.measure(label)), x + width),
                        place.timeLabels, grey, text_);
        }
        font.layout("t (s)", x + 8, place.timeLabels, grey, text_);
    }

    boxes_.draw(renderer, nullptr);
    std::size_t begin = 0;
    for (const auto& [color, end] : lines) {
        drawPolyline(renderer, thick_, line_.data() + begin, static_cast<int>(end - begin),
                     lineWidth, SDL_Color{color.r, color.g, color.b, 255});
        begin = end;
    }
    font.draw(text_);
}

}  // namespace psb::app
