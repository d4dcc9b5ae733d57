#include "view/particle_labels.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "session/units.hpp"

namespace psb::app {

ParticleLabelText particleLabelText(std::uint64_t number, double mass, double vx, double vy) {
    const auto twoDecimals = [](double v) { return std::abs(v) < 0.005 ? 0.0 : v; };
    ParticleLabelText t;
    t.name = "particle " + std::to_string(number);
    t.values[0] = t.name + ", " + quantity(mass, "kg", false);
    char v[96];
    std::snprintf(v, sizeof v, "v (%.2f, %.2f) m/s", twoDecimals(vx), twoDecimals(vy));
    t.values[1] = v;
    return t;
}

LabelAsk particleLabelAsk(const ParticleLabelText& text, const PixelRect& disc,
                          const TextMeasure& font, bool inBox) {
    const int lh = font.lineHeight();
    LabelAsk a;
    a.disc = disc;
    a.size = {std::max(font.measure(text.values[0]), font.measure(text.values[1])) + 4, 2 * lh + 1};
    a.nameSize = {font.measure(text.name) + 4, lh + 1};
    a.inBox = inBox;
    return a;
}

}  // namespace psb::app
