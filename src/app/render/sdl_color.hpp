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
/// `c` as text on the palette's chart panels (`panel`), dark or light enough to read
/// (readableText).
[[nodiscard]] inline SDL_Color sdlTextColor(SDL_Color c, Rgba panel) {
    return sdlColor(readableText(Rgba{c.r, c.g, c.b, c.a}, panel));
}
inline void setDrawColor(SDL_Renderer* renderer, Rgba c) {
    SDL_SetRenderDrawColor(renderer, c.r, c.g, c.b, c.a);
}

}  // namespace psb::app
