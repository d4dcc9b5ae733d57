#pragma once
// The analysis overlays drawn over the world (see docs/app-instruments.md, "Seeing the physics"):
// the momentum view (V), the plots panel (K), the speed histogram (D) and a scene's bins, each
// drawn only when its ViewOptions toggle is on, in the boxes of a PanelLayout. The path traces (L)
// are drawn by the Renderer, under the discs.

#include <optional>

#include <SDL.h>

#include <particle_sandbox/time_series.hpp>
#include <particle_sandbox/world.hpp>

#include "render/bin_chart.hpp"
#include "render/geometry_batch.hpp"
#include "render/momentum_drawing.hpp"
#include "render/plot_chart.hpp"
#include "render/renderer.hpp"
#include "render/speed_chart.hpp"
#include "session/camera.hpp"
#include "view/screen_layout.hpp"

namespace psb::app {

class Font;

class AnalysisOverlays {
  public:
    /// Draws what `view` switches on, the panels in `layout`'s boxes (a panel whose box is
    /// empty is not drawn); `now` is the world's current sample, `series` feeds the plots and
    /// the centre of mass path, its collision rate counted over `rateWindow` s; `bins` is the
    /// scene's bins panel, when it is shown.
    void draw(SDL_Renderer* renderer, const Font& font, const World& world,
              const ObservablesSample& now, const Camera& camera, const TimeSeries& series,
              double rateWindow, const ViewOptions& view, const PanelLayout& layout,
              const std::optional<BinHistogram>& bins = std::nullopt);

  private:
    MomentumDrawing momentum_;
    PlotChart plots_;
    SpeedChart speeds_;
    BinChart bins_;
    GeometryBatch note_;  ///< the line naming the plots left out
};

}  // namespace psb::app
