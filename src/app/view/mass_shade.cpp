#include "view/mass_shade.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

namespace psb::app {

namespace {

Rgba rgba(Color c) {
    return Rgba{c.r, c.g, c.b};
}

/// `c` moved a fraction `t` of the way to `target` (0 or 255 per channel).
Color towards(Color c, double target, double t) {
    const auto channel = [&](std::uint8_t v) {
        return static_cast<std::uint8_t>(std::lround(v + (target - v) * t));
    };
    return Color{channel(c.r), channel(c.g), channel(c.b)};
}

}  // namespace

double MassRange::place(double mass) const {
    if (!varies() || !(mass > 0.0)) return 0.0;
    return std::clamp(std::log(mass / lo) / std::log(hi / lo), 0.0, 1.0);
}

MassRange massRange(std::span<const double> masses) {
    MassRange r{};
    bool any = false;
    for (const double m : masses) {
        if (!(m > 0.0) || !std::isfinite(m)) continue;
        r.lo = any ? std::min(r.lo, m) : m;
        r.hi = any ? std::max(r.hi, m) : m;
        any = true;
    }
    return r;
}

Color MassShades::at(double place) const {
    const auto channel = [&](std::uint8_t a, std::uint8_t b) {
        return static_cast<std::uint8_t>(std::lround(a + (b - a) * place));
    };
    return Color{channel(light.r, heavy.r), channel(light.g, heavy.g), channel(light.b, heavy.b)};
}

MassShades massShades(Color colour, Theme theme) {
    const Rgba background = palette(theme).background;
    // Neither end may fall below this contrast against the background.
    const double floor = std::min(3.0, contrastRatio(rgba(colour), background));
    const auto visible = [&](Color c) { return contrastRatio(rgba(c), background) >= floor; };
    // Both ends move a step at a time, in turn, so that neither strays far from the scene's
    // colour; the theme's own way first (paler on black, deeper on white).
    const bool paleFirst = theme == Theme::Dark;
    constexpr double kStep = 0.025, kMost = 0.7;
    double pale = 0.0, deep = 0.0;  // how far each end has moved
    bool paleOpen = true, deepOpen = true;
    MassShades s{colour, colour};
    while (contrastRatio(rgba(s.light), rgba(s.heavy)) < kMinContrast && (paleOpen || deepOpen)) {
        const bool paleTurn = paleOpen && (!deepOpen || pale < deep || (pale == deep && paleFirst));
        double& moved = paleTurn ? pale : deep;
        const double t = moved + kStep;
        const Color next = towards(colour, paleTurn ? 255.0 : 0.0, t);
        if (t > kMost + 1e-9 || !visible(next)) {
            (paleTurn ? paleOpen : deepOpen) = false;
            continue;
        }
        moved = t;
        (paleTurn ? s.light : s.heavy) = next;
    }
    return s;
}

Color discFill(const World& world, ParticleId id, Theme theme) {
    const Palette& colours = palette(theme);
    const std::optional<std::size_t> i = world.indexOf(id);
    if (!i) return Color{colours.text.r, colours.text.g, colours.text.b};
    const ParticleArrays& p = world.particles();
    const Color c = colours.mapParticles ? lightColour(p.color[*i]) : p.color[*i];
    const MassRange masses = massRange(p.mass);
    if (!masses.varies()) return c;
    return massShades(c, theme).at(masses.place(p.mass[*i]));
}

}  // namespace psb::app
