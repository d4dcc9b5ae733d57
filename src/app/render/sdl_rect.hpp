#pragma once
// The view's pixel rectangles as SDL's, where the drawing layer hands one to SDL.

#include <SDL.h>

#include "view/pixel_rect.hpp"

namespace psb::app {

[[nodiscard]] inline SDL_Rect sdlRect(const PixelRect& r) {
    return {r.x, r.y, r.w, r.h};
}

}  // namespace psb::app
