#pragma once
// The selected particle on screen: an outline around its disc.

#include <SDL.h>

#include <particle_sandbox/particle.hpp>

#include "session/camera.hpp"
#include "view/palette.hpp"

namespace psb::app {

/// Rings around the disc of `p` (3 and 4 pixels outside its rim, at least 6 pixels from its
/// centre, so a particle smaller than a pixel is still marked).
void drawSelectionOutline(SDL_Renderer* renderer, const Camera& camera, const Particle& p,
                          const Palette& colours = palette(Theme::Dark));

}  // namespace psb::app
