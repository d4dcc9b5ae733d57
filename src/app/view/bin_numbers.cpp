#include "view/bin_numbers.hpp"

#include <cmath>

namespace psb::app {

std::vector<BinNumber> binNumbers(const Camera& camera, const Bins& bins, double floor,
                                  const TextMeasure& font) {
    std::vector<BinNumber> out;
    if (bins.edges.size() < 2) return out;
    const double top = camera.worldToScreen(Vec2(bins.edges.front(), bins.top)).y();
    const double bottom = camera.worldToScreen(Vec2(bins.edges.back(), floor)).y();
    if (!(bottom - top >= 2.0 * font.lineHeight())) return out;
    for (std::size_t k = 0; k + 1 < bins.edges.size(); ++k) {
        std::string number = std::to_string(k);
        const double left = camera.worldToScreen(Vec2(bins.edges[k], floor)).x();
        const double right = camera.worldToScreen(Vec2(bins.edges[k + 1], floor)).x();
        const int width = font.measure(number);
        if (right - left < width + 4.0) continue;
        const auto x = static_cast<int>(std::round(0.5 * (left + right) - 0.5 * width));
        const auto y = static_cast<int>(std::round(top + 2.0));
        out.push_back({{x, y, width, font.lineHeight()}, std::move(number)});
    }
    return out;
}

}  // namespace psb::app
