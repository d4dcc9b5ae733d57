#include "analysis_overlays.hpp"

#include <algorithm>

namespace psb::app {

void AnalysisOverlays::draw(SDL_Renderer* renderer, const Font& font, const World& world,
                            const Camera& camera, const TimeSeries& series,
                            const ViewOptions& view) {
    if (view.momentum) momentum_.draw(renderer, font, world, camera, series, view.arrowSeconds);
    const float w = static_cast<float>(camera.viewportWidth());
    const float h = static_cast<float>(camera.viewportHeight());
    float bottom = h - 8;
    if (view.plots) {
        bottom -= static_cast<float>(PlotPanel::height());
        double mass = 0.0;
        for (const double m : world.particles().mass)
            mass += m;
        plots_.draw(renderer, font, series, w - PlotPanel::kWidth - 8, bottom, mass);
        bottom -= 6;
    }
    if (view.speeds) {
        bottom = std::max(8.0f, bottom - SpeedHistogramPanel::kHeight);
        speeds_.draw(renderer, font, world.particles(), w - SpeedHistogramPanel::kWidth - 8,
                     bottom);
    }
}

}  // namespace psb::app
