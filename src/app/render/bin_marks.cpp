#include "render/bin_marks.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "render/bin_chart.hpp"
#include "render/sdl_color.hpp"
#include "render/text.hpp"
#include "view/bin_numbers.hpp"

namespace psb::app {

void BinMarks::draw(SDL_Renderer* renderer, const Font& font, const Camera& camera,
                    const Bins& bins, double floor, const Palette& colours) {
    const SDL_Color bar = sdlColor(colours.binBar);
    if (bins.edges.size() < 2) return;
    const Vec2 topLeft = camera.worldToScreen(Vec2(bins.edges.front(), bins.top));
    const Vec2 bottomRight = camera.worldToScreen(Vec2(bins.edges.back(), floor));
    const float top = static_cast<float>(topLeft.y()), bottom = static_cast<float>(bottomRight.y());
    if (!(bottom > top)) return;
    // Two pixels wide, so that they show over the grey walls they follow.
    SDL_SetRenderDrawBlendMode(renderer, SDL_BLENDMODE_NONE);
    SDL_SetRenderDrawColor(renderer, bar.r, bar.g, bar.b, 255);
    const SDL_FRect mouth{static_cast<float>(topLeft.x()) - 1.f, top - 1.f,
                          static_cast<float>(bottomRight.x() - topLeft.x()) + 2.f, 2.f};
    SDL_RenderFillRectF(renderer, &mouth);
    for (const double edge : bins.edges) {
        const float x = static_cast<float>(camera.worldToScreen(Vec2(edge, floor)).x());
        const SDL_FRect line{x - 1.f, top, 2.f, bottom - top};
        SDL_RenderFillRectF(renderer, &line);
    }
    // Each bin's number where the view places it (the grid's distances keep off them).
    text_.clear();
    for (const BinNumber& n : binNumbers(camera, bins, floor, font)) {
        font.layout(n.text, static_cast<float>(n.at.x), static_cast<float>(n.at.y), bar, text_);
    }
    font.draw(text_);
}

}  // namespace psb::app
