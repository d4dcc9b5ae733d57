#include "view/arrow_clip.hpp"

#include <algorithm>

namespace psb::app {

ClippedArrow clipArrow(const Vec2& from, const Vec2& tip, const Camera::ScreenBox& box) {
    const double left = box.topLeft.x(), top = box.topLeft.y();
    const double right = left + box.size.x(), bottom = top + box.size.y();
    const auto inside = [&](const Vec2& p) {
        return p.x() >= left && p.x() <= right && p.y() >= top && p.y() <= bottom;
    };
    if (inside(tip) || !inside(from)) return {tip, false};
    // The largest share s of the way along from `from` to `tip` that stays inside.
    const Vec2 d = tip - from;
    double s = 1.0;
    if (d.x() > 0.0) s = std::min(s, (right - from.x()) / d.x());
    if (d.x() < 0.0) s = std::min(s, (left - from.x()) / d.x());
    if (d.y() > 0.0) s = std::min(s, (bottom - from.y()) / d.y());
    if (d.y() < 0.0) s = std::min(s, (top - from.y()) / d.y());
    return {from + std::clamp(s, 0.0, 1.0) * d, true};
}

}  // namespace psb::app
