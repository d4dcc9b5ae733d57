#pragma once
// Where the particles' labels (S) go: a pure function from the discs on screen and the sizes of
// their labels to rectangles, so that the rule is tested without drawing
// (render/renderer.cpp draws what it says). Each label, in the order asked, takes the first
// place that is free, trying in turn:
//
//   1. beside its disc (above, below, right, left, then the four corners; each slid along that
//      side to stay in the window), clear of every disc, inside the box with a disc in it;
//   2. the same, anywhere but across a wall;
//   3. further out, on rings of places around its disc, clear of every disc and not across a
//      wall, joined to its disc by a leader line (a small box has no room beside its balls;
//      the window round it has);
//   4. beside its disc, then on the rings, across a wall but clear of every disc (a box too
//      low for a label anywhere in it, with no room round it);
//   5. beside its disc over other discs (drawn without its background, which would darken
//      them);
//
// and is left out when none is free. Free: inside the window, clear of the labels already
// placed and of the panels. Where that leaves a label out, over discs or across a wall and the
// labels have a short form (LabelAsk::shortSize), every label takes its short form if that
// places them better (a small box at 200 %: two lines beside each ball rather than five over
// the walls).

#include <vector>

#include "view/pixel_rect.hpp"

namespace psb::app {

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
    /// It lies over other discs (the third rule): drawn without a background.
    bool overDiscs = false;
    /// Away from its disc (the ring rule): a line joins its nearest edge to the disc.
    bool leader = false;
    /// Across a wall (the fourth rule).
    bool acrossWall = false;
    /// In its short form (every label is, or none).
    bool shortForm = false;
    /// Left out with no side of its disc inside the window at all (a disc nearly the window's
    /// size), rather than for want of a free place.
    bool offWindow = false;
};

/// Ring places are tried for at most this many labels (a small scene: each may cost a few
/// thousand trial rectangles).
inline constexpr std::size_t kMaxLeaderLabels = 24;

/// The places of `asks`, one each, in the same order, in a `window` of pixels with the walled
/// box at `walls` (w == 0: no walls) and the panels at `keepOut`.
[[nodiscard]] std::vector<LabelPlace> placeLabels(const std::vector<LabelAsk>& asks,
                                                  const PixelRect& window, const PixelRect& walls,
                                                  const std::vector<PixelRect>& keepOut);

}  // namespace psb::app
