#pragma once
// A particle's mass as the shade of its fill, so that a 1 kg ball and a 3 kg ball look
// different without labels, while radii stay the physics' own: the darker a disc, the heavier.
//
// Each colour gets two shades, a light one for the scene's lightest mass and a dark one for
// its heaviest; a mass between them takes the shade at its place on a log scale (a gas of
// 1 kg discs round a 100 kg one: the 10 kg disc halfway). The two shades are the colour moved
// towards white and towards black, a step each in turn (the theme's own way first: paler on
// the dark theme, deeper on the light one), until they differ by kMinContrast; neither ever
// loses contrast against the background below the smaller of 3:1 (WCAG's floor for graphics)
// and what the colour itself had. Shades are lightness, so colour-blind viewers see them too.
// A scene whose particles all have one mass keeps its colours exactly.

#include <cstdint>
#include <span>

#include <particle_sandbox/color.hpp>
#include <particle_sandbox/world.hpp>

#include "view/palette.hpp"

namespace psb::app {

/// The scene's lightest and heaviest masses, kg (finite, positive ones only).
struct MassRange {
    double lo = 0.0;
    double hi = 0.0;
    /// Whether the masses differ enough to be shaded (more than one part in 10^6).
    [[nodiscard]] bool varies() const { return lo > 0.0 && hi > lo * (1.0 + 1e-6); }
    /// Where `mass` lies between lo (0) and hi (1) on a log scale, clamped.
    [[nodiscard]] double place(double mass) const;
};

[[nodiscard]] MassRange massRange(std::span<const double> masses);

/// WCAG contrast the two ends of a colour's shades reach at least (where the background
/// leaves room; black and white always do): told apart at a glance, and by colour-blind
/// viewers too, since it is lightness, not hue.
inline constexpr double kMinContrast = 2.2;

/// A colour's shades, for the lightest and the heaviest mass.
struct MassShades {
    Color light;
    Color heavy;
    /// The fill of a particle at `place` (MassRange::place) between them.
    [[nodiscard]] Color at(double place) const;
};

/// The shades of `colour` (as drawn: on the light theme, lightColour's) on `theme`'s background.
[[nodiscard]] MassShades massShades(Color colour, Theme theme);

/// The fill the box draws particle `id` of `world` in on `theme`: its colour (on the light
/// theme, lightColour's) in the shade of its mass among the scene's (render/renderer.cpp draws
/// the discs so), for what speaks of a particle elsewhere in its colour (the momenta diagram's
/// arrows). The text's colour for a particle that is gone.
[[nodiscard]] Color discFill(const World& world, ParticleId id, Theme theme);

}  // namespace psb::app
