#include "render/speed_chart.hpp"

#include "render/polyline.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "render/plot_chart.hpp"
#include "render/sdl_color.hpp"
#include "render/text.hpp"
#include "view/chart_text.hpp"

namespace psb::app {

void SpeedChart::draw(SDL_Renderer* renderer, const Font& font, const ParticleArrays& p,
                      const PixelRect& box, const Palette& colours, float lineWidth) {
    const ChartFrame f = beginChart(font, box, boxes_, text_, colours);
    const float x = f.x, y = f.y, boxW = f.w, height = f.h, lh = f.lineHeight;
    curve_.clear();
    const SpeedHistogram h = speedHistogram(p, kBins);
    const SDL_Color grey = sdlColor(colours.tickText), axis = sdlColor(colours.axis);
    const SDL_Color bar = sdlColor(colours.histogramBar), curve = sdlColor(colours.theoryCurve);
    char buf[128];
    std::snprintf(buf, sizeof buf, "bars: speeds of %zu particles%s", h.particles,
                  h.overflow > 0 ? (", " + std::to_string(h.overflow) + " off scale").c_str() : "");
    // The 2-D Maxwell-Boltzmann distribution at kT = the mean kinetic energy per particle.
    // The legend wraps within the frame (at 200 % its second line ran past the right edge).
    const std::vector<LegendLine> legend =
        fitLegend(font, {buf, "line: ideal gas (Maxwell-Boltzmann)"}, box.w);
    const SDL_Color legendColour[2] = {sdlTextColor(bar, colours.panel),
                                       sdlTextColor(curve, colours.panel)};
    for (std::size_t k = 0; k < legend.size(); ++k) {
        font.layout(legend[k].text, x + kChartPad, y + 4 + lh * static_cast<float>(k),
                    legendColour[legend[k].entry], text_);
    }
    // The plot under the legend, with half a line for the top tick's label.
    const float right = x + boxW - 10;
    const float top = y + 6 + (static_cast<float>(legend.size()) + 0.5f) * lh,
                bottom = y + height - 2 * lh - 6;
    // Densities, s/m: a bin's count / (N · width), so bars and curve share one axis.
    const double n = static_cast<double>(std::max<std::size_t>(h.particles, 1));
    const double width = h.binWidth();
    double top_density = 0.0;
    for (const std::size_t c : h.counts)
        top_density = std::max(top_density, static_cast<double>(c) / (n * width));
    constexpr int kCurvePoints = 96;
    for (int k = 0; k <= kCurvePoints; ++k)
        top_density = std::max(top_density, h.expectedDensity(h.vmax * k / kCurvePoints));
    const PlotRange r = plotRange(0.0, top_density > 0.0 ? top_density : 1.0, 1e-300);
    // The y axis as far in as its widest tick label needs (62 pixels at 100 %).
    const int ticks = yTickCount(bottom - top, font.lineHeight());
    const float left = x + static_cast<float>(yAxisRoom(font, yTickLabels(0.0, r.hi, ticks), 62));
    const auto sy = [&](double d) {
        return bottom - static_cast<float>(d / r.hi) * (bottom - top);
    };
    const auto sx = [&](double v) {
        return left + static_cast<float>(v / h.vmax) * (right - left);
    };
    for (std::size_t b = 0; b < h.counts.size(); ++b) {
        if (h.counts[b] == 0) continue;
        const double d = static_cast<double>(h.counts[b]) / (n * width);
        boxes_.quad(sx(static_cast<double>(b) * width) + 1, sy(d),
                    sx(static_cast<double>(b + 1) * width), bottom, bar);
    }
    for (int k = 0; k <= kCurvePoints; ++k) {
        const double v = h.vmax * k / kCurvePoints;
        curve_.push_back({sx(v), sy(h.expectedDensity(v))});
    }

    boxes_.quad(left - 1, top, left, bottom, axis);
    boxes_.quad(left - 1, bottom, right, bottom + 1, axis);
    layoutYTicks(font, 0.0, r.hi, left, sy, boxes_, text_, colours, ticks);
    const double xstep = niceStep(0.0, h.vmax, 5);
    for (const double t : niceTicks(0.0, h.vmax, 5)) {
        const float tx = sx(t);
        boxes_.quad(tx, bottom + 1, tx + 1, bottom + 4, axis);
        const std::string label = tickLabel(t, xstep);
        // Centred on its tick, but the last one (at the axis's right end) kept inside the
        // frame, as the plots' time labels are: it reached the window's edge.
        font.layout(label, timeLabelLeft(tx, static_cast<float>(font.measure(label)), x + boxW),
                    bottom + 4, grey, text_);
    }
    font.layout("speed (m/s)", right - static_cast<float>(font.measure("speed (m/s)")),
                bottom + 4 + lh, grey, text_);
    font.layout("density (s/m)", x + 8, bottom + 4 + lh, grey, text_);

    boxes_.draw(renderer, nullptr);
    if (h.particles > 0) {
        drawPolyline(renderer, thick_, curve_.data(), static_cast<int>(curve_.size()), lineWidth,
                     SDL_Color{curve.r, curve.g, curve.b, 255});
    }
    font.draw(text_);
}

}  // namespace psb::app
