#pragma once
// Text with SDL2_ttf, drawn from a glyph atlas. Labels and the HUD change every frame (numbers),
// so caching rendered strings would miss; instead every printable Latin-1 glyph (ASCII and
// U+00A0–U+00FF: µ, ², °, ±, ×, é ...) is rendered once into one texture, and a string (UTF-8)
// becomes textured quads in a GeometryBatch: all the text of a frame costs one draw call per
// font.

#include <array>
#include <filesystem>
#include <string_view>

#include <SDL.h>

#include "render/geometry_batch.hpp"
#include "view/text_measure.hpp"

typedef struct _TTF_Font TTF_Font;

namespace psb::app {

class Font final : public TextMeasure {
  public:
    /// Opens `path` at `pixelSize` and builds its atlas for `renderer`. Throws
    /// std::runtime_error naming the file when it cannot be opened.
    Font(SDL_Renderer* renderer, const std::filesystem::path& path, int pixelSize);
    ~Font() override;
    Font(const Font&) = delete;
    Font& operator=(const Font&) = delete;
    /// Exchanges two fonts' faces and atlases: a font made at a new size takes the place of one
    /// that others hold by reference (the UI's scale changed).
    friend void swap(Font& a, Font& b) noexcept;

    /// Distance between baselines, pixels.
    [[nodiscard]] int lineHeight() const override { return lineHeight_; }
    /// Width of `text` in pixels.
    [[nodiscard]] int measure(std::string_view text) const override;
    /// Appends the quads of `text` with its top-left corner at (x, y), pixels, rounded to whole
    /// pixels. `text` is UTF-8; a character outside printable Latin-1 (or a malformed byte)
    /// shows as '?'.
    void layout(std::string_view text, float x, float y, SDL_Color color,
                GeometryBatch& batch) const;
    /// Draws a batch built with layout() (one SDL_RenderGeometry call).
    void draw(const GeometryBatch& batch) const;

  private:
    struct Glyph {
        SDL_Rect atlas{};  ///< where the glyph's image is in the atlas, pixels
        int advance = 0;
    };
    static constexpr int kFirst = 32, kLast = 255;
    /// The glyph of the character that starts at text[i]; advances i past it.
    [[nodiscard]] const Glyph& next(std::string_view text, std::size_t& i) const;

    SDL_Renderer* renderer_;
    TTF_Font* font_ = nullptr;
    SDL_Texture* atlas_ = nullptr;
    int atlasW_ = 1, atlasH_ = 1;
    int lineHeight_ = 0;
    std::array<Glyph, kLast - kFirst + 1> glyphs_{};
};

}  // namespace psb::app
