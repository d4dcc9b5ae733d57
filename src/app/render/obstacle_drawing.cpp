#include "render/obstacle_drawing.hpp"

#include <algorithm>
#include <cmath>

#include "render/sdl_color.hpp"

namespace psb::app {
namespace {

void disc(GeometryBatch& batch, const Vec2& centre, double radius, SDL_Color color) {
    const auto x = static_cast<float>(centre.x()), y = static_cast<float>(centre.y());
    const auto r = static_cast<float>(radius);
    batch.quad(x - r, y - r, x + r, y + r, color);
}

}  // namespace

void batchObstacle(const Obstacle& o, const Camera& camera, SDL_Color color, GeometryBatch& batch) {
    const double r = std::max(1.0, camera.toScreen(o.radius));
    const Vec2 a = camera.worldToScreen(o.a);
    disc(batch, a, r, color);
    if (o.isPeg()) return;
    const Vec2 b = camera.worldToScreen(o.b);
    disc(batch, b, r, color);
    const Vec2 along = b - a;
    const double length = along.norm();
    if (!(length > 0.0)) return;
    const Vec2 side = Vec2(-along.y(), along.x()) * (r / length);
    auto point = [](const Vec2& v) {
        return SDL_FPoint{static_cast<float>(v.x()), static_cast<float>(v.y())};
    };
    batch.polygon4(point(a + side), point(b + side), point(b - side), point(a - side), color,
                   SDL_FPoint{0.5f, 0.5f});
}

void batchObstacles(const World& world, const Camera& camera, GeometryBatch& batch,
                    const Palette& colours) {
    batch.clear();
    for (const Obstacle& o : world.obstacles())
        batchObstacle(o, camera, sdlColor(colours.obstacle), batch);
}

}  // namespace psb::app
