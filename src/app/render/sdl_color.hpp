#pragma once
// The palette's colours (view/palette.hpp) as SDL's.

#include <SDL.h>

#include "view/palette.hpp"

namespace psb::app {

[[nodiscard]] inline SDL_Color sdlColor(Rgba c) {
    return {c.r, c.g, c.b, c.a};
}
/// `c` with opacity `alpha`.
[[nodiscard]] inline SDL_Color sdlColor(Rgba c, Uint8 alpha) {
    return {c.r, c.g, c.b, alpha};
}
inline void setDrawColor(SDL_Renderer* renderer, Rgba c) {
    SDL_SetRenderDrawColor(renderer, c.r, c.g, c.b, c.a);
}

}  // namespace psb::app
