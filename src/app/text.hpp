#pragma once
// Text with SDL2_ttf, drawn from a glyph atlas. Labels and the HUD change every frame (numbers),
// so caching rendered strings would miss; instead every printable ASCII glyph is rendered once
// into one texture, and a string becomes textured quads in a GeometryBatch: all the text of a
// frame costs one draw call per font.

#include <array>
#include <filesystem>
#include <string_view>

#include <SDL.h>

#include "geometry_batch.hpp"

typedef struct _TTF_Font TTF_Font;

namespace psb::app {

class Font {
  public:
    /// Opens `path` at `pixelSize` and builds its atlas for `renderer`. Throws
    /// std::runtime_error naming the file when it cannot be opened.
    Font(SDL_Renderer* renderer, const std::filesystem::path& path, int pixelSize);
    ~Font();
    Font(const Font&) = delete;
    Font& operator=(const Font&) = delete;

    /// Distance between baselines, pixels.
    [[nodiscard]] int lineHeight() const { return lineHeight_; }
    /// Width of `text` in pixels.
    [[nodiscard]] int measure(std::string_view text) const;
    /// Appends the quads of `text` with its top-left corner at (x, y), pixels, rounded to whole
    /// pixels. Characters outside printable ASCII show as '?'.
    void layout(std::string_view text, float x, float y, SDL_Color color,
                GeometryBatch& batch) const;
    /// Draws a batch built with layout() (one SDL_RenderGeometry call).
    void draw(const GeometryBatch& batch) const;

  private:
    struct Glyph {
        SDL_Rect atlas{};  ///< where the glyph's image is in the atlas, pixels
        int advance = 0;
    };
    static constexpr int kFirst = 32, kLast = 126;
    [[nodiscard]] const Glyph& glyph(char c) const;

    SDL_Renderer* renderer_;
    TTF_Font* font_ = nullptr;
    SDL_Texture* atlas_ = nullptr;
    int atlasW_ = 1, atlasH_ = 1;
    int lineHeight_ = 0;
    std::array<Glyph, kLast - kFirst + 1> glyphs_{};
};

}  // namespace psb::app
