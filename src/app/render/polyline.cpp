#include "render/polyline.hpp"

#include <algorithm>
#include <cmath>

namespace psb::app {

float chartLineWidth(double uiScale) {
    if (!std::isfinite(uiScale)) return 1.f;
    return static_cast<float>(std::max(1.0, std::round(uiScale)));
}

void drawPolyline(SDL_Renderer* renderer, GeometryBatch& scratch, const SDL_FPoint* points, int n,
                  float width, SDL_Color color) {
    if (n < 2) return;
    if (!(width >= 1.5f)) {
        SDL_SetRenderDrawColor(renderer, color.r, color.g, color.b, color.a);
        SDL_RenderDrawLinesF(renderer, points, n);
        return;
    }
    scratch.clear();
    const float h = 0.5f * width;
    for (int k = 0; k + 1 < n; ++k) {
        const SDL_FPoint a = points[k], b = points[k + 1];
        const float dx = b.x - a.x, dy = b.y - a.y;
        const float len = std::sqrt(dx * dx + dy * dy);
        if (!(len > 0.f)) continue;
        const float nx = -dy / len * h, ny = dx / len * h;
        scratch.polygon4({a.x + nx, a.y + ny}, {b.x + nx, b.y + ny}, {b.x - nx, b.y - ny},
                         {a.x - nx, a.y - ny}, color);
    }
    for (int k = 1; k + 1 < n; ++k)
        scratch.quad(points[k].x - h, points[k].y - h, points[k].x + h, points[k].y + h, color);
    scratch.draw(renderer, nullptr);
}

}  // namespace psb::app
