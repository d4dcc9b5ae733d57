#pragma once
// The measuring marks drawn over the box, in screen pixels: the grid of metres (Shift+G) and
// the ruler (Q, session/lab_ruler.hpp). Kept as plain numbers and strings so that the tests
// check where every line and label goes; render/lab_marks_drawing.hpp draws them.

#include <array>
#include <string>
#include <vector>

#include <particle_sandbox/math.hpp>

#include "session/camera.hpp"
#include "session/lab_ruler.hpp"
#include "view/label_places.hpp"
#include "view/pixel_rect.hpp"
#include "view/text_measure.hpp"

namespace psb::app {

struct MarkLine {
    Vec2 a, b;            ///< pixels
    bool strong = false;  ///< a grid line at a round number of steps, or a ruler's major tick
};

struct MarkLabel {
    Vec2 at;           ///< pixels: the label's centre, or the middle of its left side when `left`
    std::string text;  ///< its lines, separated by '\n', each centred (or from the left)
    bool left = false;
};

/// The grid: lines every `step` metres across the box (its visible part), labelled along the
/// box's top and left edges (or the window's, when those are off screen).
struct GridView {
    double step = 0.0;  ///< metres between lines
    std::vector<MarkLine> lines;
    std::vector<MarkLabel> labels;
    std::string legend;  ///< "Grid: 1 m squares", for the HUD and F12's text
};

/// Grid lines no closer than this on screen, pixels.
inline constexpr double kGridMinPixels = 60.0;

/// The grid over a `width` × `height` box seen through `camera`, its heights counted from the
/// floor up with `yUp` (Axes), else from the top edge down. Empty (no lines) when the box is not
/// on screen.
/// `minPixels`: the closest lines may be, pixels (kGridMinPixels × the UI's scale, so that
/// labels drawn larger stay apart); in a box too small for a line inside it that far from its
/// edges, finer steps (down to kGridLeastPixels), so that a small box keeps a line and a label
/// each way. `labelPixels`: the labels' line height, pixels: those along the top edge stand
/// clear of the top wall below it (at 200 % they straddled it, and a ruler's reading above the
/// box took their place).
[[nodiscard]] GridView gridView(const Camera& camera, double width, double height, bool yUp = false,
                                double minPixels = kGridMinPixels, double labelPixels = 17.0);

/// The closest grid lines get in a small box, pixels.
inline constexpr double kGridLeastPixels = 30.0;

/// The ruler: its edge, its ticks, the handles at its ends and its reading.
struct RulerView {
    Vec2 a, b;  ///< its ends, pixels
    std::vector<MarkLine> ticks;
    double tickStep = 0.0;  ///< metres between ticks
    /// Its reading as drawn beside it: in one line, or in two or three where one does not fit
    /// or read clear (keepMarkLabelsClear).
    MarkLabel label;
    std::string line;  ///< the reading in one line (rulerLine), as F12's text says it
    /// The reading in one, two and three lines (rulerLines).
    std::array<std::string, 3> forms;
    bool held = false;
};

/// Ticks no closer than this on screen, pixels.
inline constexpr double kRulerTickPixels = 8.0;

[[nodiscard]] RulerView rulerView(const LabRuler& ruler, const Camera& camera);

/// The rectangle `label` takes when drawn in `font` (its widest line, its lines' height),
/// pixels, with `pad` pixels of background around its text.
[[nodiscard]] PixelRect labelRect(const MarkLabel& label, const TextMeasure& font, int pad = 0);

/// The ruler's reading's background beyond its text, pixels each side (the drawing layer's).
inline constexpr int kReadingPad = 4;
/// A grid label's plate beyond its text, pixels each side: the labels' box colour behind the
/// number, so that it reads over the particles of a crowded box (it stood on them bare).
inline constexpr int kGridLabelPad = 3;

/// The plates behind the grid's labels (labelRect with kGridLabelPad), in `font`, the labels'
/// font: what the drawing layer fills and what the particles' labels keep off.
[[nodiscard]] std::vector<PixelRect> gridLabelPlates(const GridView& grid, const TextMeasure& font);

/// The rule every measuring mark's label obeys: it is read whole. The ruler's reading goes
/// where all of it is inside the room's window (the window right of the control panel), clear
/// of its keepOut (the panels) and of the ruler itself, and, where such a place is, clear of
/// `discs` (discsOnScreen) and of the grid's labels and across no wall: beside the ruler's middle,
/// below it first (the side its ticks point down the screen), then above, right and left, each slid
/// along that side; then further out on rings round the middle, out to the window's edges; in one
/// line, else in two (the length and the slope over the distances) where only those fit or read
/// clear; where no place is clear of all that, over a grid label (left out) rather than a ball
/// (firstClearPlace, label_places.hpp). Where no place clear of the panels is, it goes below the
/// middle, slid into the room as far as it can. A grid label that would cross the reading, a panel
/// or the room's edge is left out (its line stays). Sizes are measured in `font`, the labels' font.
void keepMarkLabelsClear(GridView* grid, RulerView* ruler, const TextMeasure& font,
                         const LabelRoom& room, const std::vector<PixelRect>& discs = {});

/// The ruler on screen as labels keep clear of it: its edge, the face its ticks are on and the
/// handles at its ends.
[[nodiscard]] ScreenWall rulerBand(const RulerView& ruler);

/// The protractor of the Wall tool: a wall being drawn from `a` to `b` (metres) labelled with
/// its length and its slope ("2.60 m, 20.0°") beyond its end `b`, in pixels.
[[nodiscard]] MarkLabel wallAngleLabel(const Vec2& a, const Vec2& b, const Camera& camera);
/// The ruler's reading as F12's text says it: "1.25 m, 20.0° (horizontal 1.17 m, vertical
/// 0.428 m)".
[[nodiscard]] std::string rulerLine(const LabRuler& ruler);
/// The same in `count` lines (1 to 3), separated by '\n': "1.25 m, 20.0°" over "horizontal
/// 1.17 m, vertical 0.428 m", or over "horizontal 1.17 m" over "vertical 0.428 m".
[[nodiscard]] std::string rulerLines(const LabRuler& ruler, int count);

}  // namespace psb::app
