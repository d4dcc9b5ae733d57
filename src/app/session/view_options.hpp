#pragma once
// What the view shows, as plain data the session holds and the drawing layer reads: the
// toggles of the keys A, S, V, L, K, D, O, J, I, Q, Shift+G, the Spin and y up checkboxes, the
// arrow scale, and how the window looks to a room: the UI's scale (Ctrl+plus, Ctrl+minus, Ctrl+0)
// and the theme (Ctrl+T). No SDL, so the session and its tests can use it without a window.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

#include <particle_sandbox/axes.hpp>
#include <particle_sandbox/world.hpp>

namespace psb::app {

/// What L shows.
enum class TrailMode { Off, Selected, All };

/// What can be shown or hidden (checkboxes, and the keys A, S, V, K, D, O, J, I, Q, Shift+G).
enum class ShowOption : std::uint8_t {
    Arrows,
    Labels,
    Momentum,
    Plots,
    Speeds,
    Profile,
    Bins,
    Collision,
    Values,
    Ruler,
    Grid,
    Spin,
    YUp
};

/// The window's colours (view/palette.hpp): today's dark theme, or a light, high-contrast one for
/// projectors (white background, dark text, colours told apart by colour-blind viewers).
enum class Theme : std::uint8_t { Dark, Light };
/// "dark", "light".
[[nodiscard]] const char* toString(Theme theme);

/// The UI's scale: the panel, the HUD, the labels and the charts together, × their size at 100 %.
inline constexpr double kMinUiScale = 0.75;
inline constexpr double kMaxUiScale = 3.0;
/// The scales Ctrl+plus and Ctrl+minus step through (a browser's zoom steps).
inline constexpr double kUiScaleSteps[] = {0.75, 0.9, 1.0, 1.1, 1.25, 1.5, 1.75, 2.0, 2.5, 3.0};

/// The least width, points at the UI's scale, the open panel takes: its rows of buttons and its
/// sliders with their names still fit (its sentences wrap). A window narrower than this many
/// points at the scale chosen gets a smaller scale (mostUiScale).
inline constexpr double kPanelLeastPoints = 240.0;
/// The most UI scale a window `widthPoints` wide (window points: CSS pixels in a page) allows: the
/// open panel, kPanelLeastPoints at that scale, across the whole window and no wider, in steps of
/// 5 % (160 % on a phone 390 points wide, 130 % at 320); never below kMinUiScale nor above
/// kMaxUiScale. Its close button and its rows then stay on screen at any scale chosen.
[[nodiscard]] double mostUiScale(double widthPoints);

/// The scale the UI takes by itself in a window `heightPoints` high (window points): 100 % up to
/// 899 points, then a quarter step per 180 points (125 % at 900, 150 % at 1080, 200 % at 1440,
/// 300 % at 2160 and above). The layout was drawn for the 800-point window the program opens;
/// the rule keeps the text the same fraction of the window's height (about 1/48: 15-point panel
/// text in 720 points), so a full-screen window on a 1920×1080 projector opens at 150 % (22-pixel
/// text, docs/app.md "Classroom").
[[nodiscard]] double automaticUiScale(double heightPoints);
/// The next listed scale (kUiScaleSteps) above `scale` for `steps` > 0, below it for `steps` < 0,
/// `steps` times; at the ends it stays.
[[nodiscard]] double steppedUiScale(double scale, int steps);

/// Off -> Selected -> All -> Off.
[[nodiscard]] TrailMode nextTrailMode(TrailMode mode);
/// "off", "selected", "all".
[[nodiscard]] const char* toString(TrailMode mode);

/// A moving particle's arrow reaches at least this far beyond its rim, pixels, so that big slow
/// particles show one (the HUD names the arrow scale, so a short arrow still reads as a speed).
inline constexpr double kMinArrowPixels = 10.0;

/// The arrow scale the user may set, seconds of motion.
inline constexpr double kMinArrowSeconds = 0.005;
inline constexpr double kMaxArrowSeconds = 5.0;

/// What to draw besides the discs.
struct ViewOptions {
    bool arrows = true;   ///< velocity arrows
    bool labels = false;  ///< x and y velocity, momentum and mass beside each particle
    /// Arrow length per unit speed, seconds: an arrow reaches where the particle will be after
    /// this time. The original drew 20 × the per-frame displacement at 60 fps, i.e. 1/3 s.
    double arrowSeconds = 1.0 / 3.0;
    /// The user set the arrow scale (the Show section's slider): it stays as set, no longer
    /// shortening by itself, until a scene opens.
    bool arrowScaleSet = false;
    // Analysis overlays (see docs/app-instruments.md, "Seeing the physics").
    bool momentum = false;              ///< V: momentum arrows, centre of mass, Σ m v
    TrailMode trails = TrailMode::Off;  ///< L: path traces
    bool plots = false;                 ///< K: energy, momentum and collision rate against time
    bool speeds = false;                ///< D: speed histogram against Maxwell–Boltzmann
    /// The bin counts of a scene with bins (a Galton board) against its expected distribution;
    /// on unless switched off, drawn only for a scene that has bins.
    bool bins = true;
    bool profile = false;  ///< O: the step pipeline's stages, timed
    /// J: the last collision card (the selected particle's last collision, or any pair's).
    bool collision = false;
    /// I: the values table (every particle's signed values and their totals), in a window.
    bool values = false;
    /// Q: the ruler (session/lab_ruler.hpp).
    bool ruler = false;
    /// Shift+G: a grid of metres over the box, labelled along its top and left edges.
    bool grid = false;
    /// The Spin checkbox: each turning disc's rotation mark (a contrasting quarter that turns
    /// with it), in a world that keeps rotation; fixed-rotation discs have none.
    bool spin = true;
    /// The "y up" checkbox (particle_sandbox/axes.hpp): numbers shown and typed count y upward from
    /// the floor, as in school physics. On by default in every scene, not only those with gravity:
    /// a student's vy should not change sign between two presets, and school problems put y up
    /// whether or not something falls. The files keep the world's y down.
    bool yUp = true;
    /// The UI's scale chosen (kMinUiScale to kMaxUiScale), and whether it follows the window's
    /// height (automaticUiScale) rather than being set (Ctrl+plus, Ctrl+minus, the slider). The
    /// settings keep it; it is used up to what the window allows (uiScaleInUse).
    double uiScale = 1.0;
    bool uiScaleAutomatic = true;
    /// The most the window's width allows (mostUiScale, cmd::FitUiScale).
    double uiScaleMost = kMaxUiScale;
    Theme theme = Theme::Dark;  ///< Ctrl+T

