#include "render/overlay_drawing.hpp"

#include "render/geometry_batch.hpp"
#include "render/sdl_color.hpp"

namespace psb::app {

void drawOverlays(SDL_Renderer* renderer, const Font& font, const Overlays& o,
                  const PanelLayout& layout, const Palette& colours) {
    GeometryBatch boxes, text;
    const float lh = static_cast<float>(font.lineHeight());
    // Dark enough that arrows and discs under a panel do not break up its text.
    const auto panel = [&](const std::vector<std::string>& ls, const PixelRect& box,
                           Uint8 alpha = 215) {
        if (box.w <= 0 || ls.empty()) return;
        boxes.quad(static_cast<float>(box.x), static_cast<float>(box.y),
                   static_cast<float>(box.x + box.w), static_cast<float>(box.y + box.h),
                   sdlColor(colours.panel, alpha));
        for (std::size_t k = 0; k < ls.size(); ++k) {
            font.layout(ls[k], static_cast<float>(box.x + 4),
                        static_cast<float>(box.y + 2) + lh * static_cast<float>(k),
                        sdlColor(colours.text), text);
        }
    };
    panel(o.hud, layout.hud);
    if (o.showProfile) panel(o.profile, layout.profile, 200);
    panel(o.messages, layout.messages);
    panel(o.inspector, layout.inspector, 200);
    boxes.draw(renderer, nullptr);
    font.draw(text);
    if (o.showHelp) {
        // The help is asked for and read, then closed: it covers the other panels meanwhile,
        // their text included (drawn after them, opaque).
        boxes.clear();
        text.clear();
        const PixelPoint size = textBoxSize(font, o.help);
        panel(o.help, PixelRect{o.helpAt.x, o.helpAt.y, size.x, size.y}, 245);
        boxes.draw(renderer, nullptr);
        font.draw(text);
    }
}

}  // namespace psb::app
