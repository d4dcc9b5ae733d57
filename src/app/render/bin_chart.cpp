#include "render/bin_chart.hpp"

#include "render/polyline.hpp"

#include <algorithm>
#include <cmath>

#include "render/plot_chart.hpp"
#include "render/sdl_color.hpp"
#include "render/text.hpp"
#include "view/overlays.hpp"

namespace psb::app {

BinChartLayout binChartLayout(const Font& font, float x, float width, float legendBottom,
                              float boxBottom, const std::string& yTitle,
                              const std::string& xTitle) {
    const float lh = static_cast<float>(font.lineHeight());
    BinChartLayout c;
    c.left = x + 44;
    c.right = x + width - 10;
    c.yCaption = {x + 8, legendBottom + 2, static_cast<float>(font.measure(yTitle)), lh};
    // The top tick's label is centred on the top of the plot: half a line under the caption.
    c.top = c.yCaption.y + lh + lh / 2 + 2;
    c.bottom = boxBottom - 2 * lh - 6;
    const float xw = static_cast<float>(font.measure(xTitle));
    c.xCaption = {std::max(x + 8, c.right - xw), c.bottom + 3 + lh, xw, lh};
    return c;
}

void BinChart::draw(SDL_Renderer* renderer, const Font& font, const BinHistogram& h,
                    const PixelRect& box, const Palette& colours, float lineWidth) {
    const ChartFrame f = beginChart(font, box, boxes_, text_, colours);
    const float x = f.x, y = f.y, boxW = f.w, height = f.h, lh = f.lineHeight;
    curve_.clear();
    const SDL_Color grey = sdlColor(colours.tickText), axis = sdlColor(colours.axis);
    const SDL_Color bar = sdlColor(colours.binBar), dot = sdlColor(colours.theoryCurve),
                    normal = sdlColor(colours.normalCurve);
    const SDL_Color colors[] = {bar, dot, normal, grey};
    // Each legend line in its colour, wrapped to the box.
    float lineY = y + 4;
    for (std::size_t k = 0; k < h.legend.size(); ++k) {
        for (const std::string& line : wrapLines(font, {h.legend[k]}, box.w - 8)) {
            font.layout(line, x + 8, lineY,
                        sdlTextColor(colors[std::min<std::size_t>(k, 3)], colours.panel), text_);
            lineY += lh;
        }
    }
    const std::string yTitle = "balls";
    const std::string xTitle =
        h.bins.binomial ? "bin = times a ball went right" : "bin, left to right";
    const BinChartLayout chart = binChartLayout(font, x, boxW, lineY, y + height, yTitle, xTitle);
    const float left = chart.left, right = chart.right, top = chart.top, bottom = chart.bottom;
    const std::vector<std::size_t>& counts = h.now.counts.counts;
    const std::size_t bins = counts.size();
    if (bins == 0 || !chart.fits()) {
        boxes_.draw(renderer, nullptr);
        font.draw(text_);
        return;
    }
    boxes_.quad(left - 1, top, left, bottom, axis);
    boxes_.quad(left - 1, bottom, right, bottom + 1, axis);

    // One axis for bars, dots and curve: balls per bin.
    const double total = static_cast<double>(h.now.counts.counted());
    double highest = 1.0;
    for (const std::size_t c : counts)
        highest = std::max(highest, static_cast<double>(c));
    for (const double e : h.now.expected)
        highest = std::max(highest, e);
    const PlotRange r = plotRange(0.0, highest, 1.0);
    const float binW = (right - left) / static_cast<float>(bins);
    const auto sx = [&](double k) { return left + static_cast<float>(k) * binW; };
    const auto sy = [&](double v) {
        return bottom - static_cast<float>(v / r.hi) * (bottom - top);
    };
    for (std::size_t k = 0; k < bins; ++k) {
        if (counts[k] == 0) continue;
        boxes_.quad(sx(static_cast<double>(k)) + 1, sy(static_cast<double>(counts[k])),
                    sx(static_cast<double>(k + 1)) - 1, bottom, bar);
    }
    for (std::size_t k = 0; k < h.now.expected.size(); ++k) {
        const float cx = sx(static_cast<double>(k) + 0.5), cy = sy(h.now.expected[k]);
        boxes_.quad(cx - 3, cy - 3, cx + 3, cy + 3, dot);
    }
    if (h.bins.binomial && total > 0.0) {
        constexpr int kPoints = 120;
        for (int i = 0; i <= kPoints; ++i) {
            // Bin k (k successes) is centred at k + 1/2 on this axis.
            const double k = static_cast<double>(bins) * i / kPoints;
            curve_.push_back({sx(k), sy(normalCount(k - 0.5, *h.bins.binomial, total))});
        }
    }

    layoutYTicks(font, 0.0, r.hi, left, sy, boxes_, text_, colours);
    // Bin numbers under the bars, as many as fit.
    const int every = std::max(
        1, static_cast<int>(std::ceil(static_cast<float>(font.measure("000") + 4) / binW)));
    for (std::size_t k = 0; k < bins; k += static_cast<std::size_t>(every)) {
        const std::string label = std::to_string(k);
        font.layout(label, sx(static_cast<double>(k) + 0.5) - font.measure(label) / 2.0f,
                    bottom + 3, grey, text_);
    }
    font.layout(xTitle, chart.xCaption.x, chart.xCaption.y, grey, text_);
    font.layout(yTitle, chart.yCaption.x, chart.yCaption.y, grey, text_);

    boxes_.draw(renderer, nullptr);
    if (curve_.size() > 1) {
        drawPolyline(renderer, thick_, curve_.data(), static_cast<int>(curve_.size()), lineWidth,
                     SDL_Color{normal.r, normal.g, normal.b, 255});
    }
    font.draw(text_);
}

}  // namespace psb::app
