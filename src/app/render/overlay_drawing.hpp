#pragma once
// Drawing the text panels of a frame (view/overlays.hpp): each a translucent box with lines of
// text; all boxes are one draw call and all text one more.

#include <SDL.h>

#include "render/text.hpp"
#include "view/overlays.hpp"
#include "view/palette.hpp"
#include "view/screen_layout.hpp"

namespace psb::app {

/// Draws the panels of `o` onto `renderer` in the boxes of `layout` (a box with w == 0 is not
/// drawn), the messages unless `o.messagesAfterCapture` (a video records: then the HUD drawn is
/// the video's, `o.hudRecorded`). The help, when switched on, is drawn over the whole window,
/// opaque; while a video records it is left to drawMessages (no key hints in a video).
void drawOverlays(SDL_Renderer* renderer, const Font& font, const Overlays& o,
                  const PanelLayout& layout, const Palette& colours = palette(Theme::Dark));

/// Draws what drawOverlays leaves out of a video while it records: the screen's HUD (with its
/// key hints, opaque over the video's) and the messages' panel; with the help on, the help
/// alone, over the whole window.
void drawMessages(SDL_Renderer* renderer, const Font& font, const Overlays& o,
                  const PanelLayout& layout, const Palette& colours = palette(Theme::Dark));

}  // namespace psb::app
