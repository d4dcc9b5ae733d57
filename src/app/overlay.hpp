#pragma once
// The text panels drawn over the world: the HUD (top-left), the help (below it), the profile
// (top-right), short messages (bottom-left) and the selected particle's inspector
// (bottom-right). Each is a translucent box with lines of text; all boxes are one draw call and
// all text one more.

#include <string>
#include <vector>

#include <SDL.h>

#include "text.hpp"

namespace psb::app {

struct Overlays {
    std::vector<std::string> hud;
    std::vector<std::string> help;
    std::vector<std::string> profile;
    std::vector<std::string> messages;
    std::vector<std::string> inspector;  ///< empty: nothing selected
    bool showHelp = false;
    bool showProfile = false;
};

/// Draws the panels of `o` onto `renderer`, whose output is `width` × `height` pixels. The help
/// and the profile are drawn only when switched on.
void drawOverlays(SDL_Renderer* renderer, const Font& font, const Overlays& o, int width,
                  int height);

}  // namespace psb::app