    /// The scale the panel, the HUD, the labels and the charts are drawn at: the one chosen, no
    /// more than the window allows.
    [[nodiscard]] double uiScaleInUse() const {
        return uiScale < uiScaleMost ? uiScale : uiScaleMost;
    }
    /// The flag of `option`.
    [[nodiscard]] bool& flag(ShowOption option);
    /// The axes numbers are shown in, for a box of `def`'s size.
    [[nodiscard]] Axes axes(const WorldDef& def) const { return {yUp, def.height}; }
    [[nodiscard]] bool shown(ShowOption option) const {
        return const_cast<ViewOptions&>(*this).flag(option);
    }
};

/// What the message says when `option` is switched `on` ("Plots on", "Arrows off").
[[nodiscard]] std::string showMessage(ShowOption option, bool on);

/// An arrow scale for `world` (seconds, see ViewOptions::arrowSeconds): the original's 1/3 s,
/// shortened when that would make the root-mean-square arrow longer than a fifth of the box or
/// three quarters of the mean spacing between particles (a dense gas would be hidden under its
/// arrows).
[[nodiscard]] double arrowSecondsFor(const World& world);

/// The on-screen length of a particle's arrow from its centre, pixels: `seconds` × speed ×
/// `zoom`. With a minimum of 2 pixels or more (`minExtraPixels`, see minArrowExtra), a particle
/// that moves half a pixel or more over `seconds` gets an arrow reaching at least that far past
/// its rim (`radiusPixels`); below 2 pixels a minimum would not read, and an arrow that ends
/// within a pixel of the rim is not drawn. 0: no arrow.
[[nodiscard]] inline double arrowPixels(double speed, double seconds, double zoom,
                                        double radiusPixels, double minExtraPixels) {
    const double len = seconds * speed * zoom;
    if (!(len >= 0.5) || !std::isfinite(len)) return 0.0;
    if (minExtraPixels >= 2.0) return std::max(len, radiusPixels + minExtraPixels);
    return len > radiusPixels + 1.0 ? len : 0.0;
}

/// The speed below which a particle of `world`, stepped in frames of `frame` seconds (the
/// scene's dt), counts as resting for its arrow: in the discrete and substep modes twice what
/// one step of gravity adds (2 |g| dt, dt the substep's), which a particle resting on the floor
/// or an obstacle keeps between steps; 0 in the exact mode (its resting particles have no
/// speed) and without gravity.
[[nodiscard]] double restingSpeed(const World& world, double frame);

/// The minimum arrow beyond the rim for a world whose mean particle spacing is `spacingPixels`
/// on screen: kMinArrowPixels, or half the spacing when that is less (a dense gas is not
/// covered by minimum arrows).
[[nodiscard]] double minArrowExtra(double spacingPixels);

}  // namespace psb::app
