#pragma once
// Drawing the momentum view (the V key, view/momentum_view.hpp): an arrow per particle, the
// centre of mass with its recent path, the total momentum's arrow and the legend.

#include <vector>

#include <SDL.h>

#include <particle_sandbox/time_series.hpp>
#include <particle_sandbox/world.hpp>

#include "render/geometry_batch.hpp"
#include "session/camera.hpp"
#include "view/momentum_view.hpp"
#include "view/palette.hpp"
#include "view/pixel_rect.hpp"

namespace psb::app {

class Font;

/// Colours of the momentum view, for the tests to look for.

class MomentumDrawing {
  public:
    /// Draws the per-particle arrows, the centre of mass path from `series` (its samples'
    /// centreOfMass, oldest first), the marker, the total arrow, and the legend in `legend`
    /// (pixels; not drawn when w == 0).
    void draw(SDL_Renderer* renderer, const Font& font, const World& world,
              const ObservablesSample& now, const Camera& camera, const TimeSeries& series,
              double arrowSeconds, const PixelRect& legend,
              const Palette& colours = palette(Theme::Dark), const Axes& axes = {});

  private:
    GeometryBatch arrows_, text_;
    std::vector<SDL_FPoint> path_;
};

}  // namespace psb::app
