#include "render/overlay_drawing.hpp"

#include <algorithm>

#include "render/geometry_batch.hpp"
#include "render/sdl_color.hpp"

namespace psb::app {

namespace {

/// Text panels batched: every box one draw call, every line of text one more.
class PanelBatch {
  public:
    PanelBatch(const Font& font, const Palette& colours) : font_(font), colours_(colours) {}

    void add(const std::vector<std::string>& ls, const PixelRect& box) {
        if (box.w <= 0 || ls.empty()) return;
        // Dark enough that arrows and discs under a panel do not break up its text.
        boxes_.quad(static_cast<float>(box.x), static_cast<float>(box.y),
                    static_cast<float>(box.x + box.w), static_cast<float>(box.y + box.h),
                    sdlColor(colours_.panel));
        const float lh = static_cast<float>(font_.lineHeight());
        for (std::size_t k = 0; k < ls.size(); ++k) {
            font_.layout(ls[k], static_cast<float>(box.x + 4),
                         static_cast<float>(box.y + 2) + lh * static_cast<float>(k),
                         sdlColor(colours_.text), text_);
        }
    }
    void draw(SDL_Renderer* renderer) {
        boxes_.draw(renderer, nullptr);
        font_.draw(text_);
        boxes_.clear();
        text_.clear();
    }

  private:
    const Font& font_;
    const Palette& colours_;
    GeometryBatch boxes_, text_;
};

/// The help (H): over the whole window, opaque, every panel, chart and legend under it hidden
/// (its box was as wide as its lines, and the charts and legend showed in a strip at its
/// right), its text from `o.helpAt`.
void drawHelp(SDL_Renderer* renderer, const Font& font, const Overlays& o, const Palette& colours) {
    int w = 0, h = 0;
    if (SDL_GetRendererOutputSize(renderer, &w, &h) != 0) return;
    const SDL_Color bg = sdlColor(colours.panel);
    SDL_SetRenderDrawBlendMode(renderer, SDL_BLENDMODE_NONE);
    SDL_SetRenderDrawColor(renderer, bg.r, bg.g, bg.b, 255);
    const SDL_Rect all{0, 0, w, h};
    SDL_RenderFillRect(renderer, &all);
    PanelBatch panels(font, colours);
    const PixelPoint size = textBoxSize(font, o.help);
    panels.add(o.help, PixelRect{o.helpAt.x, o.helpAt.y, size.x, size.y});
    panels.draw(renderer);
}

}  // namespace

void drawOverlays(SDL_Renderer* renderer, const Font& font, const Overlays& o,
                  const PanelLayout& layout, const Palette& colours) {
    PanelBatch panels(font, colours);
    // The HUD's box fits its lines (the layout may keep it more room: frame_view.cpp). While a
    // video records, the frame holds the readings only; the hints come after it is taken.
    const std::vector<std::string>& hud = o.messagesAfterCapture ? o.hudRecorded : o.hud;
    const PixelPoint hudSize = textBoxSize(font, hud);
    panels.add(hud, PixelRect{layout.hud.x, layout.hud.y, hudSize.x, hudSize.y});
    if (o.showProfile) panels.add(o.profile, layout.profile);
    if (!o.messagesAfterCapture) panels.add(o.messages, layout.messages);
    panels.add(o.inspector, layout.inspector);
    panels.draw(renderer);
    // The help is asked for and read, then closed: it covers the other panels meanwhile,
    // their text included (drawn after them, opaque: at 245 the HUD's lines showed through
    // its first ones). While a video records it is drawn once the frame is taken: a video
    // holds no key hints.
    if (o.showHelp && !o.messagesAfterCapture) drawHelp(renderer, font, o, colours);
}

void drawMessages(SDL_Renderer* renderer, const Font& font, const Overlays& o,
                  const PanelLayout& layout, const Palette& colours) {
    if (o.showHelp) {  // the help covers them; not in the video
        drawHelp(renderer, font, o, colours);
        return;
    }
    PanelBatch panels(font, colours);
    // The screen's HUD over the video's, opaque: its lines are the video's and more, and its
    // box at least as large as the video's (whose first line, with a past frame's time, is
    // longer: its end showed beside the screen's HUD).
    const PixelPoint screen = textBoxSize(font, o.hud), video = textBoxSize(font, o.hudRecorded);
    const PixelPoint hudSize{std::max(screen.x, video.x), std::max(screen.y, video.y)};
    panels.add(o.hud, PixelRect{layout.hud.x, layout.hud.y, hudSize.x, hudSize.y});
    panels.add(o.messages, layout.messages);
    panels.draw(renderer);
}

}  // namespace psb::app
