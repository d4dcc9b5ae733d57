#pragma once
// The speed distribution's chart (the D key): the histogram of view/speed_histogram.hpp as bars
// against the Maxwell–Boltzmann curve it expects.

#include <cstddef>
#include <vector>

#include <SDL.h>

#include <particle_sandbox/particle_arrays.hpp>

#include "render/geometry_batch.hpp"
#include "view/palette.hpp"
#include "view/pixel_rect.hpp"
#include "view/speed_histogram.hpp"

namespace psb::app {

class Font;

/// Histogram colours, for the tests to look for.

class SpeedChart {
  public:
    static constexpr std::size_t kBins = 32;

    /// Draws the histogram of `p` in `box` (pixels, see PanelLayout).
    void draw(SDL_Renderer* renderer, const Font& font, const ParticleArrays& p,
              const PixelRect& box, const Palette& colours = palette(Theme::Dark),
              float lineWidth = 1.f);

  private:
    GeometryBatch boxes_, text_, thick_;  // thick_: the curves wider than a pixel
    std::vector<SDL_FPoint> curve_;
};

}  // namespace psb::app
