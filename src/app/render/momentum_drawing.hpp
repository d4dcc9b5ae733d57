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
#include "view/pixel_rect.hpp"

namespace psb::app {

class Font;

/// Colours of the momentum view, for the tests to look for.
inline constexpr SDL_Color kMomentumArrowColor{255, 150, 30, 255};  ///< per particle, orange
inline constexpr SDL_Color kTotalMomentumColor{255, 255, 0, 255};   ///< Σ m v, yellow
inline constexpr SDL_Color kCentreOfMassColor{0, 230, 255, 255};    ///< marker and path, cyan

class MomentumDrawing {
  public:
    /// Draws the per-particle arrows, the centre of mass path from `series` (its samples'
    /// centreOfMass, oldest first), the marker, the total arrow, and the legend in `legend`
    /// (pixels; not drawn when w == 0).
    void draw(SDL_Renderer* renderer, const Font& font, const World& world,
              const ObservablesSample& now, const Camera& camera, const TimeSeries& series,
              double arrowSeconds, const PixelRect& legend);

  private:
    GeometryBatch arrows_, text_;
    std::vector<SDL_FPoint> path_;
};

}  // namespace psb::app
