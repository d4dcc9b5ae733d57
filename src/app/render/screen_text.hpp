#pragma once
// The text a frame shows, as plain text: written beside each screenshot (F12, NAME.txt next to
// NAME.png), so that a report, a screen reader or a test can read what was on screen without
// reading pixels. Also the rectangles the panels and the box took, in window pixels.

#include <string>

#include "render/renderer.hpp"
#include "view/frame_view.hpp"

namespace psb::app {

/// Sections "HUD:", "Messages:", "Inspector:", "Profile:", "Help:", "Bins:" (the bins panel's
/// legend, then its counts and the binomial's expected counts, rounded) (the shown ones, a line per
/// line of text, indented by two spaces), then "Labels: N drawn, M left out", then "Layout:"
/// with a line "NAME x y w h" per panel drawn and for the box ("box").
[[nodiscard]] std::string screenText(const FrameView& frame, const DrawStats& drawn);

}  // namespace psb::app
