#pragma once
// Where the particles' labels (S) go: a pure function from the discs on screen and the sizes of
// their labels to rectangles, so that the rule is tested without drawing
// (render/renderer.cpp draws what it says). Each label, in the order asked, takes the first
// place that is free, trying in turn:
//
//   1. beside its disc (above, below, right, left, then the four corners; each slid along that
//      side to stay in the window), inside the box with a disc in it;
//   2. the same, anywhere;
//   3. further out, on rings of places around its disc, joined to its disc by a leader line (a
//      small box has no room beside its balls; the window round it has);
//
// and is left out when none is free. Free: inside the window, clear of every disc, of the labels
// already placed and of what the room keeps out (the panels, pegs, the ruler's reading), and
// across no wall (the box's outline, a wall at any angle). A label never covers a ball nor
// crosses a wall: in a crowd (the funnel's 400 balls) most are left out, and the HUD says how
// many. Where that leaves a label out and the labels have a short form (LabelAsk::shortSize),
// every label takes its short form if that leaves fewer out (a small box at 200 %: two lines
// beside each ball rather than none).

#include <cstddef>
#include <vector>

#include "view/pixel_rect.hpp"

namespace psb::app {

/// A wall at any angle on screen, pixels: from (ax, ay) to (bx, by), `halfWidth` either side
/// of that line, its ends rounded.
struct ScreenWall {
    double ax = 0.0, ay = 0.0, bx = 0.0, by = 0.0;
    double halfWidth = 0.0;
};

/// Whether `r` touches `wall`.
[[nodiscard]] bool crosses(const PixelRect& r, const ScreenWall& wall);

/// Where labels may go: inside `window`, across neither the walled box's outline `box` (w == 0:
/// no walls) nor any of `walls`, over none of `keepOut`.
struct LabelRoom {
    PixelRect window;
    PixelRect box;
    std::vector<ScreenWall> walls;
    std::vector<PixelRect> keepOut;
};

/// One label to place.
struct LabelAsk {
    PixelRect disc;      ///< the disc's bounding square, pixels, with the gap kept round it
    PixelPoint size;     ///< the label's box, pixels
    bool inBox = false;  ///< the disc is inside the walled box: its label stays in it if it can
    PixelPoint shortSize{0, 0};  ///< its short form's box, pixels; {0, 0}: none
};

/// Where one label goes.
struct LabelPlace {
    PixelRect at;  ///< w == 0: left out
    /// Away from its disc (the ring rule): a line joins its nearest edge to the disc.
    bool leader = false;
    /// In its short form (every label is, or none).
    bool shortForm = false;
    /// Left out with no side of its disc inside the window at all (a disc nearly the window's
    /// size), rather than for want of a free place.
    bool offWindow = false;
};

/// Ring places are tried for at most this many labels (a small scene: each may cost a few
/// thousand trial rectangles).
inline constexpr std::size_t kMaxLeaderLabels = 24;
/// Rings of places round a disc.
inline constexpr int kLabelRings = 48;

/// The places of `asks`, one each, in the same order, in `room`.
[[nodiscard]] std::vector<LabelPlace> placeLabels(const std::vector<LabelAsk>& asks,
                                                  const LabelRoom& room);

/// Places for a box of `size` beside `anchor`, in the order tried: above, below, right and left
/// of it, centred on it and then slid a quarter of the box at a time along that side (kept
/// within `within` along it); then the four corners.
[[nodiscard]] std::vector<PixelRect> placesBeside(const PixelRect& anchor, PixelPoint size,
                                                  const PixelRect& within);

/// Places for a box of `size` on `rings` rings round `anchor`, each a gap further out, from
/// straight up round both ways: on each ring the box clears the anchor's inscribed circle by
/// that gap in every direction.
[[nodiscard]] std::vector<PixelRect> placesOnRings(const PixelRect& anchor, PixelPoint size,
                                                   int rings);

}  // namespace psb::app
