#pragma once
// The window's colours, in one place: a Palette per Theme (session/view_options.hpp), read by the
// drawing layer (the box, the HUD, the charts, the overlays) and the control panel (ImGui's
// style). No SDL: a colour is four bytes.
//
// The dark theme is the program's look from the start. The light theme is for a projector: a
// white background, near-black text (contrast ratio 19:1, WCAG's AA asks 4.5:1 for text), and the
// Okabe–Ito palette (Okabe and Ito, "Color Universal Design", 2008), eight colours that people
// with the common colour-vision deficiencies (deutan, protan, tritan) still tell apart, for the
// plots, the momentum drawing and the particles: a scene's own particle colours are mapped to the
// nearest of them by hue (lightColour), so that a white particle does not vanish on white and two
// hues a viewer cannot tell apart become two they can.

#include <cstdint>

#include <particle_sandbox/color.hpp>

#include "session/view_options.hpp"

namespace psb::app {

/// A colour with its opacity (255: opaque).
struct Rgba {
    std::uint8_t r = 0, g = 0, b = 0, a = 255;
    friend bool operator==(const Rgba&, const Rgba&) = default;
};

struct Palette {
    Rgba background;  ///< the window behind everything
    Rgba walls;       ///< a closed box's walls
    Rgba openWalls;   ///< an open box's outline (a hint)
    Rgba text;        ///< the HUD, the panels' text, messages
    /// Behind the text panels and charts, opaque: a velocity arrow or a ball under the messages'
    /// line showed through it (the Galton board at 200 %).
    Rgba panel;
    Rgba axis;           ///< the charts' axes and tick marks
    Rgba tickText;       ///< the charts' numbers
    Rgba labelBox;       ///< behind a particle's label
    Rgba labelText;      ///< a particle's label
    Rgba highlight;      ///< the selection, the selected obstacle, a dropper, the box marker
    Rgba warning;        ///< the recording mark, notes in red
    Rgba obstacle;       ///< pegs and walls drawn in the box
    Rgba preview;        ///< the obstacle tool's preview
    Rgba dropper;        ///< a ball dropper's spout
    Rgba dropperText;    ///< the words beside it
    Rgba ghost;          ///< a launch's disc before it is let go
    Rgba launchArrow;    ///< a launch's arrow
    Rgba momentumArrow;  ///< each particle's m v
    Rgba totalMomentum;  ///< Σ m v
    Rgba centreOfMass;   ///< its marker and path
    Rgba energyPlot, pxPlot, pyPlot, ratePlot;
    Rgba histogramBar;      ///< the speed histogram
    Rgba theoryCurve;       ///< Maxwell–Boltzmann, the binomial's dots
    Rgba binBar;            ///< the bins' counts
    Rgba normalCurve;       ///< the bins' normal curve
    Rgba controls;          ///< the control panel's background (opaque: see control_panel.cpp)
    Rgba caution;           ///< the panel's notes in amber (unsaved changes, a slow step)
    Rgba grid, gridStrong;  ///< the grid of metres, its lines and every fifth (or second) one
    Rgba ruler;             ///< the ruler's edge, ticks, handles and reading
    /// The particles keep their scene's colours (dark), or take lightColour's (light).
    bool mapParticles = false;
};

/// The palette of `theme`.
[[nodiscard]] const Palette& palette(Theme theme);

/// The Okabe–Ito colour a particle coloured `c` is drawn in on the light theme: black for a grey
/// (or white) one, else the nearest by hue of vermillion, orange, bluish green, sky blue, blue and
/// reddish purple (yellow is left out: on white it is hard to see).
[[nodiscard]] Color lightColour(Color c);

/// WCAG 2's contrast ratio of two opaque colours, 1 (the same) to 21 (black on white).
[[nodiscard]] double contrastRatio(Rgba a, Rgba b);

/// `colour` as text on `background` (its alpha ignored): itself when their contrast ratio is
/// at least 4.5:1 (WCAG AA for text), else moved towards black on a light background (towards
/// white on a dark one) just far enough. A legend line in its curve's colour stays that colour's
/// hue and reads: Okabe-Ito orange on the light panel is 2:1, the shade this gives 4.5:1.
[[nodiscard]] Rgba readableText(Rgba colour, Rgba background);

}  // namespace psb::app
