#pragma once
// Dear ImGui's draw lists drawn with SDL_RenderGeometry, so the on-screen controls work on every
// SDL_Renderer, SDL's software renderer under Xvfb included. Debian's libimgui ships the SDL2
// platform backend (input, window size) but no SDL_Renderer backend; this is that backend.
//
//   ImGui::Render() ──► ImDrawData: command lists, each a vertex buffer, an index buffer and
//                       draw commands (clip rect, texture id, index range, vertex offset)
//        │
//        ▼ render()
//   per list:  vertices converted once: position × framebuffer scale, packed colour → SDL_Color
//   per command: clip rect (scaled, rounded, cut to the target) → SDL_RenderSetClipRect;
//                SDL_RenderGeometryRaw(texture id, vertices from VtxOffset, 16-bit indices)
//   afterwards: the caller's viewport and clip rect are put back
//
// Texture ids are SDL_Texture pointers: the font atlas (made here, in RGBA32 with alpha
// blending) and any texture the caller passes to ImGui::Image. The framebuffer scale is the
// renderer's output size over the window size (2 on a high-DPI window); when the caller has set
// SDL_RenderSetScale, SDL scales the geometry itself and it is not scaled twice.

#include <cstddef>
#include <vector>

#include <SDL.h>
#include <imgui.h>

namespace psb::app {

class ImGuiRenderer {
  public:
    /// The renderer backend of the current ImGui context: makes the font atlas texture of its
    /// fonts on `renderer` and stores it as the atlas's texture id. Throws std::runtime_error
    /// with SDL's reason. Every member works on the current context.
    explicit ImGuiRenderer(SDL_Renderer* renderer);
    ~ImGuiRenderer();
    ImGuiRenderer(const ImGuiRenderer&) = delete;
    ImGuiRenderer& operator=(const ImGuiRenderer&) = delete;

    /// Remakes the font texture after fonts were added to the current context's atlas.
    void rebuildFontTexture();

    /// Draws one frame of ImGui output onto the renderer's current target. Returns the number
    /// of SDL_RenderGeometryRaw calls that failed (0 when all were drawn).
    int render(const ImDrawData& data);

    [[nodiscard]] SDL_Texture* fontTexture() const { return font_; }

  private:
    void destroyFontTexture();
    /// Draws one command's `n` indices (into `vertices`, `count` of them). Returns failures.
    int drawCommand(const SDL_Vertex* vertices, int count, const ImDrawIdx* indices, std::size_t n,
                    SDL_Texture* texture);
    /// The rectangle from `topLeft` to `bottomRight` (one colour; texture coordinates at the two
    /// corners) filled or copied; false when it cannot be drawn that way exactly.
    bool drawRect(const SDL_Vertex& topLeft, const SDL_Vertex& bottomRight, SDL_Texture* texture);

    SDL_Renderer* renderer_;
    SDL_Texture* font_ = nullptr;
    SDL_FPoint white_{};  // the atlas's white pixel: shapes sample only it, glyphs do not
    int fontW_ = 0, fontH_ = 0;
    std::vector<SDL_Vertex> vertices_;  // one command list's vertices, converted
};

}  // namespace psb::app
