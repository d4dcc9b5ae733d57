#pragma once
// A chart's line (a plot, a fitted curve) as thick as the UI's scale: 1 pixel at 100 %, 2 at
// 200 %, so that on a projector the curves keep the weight of the text around them.

#include <SDL.h>

#include "render/geometry_batch.hpp"

namespace psb::app {

/// Line width in pixels for a UI at `uiScale` (ViewOptions::uiScale): the scale rounded, at
/// least 1.
[[nodiscard]] float chartLineWidth(double uiScale);

/// The polyline through `points[0..n)` in `color`, `width` pixels thick: SDL's one-pixel lines
/// below 1.5 pixels, else a quad along each segment and a square at each joint (no gaps at the
/// bends), through `scratch` (cleared first).
void drawPolyline(SDL_Renderer* renderer, GeometryBatch& scratch, const SDL_FPoint* points, int n,
                  float width, SDL_Color color);

}  // namespace psb::app
