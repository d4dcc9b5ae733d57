#include "render/analysis_overlays.hpp"

#include <algorithm>

#include "render/polyline.hpp"
#include "render/sdl_color.hpp"
#include "render/text.hpp"
#include "view/chart_text.hpp"

namespace psb::app {

void AnalysisOverlays::draw(SDL_Renderer* renderer, const Font& font, const World& world,
                            const ObservablesSample& now, const Camera& camera,
                            const TimeSeries& series, double rateWindow, const ViewOptions& view,
                            const PanelLayout& layout, const std::optional<BinHistogram>& bins) {
    const Palette& colours = palette(view.theme);
    if (view.momentum) {
        momentum_.draw(renderer, font, world, now, camera, series, view.arrowSeconds, layout.legend,
                       colours, view.axes(world.def()));
    }
    if (view.plots && layout.plots.w > 0) {
        double mass = 0.0;
        for (const double m : world.particles().mass)
            mass += m;
        // Side by side in a band under the box, each column the next plots.
        // The plots that fit (plotsChosen): the momentum's first.
        const std::vector<int> chosen = plotsChosen(plotsShown(layout));
        const auto count = static_cast<int>(chosen.size());
        for (int k = 0; k < layout.plotColumns && k * layout.plotRows < count; ++k) {
            const auto from = chosen.begin() + k * layout.plotRows;
            const std::vector<int> which(
                from, from + std::min(layout.plotRows, count - k * layout.plotRows));
            plots_.draw(renderer, font, series, plotColumn(layout, k), layout.plotRowHeight, mass,
                        rateWindow, colours, view.yUp, chartLineWidth(view.uiScaleInUse()), which);
        }
        if (layout.plotsNote > 0) {
            // Under the rows, in the panel's frame: which plots are left out.
            const PixelRect& p = layout.plots;
            note_.clear();
            font.layout(plotsLeftOutNote(plotsShown(layout)), static_cast<float>(p.x + kChartPad),
                        static_cast<float>(p.y + p.h - layout.plotsNote), sdlColor(colours.text),
                        note_);
            font.draw(note_);
        }
    }
    if (view.speeds && layout.speeds.w > 0) {
        speeds_.draw(renderer, font, world.particles(), layout.speeds, colours,
                     chartLineWidth(view.uiScaleInUse()));
    }
    if (bins && layout.bins.w > 0) {
        bins_.draw(renderer, font, *bins, layout.bins, colours,
                   chartLineWidth(view.uiScaleInUse()));
    }
}

}  // namespace psb::app
