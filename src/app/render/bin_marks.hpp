#pragma once
// The bins a scene counts, marked on the board itself: a Galton board has more channels than
// bins (the outer ones catch balls knocked wide), and the chart beside it counts only the bins.
// Their edges are drawn in the bars' orange from the bins' top line down to the floor, the top
// line across them, and each bin's number (the chart's x axis) just under it.

#include <particle_sandbox/bins.hpp>

#include <SDL.h>

#include "render/geometry_batch.hpp"
#include "session/camera.hpp"
#include "view/palette.hpp"

namespace psb::app {

class Font;

class BinMarks {
  public:
    /// Draws the marks of `bins` on a board whose floor is at y = `floor` metres.
    void draw(SDL_Renderer* renderer, const Font& font, const Camera& camera, const Bins& bins,
              double floor, const Palette& colours = palette(Theme::Dark));

  private:
    GeometryBatch text_;
};

}  // namespace psb::app
