#include "render/selection_outline.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "render/sdl_color.hpp"

namespace psb::app {

void drawSelectionOutline(SDL_Renderer* renderer, const Camera& camera, const Particle& p,
                          const Palette& colours) {
    constexpr int kSegments = 64;
    const Vec2 c = camera.worldToScreen(p.position);
    const double rim = camera.toScreen(p.radius);
    SDL_SetRenderDrawBlendMode(renderer, SDL_BLENDMODE_NONE);
    setDrawColor(renderer, colours.highlight);
    for (const double gap : {3.0, 4.0}) {
        const double r = std::max(rim + gap, 6.0 + gap - 3.0);
        std::array<SDL_FPoint, kSegments + 1> ring{};
        for (int k = 0; k <= kSegments; ++k) {
            const double a = 2.0 * std::numbers::pi * k / kSegments;
            ring[static_cast<std::size_t>(k)] = {static_cast<float>(c.x() + r * std::cos(a)),
                                                 static_cast<float>(c.y() + r * std::sin(a))};
        }
        SDL_RenderDrawLinesF(renderer, ring.data(), kSegments + 1);
    }
}

}  // namespace psb::app
