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
//      small box has no room beside its balls; the window round it has) that crosses no wall
//      at an angle (a ramp between a ball and its label would put the label on the wrong
//      side of it), the label half its height clear of every other ball (one touching another
//      ball reads as that one's);
//
// and it is left out when no place is free. Free: inside the window, clear of every disc, of
// its own ball's velocity arrow, of the labels already placed and their leader lines (a leader
// line passes over no other disc nor label, nor over what the room keeps out) and of what the
// room keeps out (the panels, pegs, the grid's distances, the ruler's reading), and across no
// wall (the box's outline, a wall at any angle); and a label without a leader line is nearer
// its own disc than any other (from the label's middle to each disc's rim): a reader ties a
// label to the ball nearest it (in the original's six balls at 200 % one stood beside its
// ball's rim but nearer its neighbour, and read as the neighbour's). A label never covers a
// ball nor crosses a wall: in a crowd (the funnel's 400 balls) most are left out, and the HUD
// says how many.
//
// Every label has one form: its values (LabelAsk::size), or, where that leaves labels out that
// their names alone (LabelAsk::nameSize, "particle 3") would not, every label its name alone.
// Never a mix (labels of one line beside labels of five read as different things).
//
// The ruler's reading is placed among the same places (firstClearPlace): clear of the discs
// where a place is, over the fewest where none is; over the grid's labels only where that
// keeps it off the discs.

#include <cstddef>
#include <vector>

#include <particle_sandbox/world.hpp>

#include "session/camera.hpp"
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
/// no walls) nor any of `walls`, over none of `keepOut`. The box's walls are drawn `boxWall`
/// pixels thick outside `box`: a label outside it keeps clear of them too.
struct LabelRoom {
    PixelRect window;
    PixelRect box;
    std::vector<ScreenWall> walls;
    std::vector<PixelRect> keepOut;
    int boxWall = 0;
};

/// How thick the walled box's walls are drawn on screen, outside the box, pixels: 0.4 % of the
/// box's smaller side (`width` × `height` metres) at `zoom` pixels a metre, at least two
/// (render/renderer.cpp draws them so).
[[nodiscard]] double boxWallPixels(double width, double height, double zoom);

/// A label's leader line (LabelPlace::leader), pixels: from the rim of the disc `disc` (its
/// bounding square with the gap kept round it) to the nearest point of the label at `label`.
struct LeaderLine {
    double ax = 0.0, ay = 0.0, bx = 0.0, by = 0.0;
};
[[nodiscard]] LeaderLine leaderLine(const PixelRect& disc, const PixelRect& label);

/// Whether the line `l` crosses `wall`'s middle line, or its end at the label (or the line
/// past the wall's ends) comes within the wall's half-width.
[[nodiscard]] bool leaderCrosses(const LeaderLine& l, const ScreenWall& wall);

/// What the particles' labels keep clear of besides the discs and the scene's walls: the
/// panels and the ruler's reading (`rects`), the ruler itself and the total momentum's arrow
/// from the centre of mass (`walls`).
struct LabelKeepOut {
    std::vector<PixelRect> rects;
    std::vector<ScreenWall> walls;
};

/// One label to place.
struct LabelAsk {
    PixelRect disc;      ///< the disc's bounding square, pixels, with the gap kept round it
    PixelPoint size;     ///< the label's box, pixels
    bool inBox = false;  ///< the disc is inside the walled box: its label stays in it if it can
    /// Its name's box alone ("particle 3"), pixels: every label's form where the values leave
    /// labels out that the names would not; {0, 0}: none.
    PixelPoint nameSize{0, 0};
    /// Its ball's velocity arrow from the rim to the tip, its head's half-width either side;
    /// halfWidth == 0: none. The label is never drawn over it.
    ScreenWall arrow{};
};

/// Where one label goes.
struct LabelPlace {
    PixelRect at;  ///< w == 0: left out
    /// Away from its disc (the ring rule): a line joins its nearest edge to the disc.
    bool leader = false;
    /// Its name alone (LabelAsk::nameSize), as every label is, or none.
    bool nameOnly = false;
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

/// The room for labels over `world` seen through `camera` in `window`: its walled box's outline,
/// its walls at an angle, and `keepOut`.
[[nodiscard]] LabelRoom labelRoom(const World& world, const Camera& camera, const PixelRect& window,
                                  std::vector<PixelRect> keepOut);

/// The pegs of `world` seen through `camera`, each one's bounding square and a pixel round it:
/// as solid as the discs to a label.
[[nodiscard]] std::vector<PixelRect> pegsOnScreen(const World& world, const Camera& camera);

/// The discs of `world` seen through `camera` that meet `window`, as labels keep clear of them:
/// each one's bounding square with a gap of kLabelGap pixels round it.
[[nodiscard]] std::vector<PixelRect> discsOnScreen(const World& world, const Camera& camera,
                                                   const PixelRect& window);

/// Pixels a label keeps from its disc's rim.
inline constexpr int kLabelGap = 2;
/// The most two labels side by side keep apart, pixels (half a label's height where less).
inline constexpr int kLabelsApart = 24;

/// A place for a box that must be read whole (firstClearPlace), and what it covers.
struct ReadingPlace {
    PixelRect at;             ///< w == 0: none inside the window and clear of keepOut
    std::size_t form = 0;     ///< which of the forms' places it is
    std::size_t discs = 0;    ///< discs it covers
    bool acrossWall = false;  ///< it crosses a wall
    std::size_t marks = 0;    ///< other readings it covers (the grid's labels, left out)
    [[nodiscard]] bool clear() const { return at.w > 0 && discs == 0 && !acrossWall && marks == 0; }
};

/// Places counted for the discs they cover when none is clear (firstClearPlace).
inline constexpr std::size_t kReadingFallbacks = 24;

/// For a box that can take several forms (the ruler's reading in one, two or three lines),
/// `places` for each form in order of preference: the first place inside the room's window,
/// clear of its keepOut, of every one of `discs`, of every one of `marks` (readings that give
/// way: the grid's labels) and across no wall, trying the first form's places, then the
/// second's...; where none is, the first of them clear of the discs and the walls, over
/// marks; where none is, of the first kReadingFallbacks of each form's places inside the window
/// and clear of keepOut, the one that covers the fewest discs, then crosses no wall, then
/// covers the fewest marks (the first of equals).
[[nodiscard]] ReadingPlace firstClearPlace(const std::vector<std::vector<PixelRect>>& places,
                                           const std::vector<PixelRect>& discs,
                                           const LabelRoom& room,
                                           const std::vector<PixelRect>& marks = {});

}  // namespace psb::app
