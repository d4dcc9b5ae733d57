#pragma once
// A ball dropper as the frame shows it (scene.hpp's Dropper): a spout above where a ball starts
// and its words beside it ("dropper: 640 balls left"). Where the spout and the words go, in
// pixels, is the view's, so that the particles' labels and the grid's keep off the words
// (frame_view.hpp's labelKeepOut) and render/draw_layer.cpp draws them where this says.

#include <string>
#include <vector>

#include <particle_sandbox/dropper.hpp>
#include <particle_sandbox/math.hpp>

#include "session/camera.hpp"
#include "view/label_places.hpp"
#include "view/pixel_rect.hpp"
#include "view/text_measure.hpp"

namespace psb::app {

/// A ball dropper: its spout above where a ball starts, and what it has left.
struct DropperView {
    Vec2 at = Vec2::Zero();  ///< where a ball starts (the middle of the spread), metres
    double radius = 0.0;     ///< a ball's, metres
    double spread = 0.0;     ///< metres either side of `at`
    std::string label;       ///< "dropper: 640 balls left"
    /// Its words as placed (dropperWords): buildFrame places them once the panels are laid out.
    struct Words {
        PixelRect at;                    ///< the rectangle they take, pixels
        std::vector<std::string> lines;  ///< drawn from `at`'s top-left, a line height apart
    } words;
};

/// The spout on screen, pixels: a funnel from `top` (half `high` wide) narrowing down to
/// `bottom` (half `low` wide), just above where a ball starts, centred on `x`; as wide as the
/// spread and a ball either side, at least a few pixels whatever the zoom.
struct DropperSpout {
    double x = 0.0;
    double top = 0.0, bottom = 0.0;
    double low = 0.0, high = 0.0;
};

[[nodiscard]] DropperSpout dropperSpout(const Camera& camera, const DropperView& dropper);

/// Where the dropper's words `label` go, in `font`: beside its spout, level with its middle,
/// read whole inside the room's walled box (w == 0: a box without walls, the window counts)
/// and its window, clear of its keepOut (the panels, the pegs). Right of the spout in
/// one line, else left of it; else wrapped at spaces to the room on that side (the side with
/// more room first: "dropper:" over "876 balls left"); else above the box's top wall (as drawn)
/// over the spout, in one line, else wrapped, slid along to stay in the window. Where none of these
/// is clear, right of the spout in one line. A small box at 200 % ran its words out of the box and
/// under the bins' chart.
[[nodiscard]] DropperView::Words dropperWords(const DropperSpout& spout, const std::string& label,
                                              const TextMeasure& font, const LabelRoom& room);

/// What the words beside a dropper's spout say: "dropper: 640 balls left", "dropper: 1 ball
/// left", "dropper: empty".
[[nodiscard]] std::string dropperLabel(const Dropper& dropper);

}  // namespace psb::app
