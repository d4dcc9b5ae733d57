#pragma once
// The text panels shown over the world: the HUD (top-left), the help (below it), the profile
// (top-right), short messages (bottom-left) and the selected particle's inspector
// (bottom-right): their lines, wrapped to the room they have, and the boxes those lines need.
// The drawing layer draws them (render/overlay_drawing.hpp).

#include <string>
#include <vector>

#include "view/pixel_rect.hpp"
#include "view/screen_layout.hpp"
#include "view/text_measure.hpp"

namespace psb::app {

struct Overlays {
    std::vector<std::string> hud;
    /// While a video records, the HUD it holds: the readings without the key hints (HudData::
    /// forVideo); `hud`, the one at the screen's, is drawn over it after the frame is taken.
    std::vector<std::string> hudRecorded;
    std::vector<std::string> help;  ///< the page of the help shown
    PixelPoint helpAt{0, 0};        ///< where the help's box goes (helpRoom)
    std::vector<std::string> profile;
    std::vector<std::string> messages;
    std::vector<std::string> inspector;  ///< empty: nothing selected
    bool showHelp = false;
    bool showProfile = false;
    /// The messages speak to the one at the screen (a file written, a recording started), not
    /// to a video's audience: while a video records they (and the HUD's hints: hudRecorded)
    /// are drawn after the frame is taken.
    bool messagesAfterCapture = false;
};

/// Lines of messages the band below the box holds.
inline constexpr std::size_t kMessageLines = 3;

/// `lines` broken at spaces so that each fits `maxWidth` pixels of `font` with its box's
/// padding (a word longer than that stays whole); continuation lines are indented by two
/// spaces. A message cut at the window's edge would hide its reason.
[[nodiscard]] std::vector<std::string> wrapLines(const TextMeasure& font,
                                                 const std::vector<std::string>& lines,
                                                 int maxWidth);

/// The message band's lines: the newest `messages` that fit `maxLines` lines whole, each
/// wrapped as wrapLines wraps it to `maxWidth`; older ones are dropped whole, never their first
/// lines (a long message lost its head: "…mp4: 3.8 s" without "Saved video"). A newest message
/// longer than the band drops its asides in brackets, the last first, until it fits whole (at
/// 200 % "Saved video PATH: 3.4 s, 84 frames, 980x1000 (25 frames a second of 60: the window
/// drew no faster)" was cut mid-word); one that is still too long keeps its first lines, the
/// last cut at a space and ending in "…" (the log has it all).
[[nodiscard]] std::vector<std::string> messageLines(const TextMeasure& font,
                                                    const std::vector<std::string>& messages,
                                                    int maxWidth, std::size_t maxLines);

/// The HUD's lines ("a | b | c") broken between their " | " parts where they do not fit
/// `maxWidth`, each continuation indented by two spaces; a part too wide alone is broken at
/// spaces as wrapLines does. A narrow window shows every reading, not the first half of each.
[[nodiscard]] std::vector<std::string> wrapHudLines(const TextMeasure& font,
                                                    const std::vector<std::string>& lines,
                                                    int maxWidth);

/// Whether the HUD is narrow in a window that leaves it `room` pixels right of the control panel
/// (HudData::narrow): the full readings' second line would not fit on one line in `font`.
[[nodiscard]] bool hudIsNarrow(const TextMeasure& font, int room);

/// The box (pixels) that `lines` need in `font`, padding included: what a LayoutRequest asks.
[[nodiscard]] PixelPoint textBoxSize(const TextMeasure& font,
                                     const std::vector<std::string>& lines);

/// The room (pixels, padding included) the help has in a window `width` × `height`: all of it
/// (the control panel is not drawn while the help is open; the HUD and the other panels are
/// covered).
[[nodiscard]] PixelRect helpRoom(int width, int height);

/// Where each of the help's `lines` is drawn in `font` from `at` (the help's box's corner), as
/// drawOverlays draws a panel's lines, pixels: what the recording mark keeps off.
[[nodiscard]] std::vector<PixelRect> helpLineRects(const TextMeasure& font,
                                                   const std::vector<std::string>& lines,
                                                   PixelPoint at);

/// The help's `lines` (a title, a blank line, one line per control) in pages that fit `room`
/// (each line wrapped to its width, a control never split between pages); each page starts
/// with the title, saying "page k of n" and what H does when there is more than one.
[[nodiscard]] std::vector<std::vector<std::string>> helpPages(const TextMeasure& font,
                                                              const std::vector<std::string>& lines,
                                                              PixelPoint room);

}  // namespace psb::app
