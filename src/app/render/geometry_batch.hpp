#pragma once
// Triangles collected on the CPU and sent to SDL in one SDL_RenderGeometry call: the way every
// circle, arrow, label background and glyph is drawn, so the number of draw calls per frame does
// not grow with the number of particles.

#include <vector>

#include <SDL.h>

namespace psb::app {

class GeometryBatch {
  public:
    void clear() {
        vertices_.clear();
        indices_.clear();
    }
    [[nodiscard]] bool empty() const { return indices_.empty(); }
    [[nodiscard]] std::size_t triangleCount() const { return indices_.size() / 3; }

    /// An axis-aligned rectangle (pixels) showing the texture rectangle [u0,u1]×[v0,v1]
    /// (normalised texture coordinates; ignored when drawn without a texture).
    void quad(float x0, float y0, float x1, float y1, SDL_Color c, float u0 = 0.f, float v0 = 0.f,
              float u1 = 1.f, float v1 = 1.f);
    /// A filled triangle (pixels), every vertex at texture coordinate `uv`.
    void triangle(SDL_FPoint a, SDL_FPoint b, SDL_FPoint c, SDL_Color color,
                  SDL_FPoint uv = {0.f, 0.f});
    /// A filled convex quadrilateral a-b-c-d (pixels), every vertex at texture coordinate `uv`.
    void polygon4(SDL_FPoint a, SDL_FPoint b, SDL_FPoint c, SDL_FPoint d, SDL_Color color,
                  SDL_FPoint uv = {0.f, 0.f});

    /// A convex quadrilateral a-b-c-d (pixels) showing the texture at ua, ub, uc, ud (normalised
    /// texture coordinates): a texture's piece turned or sheared.
    void texturedPolygon4(SDL_FPoint a, SDL_FPoint b, SDL_FPoint c, SDL_FPoint d, SDL_Color color,
                          SDL_FPoint ua, SDL_FPoint ub, SDL_FPoint uc, SDL_FPoint ud);

    /// One SDL_RenderGeometry call (texture may be null). Returns SDL's result (0 on success).
    int draw(SDL_Renderer* renderer, SDL_Texture* texture) const;

  private:
    std::vector<SDL_Vertex> vertices_;
    std::vector<int> indices_;
};

}  // namespace psb::app
