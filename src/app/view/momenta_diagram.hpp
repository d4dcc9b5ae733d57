#pragma once
// The momenta diagram of the last collision (PhET Collision Lab's "Momenta" diagram): each
// particle's momentum m v as an arrow, placed tip to tail from the origin, and the total as its
// own arrow from the origin to the last tip, once as it was just before the collision and once
// just after, on one scale so the two can be compared. Between two particles the total's arrow
// is the same before and after (momentum is kept); against a wall or an obstacle it changes.
// Arrows point as the particles move in the box (the box's x to the right, y down). The panel's
// Last collision section draws it; the text F12 writes lists it.

#include <array>
#include <string>
#include <vector>

#include <particle_sandbox/axes.hpp>
#include <particle_sandbox/color.hpp>
#include <particle_sandbox/math.hpp>
#include <particle_sandbox/world.hpp>

#include "session/last_collision.hpp"
#include "view/palette.hpp"

namespace psb::app {

struct MomentaDiagram {
    enum class Kind { First, Second, Total };
    struct Arrow {
        Vec2 from;  ///< kg m/s, the diagram's origin at (0, 0)
        Vec2 to;
        Kind kind = Kind::First;
        std::string label;  ///< "p 1", "p 2", "total p"
        /// Added to both ends on screen, in sides of the square: when every momentum lies on
        /// one axis (a head-on collision), the arrows would lie on top of each other, so each
        /// gets a row of its own across that axis, as in PhET's one-dimensional diagram; no
        /// row is the axis itself, where the axis's line would hide the arrow.
        Vec2 offset = Vec2::Zero();
    };
    std::vector<Arrow> before, after;
    /// The square's half-width, kg m/s, as its caption states it (momentaDiagramScale): a round
    /// number (1, 1.5, 2, 2.5, 3, 4, 5, 6 or 8 times a power of ten) that leaves every tip of
    /// both halves at least kMargin of the side inside the square, so an arrowhead never
    /// touches its edge. A diagram of resting particles still gets one.
    double reach = 1.0;
    /// The free band a tip keeps from the square's edge, in sides of the square.
    static constexpr double kMargin = 0.05;

    /// A momentum's place in a square of `side` pixels whose centre is the origin (x right,
    /// y down as in the box): `reach` reaches the square's edge, so an arrow of `reach` kg m/s
    /// is side / 2 pixels long, exactly what the caption says.
    [[nodiscard]] Vec2 toPixels(const Vec2& p, double side) const;
    /// An arrow's ends on screen, its row's offset included.
    [[nodiscard]] Vec2 fromPixels(const Arrow& a, double side) const {
        return toPixels(a.from, side) + side * a.offset;
    }
    [[nodiscard]] Vec2 toPixels(const Arrow& a, double side) const {
        return toPixels(a.to, side) + side * a.offset;
    }
};

[[nodiscard]] MomentaDiagram momentaDiagram(const CollisionCard& card);

/// The colours of the diagram's arrows on `theme`: particle 1's, particle 2's and the total's.
/// Fixed, so that no two are ever alike: Okabe and Ito's orange and sky blue on the dark theme,
/// their vermillion and blue on the light one (sky blue on white hardly shows), and the total
/// in the theme's text colour, white or black. (Each particle's arrow took its ball's colour
/// for a while: a black ball's arrow was the black of the total's.)
[[nodiscard]] std::array<Color, 3> momentaColours(Theme theme);

/// Where the labels of `arrows` (one half of `d`, drawn in a square of `side` pixels) go: the
/// top-left corner of each label's box, `sizes[k]` pixels for arrows[k]. Each stays inside the
/// square, over no other label, clear of every arrow (`arrowHalfWidth` pixels either side of
/// its line, the head's width) and of the axes through the centre: beside its arrow's middle
/// where it can (above it first), then beside it further along, then at the free place
/// nearest its middle. With no free place at all it takes the one that crosses fewest. (They
/// were centred above each arrow's middle: in a gas's collision "p 1653" lay over "total p",
/// "p 2837" was cut at the square's edge and an axis ran through "total p".)
[[nodiscard]] std::vector<Vec2> momentaLabelPlaces(const MomentaDiagram& d,
                                                   const std::vector<MomentaDiagram::Arrow>& arrows,
                                                   double side, const std::vector<Vec2>& sizes,
                                                   double arrowHalfWidth);

/// The diagram's caption under the two squares: "The square reaches 3.00 kg m/s from its
/// centre; ...", the number the arrows are drawn to (MomentaDiagram::reach).
[[nodiscard]] std::string momentaDiagramScale(const MomentaDiagram& diagram);

/// The diagram as text, for the screenshot's file: "Momenta before: p 1 (3.00, 0) + p 2 (-3.00, 0)
/// = total p (0, 0) kg m/s" and the same after, in `axes` (the y up option).
[[nodiscard]] std::vector<std::string> momentaDiagramLines(const MomentaDiagram& diagram,
                                                           const Axes& axes = {});

}  // namespace psb::app
