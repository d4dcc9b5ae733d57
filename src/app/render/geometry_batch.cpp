#include "render/geometry_batch.hpp"

namespace psb::app {

void GeometryBatch::quad(float x0, float y0, float x1, float y1, SDL_Color c, float u0, float v0,
                         float u1, float v1) {
    const int base = static_cast<int>(vertices_.size());
    vertices_.push_back({{x0, y0}, c, {u0, v0}});
    vertices_.push_back({{x1, y0}, c, {u1, v0}});
    vertices_.push_back({{x1, y1}, c, {u1, v1}});
    vertices_.push_back({{x0, y1}, c, {u0, v1}});
    for (int k : {0, 1, 2, 0, 2, 3})
        indices_.push_back(base + k);
}

void GeometryBatch::triangle(SDL_FPoint a, SDL_FPoint b, SDL_FPoint c, SDL_Color color,
                             SDL_FPoint uv) {
    const int base = static_cast<int>(vertices_.size());
    vertices_.push_back({a, color, uv});
    vertices_.push_back({b, color, uv});
    vertices_.push_back({c, color, uv});
    for (int k : {0, 1, 2})
        indices_.push_back(base + k);
}

void GeometryBatch::polygon4(SDL_FPoint a, SDL_FPoint b, SDL_FPoint c, SDL_FPoint d,
                             SDL_Color color, SDL_FPoint uv) {
    const int base = static_cast<int>(vertices_.size());
    for (SDL_FPoint p : {a, b, c, d})
        vertices_.push_back({p, color, uv});
    for (int k : {0, 1, 2, 0, 2, 3})
        indices_.push_back(base + k);
}

void GeometryBatch::texturedPolygon4(SDL_FPoint a, SDL_FPoint b, SDL_FPoint c, SDL_FPoint d,
                                     SDL_Color color, SDL_FPoint ua, SDL_FPoint ub, SDL_FPoint uc,
                                     SDL_FPoint ud) {
    const int base = static_cast<int>(vertices_.size());
    vertices_.push_back({a, color, ua});
    vertices_.push_back({b, color, ub});
    vertices_.push_back({c, color, uc});
    vertices_.push_back({d, color, ud});
    for (int k : {0, 1, 2, 0, 2, 3})
        indices_.push_back(base + k);
}

int GeometryBatch::draw(SDL_Renderer* renderer, SDL_Texture* texture) const {
    if (indices_.empty()) return 0;
    return SDL_RenderGeometry(renderer, texture, vertices_.data(),
                              static_cast<int>(vertices_.size()), indices_.data(),
                              static_cast<int>(indices_.size()));
}

}  // namespace psb::app
