#pragma once
// The text panels drawn over the world: the HUD (top-left), the help (below it), the profile
// (top-right), short messages (bottom-left) and the selected particle's inspector
// (bottom-right). Each is a translucent box with lines of text; all boxes are one draw call and
// all text one more.

#include <string>
#include <vector>

#include <SDL.h>

#include "panel_layout.hpp"
#include "text.hpp"

namespace psb::app {

struct Overlays {
    std::vector<std::string> hud;
    std::vector<std::string> help;  ///< the page of the help shown
    SDL_Point helpAt{0, 0};         ///< where the help's box goes (helpRoom)
    std::vector<std::string> profile;
    std::vector<std::string> messages;
    std::vector<std::string> inspector;  ///< empty: nothing selected
    bool showHelp = false;
    bool showProfile = false;
};

/// Lines of messages the band below the box holds.
inline constexpr std::size_t kMessageLines = 3;

/// `lines` broken at spaces so that each fits `maxWidth` pixels of `font` with its box's
/// padding (a word longer than that stays whole); continuation lines are indented by two
/// spaces. A message cut at the window's edge would hide its reason.
[[nodiscard]] std::vector<std::string> wrapLines(const Font& font,
                                                 const std::vector<std::string>& lines,
                                                 int maxWidth);

/// The HUD's lines ("a | b | c") broken between their " | " parts where they do not fit
/// `maxWidth`, each continuation indented by two spaces; a part too wide alone is broken at
/// spaces as wrapLines does. A narrow window shows every reading, not the first half of each.
[[nodiscard]] std::vector<std::string> wrapHudLines(const Font& font,
                                                    const std::vector<std::string>& lines,
                                                    int maxWidth);

/// The box (pixels) that `lines` need in `font`, padding included: what a LayoutRequest asks.
[[nodiscard]] SDL_Point textBoxSize(const Font& font, const std::vector<std::string>& lines);

/// The room (pixels, padding included) the help has in a window `width` × `height`: all of it
/// (the control panel is not drawn while the help is open; the HUD and the other panels are
/// covered).
[[nodiscard]] SDL_Rect helpRoom(int width, int height);

/// The help's `lines` (a title, a blank line, one line per control) in pages that fit `room`
/// (each line wrapped to its width, a control never split between pages); each page starts
/// with the title, saying "page k of n" and what H does when there is more than one.
[[nodiscard]] std::vector<std::vector<std::string>> helpPages(const Font& font,
                                                              const std::vector<std::string>& lines,
                                                              SDL_Point room);

/// Draws the panels of `o` onto `renderer` in the boxes of `layout` (a box with w == 0 is not
/// drawn). The help is drawn over everything when switched on.
void drawOverlays(SDL_Renderer* renderer, const Font& font, const Overlays& o,
                  const PanelLayout& layout);

}  // namespace psb::app
