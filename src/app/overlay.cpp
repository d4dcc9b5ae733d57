#include "overlay.hpp"

#include <algorithm>

#include "geometry_batch.hpp"

namespace psb::app {

void drawOverlays(SDL_Renderer* renderer, const Font& font, const Overlays& o, int width,
                  int height) {
    GeometryBatch boxes, text;
    const float lh = static_cast<float>(font.lineHeight());
    const auto widthOf = [&](const std::vector<std::string>& ls) {
        int w = 0;
        for (const auto& l : ls)
            w = std::max(w, font.measure(l));
        return static_cast<float>(w);
    };
    const auto panel = [&](const std::vector<std::string>& ls, float x, float y,
                           Uint8 alpha = 150) {
        boxes.quad(x - 4, y - 2, x + widthOf(ls) + 4, y + lh * static_cast<float>(ls.size()) + 2,
                   SDL_Color{0, 0, 0, alpha});
        for (std::size_t k = 0; k < ls.size(); ++k) {
            font.layout(ls[k], x, y + lh * static_cast<float>(k), SDL_Color{230, 230, 230, 255},
                        text);
        }
    };
    panel(o.hud, 8, 6);
    if (o.showHelp) panel(o.help, 40, 40 + lh * static_cast<float>(o.hud.size()), 225);
    if (o.showProfile && !o.profile.empty()) {
        const float w = widthOf(o.profile);
        panel(o.profile, std::max(8.0f, static_cast<float>(width) - 8 - w), 6, 200);
    }
    if (!o.messages.empty()) {
        panel(o.messages, 8,
              static_cast<float>(height) - 8 - lh * static_cast<float>(o.messages.size()));
    }
    if (!o.inspector.empty()) {
        const float w = widthOf(o.inspector);
        panel(o.inspector, std::max(8.0f, static_cast<float>(width) - 8 - w),
              static_cast<float>(height) - 8 - lh * static_cast<float>(o.inspector.size()), 200);
    }
    boxes.draw(renderer, nullptr);
    font.draw(text);
}

}  // namespace psb::app
