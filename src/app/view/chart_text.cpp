#include "view/chart_text.hpp"

#include <algorithm>
#include <cmath>

#include "view/overlays.hpp"

namespace psb::app {

std::vector<LegendLine> fitLegend(const TextMeasure& font, const std::vector<std::string>& entries,
                                  int width) {
    std::vector<LegendLine> out;
    // wrapLines keeps 8 pixels of a box's padding out of the width it is given.
    const int room = std::max(1, width - 2 * kChartPad + 8);
    for (std::size_t k = 0; k < entries.size(); ++k) {
        for (std::string& line : wrapLines(font, {entries[k]}, room))
            out.push_back({std::move(line), k});
    }
    return out;
}

int yAxisRoom(const TextMeasure& font, const std::vector<std::string>& labels, int least) {
    int widest = 0;
    for (const std::string& l : labels)
        widest = std::max(widest, font.measure(l));
    // The padding, the labels, and 6 pixels for the tick marks and the gap before them.
    return std::max(least, kChartPad + widest + 6);
}

PlotRowsPlace plotRowsPlace(float y, int rows, float rowHeight, float lineHeight) {
    PlotRowsPlace p;
    const float half = std::ceil(lineHeight / 2.f);
    for (int k = 0; k < rows; ++k) {
        const float rowTop = y + 6.f + static_cast<float>(k) * rowHeight;
        PlotRowPlace r;
        r.title = rowTop - 1.f;
        r.top = rowTop + lineHeight + half;
        // The bottom tick label, centred on the bottom, ends half a line below it, clear of the
        // next title (a line and 8 pixels below the bottom).
        r.bottom = rowTop + rowHeight - lineHeight - 8.f;
        p.rows.push_back(r);
    }
    if (rows > 0) {
        // The last plot stops where the time labels' line fits below its bottom tick label and
        // above the frame's bottom edge (2 pixels in).
        const float frameBottom = y + static_cast<float>(rows) * rowHeight + 8.f;
        PlotRowPlace& last = p.rows.back();
        last.bottom = std::min(last.bottom, frameBottom - 2.f - lineHeight - half - 2.f);
        p.timeLabels = last.bottom + half + 2.f;
    }
    return p;
}

int yTickCount(double pixels, int lineHeight) {
    if (lineHeight <= 0) return 4;
    // n ticks are n - 1 steps apart; each label wants its line and a little air (the top and
    // bottom labels stand half a line past the axis's ends, where plotRowsPlace keeps room).
    const int steps = static_cast<int>(std::floor(pixels / (1.15 * lineHeight)));
    return std::clamp(steps + 1, 1, 5);
}

}  // namespace psb::app
