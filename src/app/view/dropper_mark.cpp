#include "view/dropper_mark.hpp"

#include <algorithm>
#include <cmath>

namespace psb::app {

DropperSpout dropperSpout(const Camera& camera, const DropperView& d) {
    const Vec2 at = camera.worldToScreen(d.at);
    const double ppm = camera.worldToScreen(d.at + Vec2(1.0, 0.0)).x() - at.x();
    const double r = std::max(d.radius * ppm, 2.0);
    DropperSpout s;
    s.x = at.x();
    s.bottom = at.y() - 1.3 * r;
    s.top = s.bottom - std::max(3.5 * r, 10.0);
    s.low = d.spread * ppm + 1.5 * r;
    s.high = s.low + std::max(2.0 * r, 6.0);
    return s;
}

PixelRect dropperLabelRect(const DropperSpout& s, const std::string& label,
                           const TextMeasure& font) {
    const double x = s.x + s.high + 6.0;
    const double y = 0.5 * (s.top + s.bottom) - font.lineHeight() / 2.0;
    return {static_cast<int>(std::floor(x)), static_cast<int>(std::floor(y)),
            font.measure(label) + 1, font.lineHeight() + 1};
}

std::string dropperLabel(const Dropper& d) {
    if (d.balls == 0) return "dropper: empty";
    return "dropper: " + std::to_string(d.balls) + (d.balls == 1 ? " ball left" : " balls left");
}

}  // namespace psb::app
