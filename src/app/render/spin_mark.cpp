#include "render/spin_mark.hpp"

#include <algorithm>
#include <cmath>

namespace psb::app {

SDL_Color spinMarkColor(const Color& disc) {
    // Rec. 601 luma, 0..255: above the middle the disc reads as light.
    const double luma = 0.299 * disc.r + 0.587 * disc.g + 0.114 * disc.b;
    const auto mix = [&](std::uint8_t c) {
        const double v = luma > 110.0 ? c / 3.0 : c + (255.0 - c) * (2.0 / 3.0);
        return static_cast<Uint8>(std::lround(v));
    };
    return {mix(disc.r), mix(disc.g), mix(disc.b), 255};
}

void addSpinMark(GeometryBatch& discs, float x, float y, float r, double angle, const Color& disc) {
    // The quarter between the disc's turned +x and +y axes: the square [0, r]² of the turned
    // frame over the same quarter of the circle texture, whose alpha cuts the rim's arc.
    const float ux = static_cast<float>(std::cos(angle)), uy = static_cast<float>(std::sin(angle));
    const SDL_FPoint centre{x, y};
    const SDL_FPoint alongX{x + r * ux, y + r * uy};
    const SDL_FPoint corner{x + r * (ux - uy), y + r * (uy + ux)};
    const SDL_FPoint alongY{x - r * uy, y + r * ux};
    discs.texturedPolygon4(centre, alongX, corner, alongY, spinMarkColor(disc), {0.5f, 0.5f},
                           {1.f, 0.5f}, {1.f, 1.f}, {0.5f, 1.f});
}

}  // namespace psb::app
