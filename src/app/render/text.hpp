#pragma once
// Text with SDL2_ttf, drawn from a glyph atlas. Labels and the HUD change every frame (numbers),
// so caching rendered strings would miss; instead every printable Latin-1 glyph (ASCII and
// U+00A0–U+00FF: µ, ², °, ±, ×, é ...) and the few others the app writes (Font::kExtras: the
// ellipsis, dashes, the minus sign, an arrow, Greek letters) is rendered once into one texture,
// and a string (UTF-8) becomes textured quads in a GeometryBatch: all the text of a frame costs
// one draw call per font.

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
    /// pixels. `text` is UTF-8; a character outside printable Latin-1 and kExtras (or a
    /// malformed byte) shows as '?'.
    void layout(std::string_view text, float x, float y, SDL_Color color,
                GeometryBatch& batch) const;
    /// Draws a batch built with layout() (one SDL_RenderGeometry call).
    void draw(const GeometryBatch& batch) const;

    /// The characters beyond Latin-1 the atlas holds: what the app's messages, labels and
    /// readings write (a message shortened to its band ended in a '?' where its "…" was).
    static constexpr std::array<char32_t, 31> kExtras = {
        0x2026, 0x2013, 0x2014, 0x2212, 0x2192, 0x0394, 0x03B1, 0x03B2, 0x03B3, 0x03B4, 0x03B5,
        0x03B6, 0x03B7, 0x03B8, 0x03B9, 0x03BA, 0x03BB, 0x03BC, 0x03BD, 0x03BE, 0x03BF, 0x03C0,
        0x03C1, 0x03C2, 0x03C3, 0x03C4, 0x03C5, 0x03C6, 0x03C7, 0x03C8, 0x03C9};
    /// Whether the atlas has a glyph of `code` (a Unicode code point).
    [[nodiscard]] static bool drawable(char32_t code);

  private:
    struct Glyph {
        SDL_Rect atlas{};  ///< where the glyph's image is in the atlas, pixels
        int advance = 0;
    };
    static constexpr int kFirst = 32, kLast = 255;
    static constexpr std::size_t kGlyphs = kLast - kFirst + 1 + kExtras.size();
    /// The glyph's place in glyphs_, or npos for a character the atlas does not hold.
    [[nodiscard]] static std::size_t slot(char32_t code);
    /// The glyph of the character that starts at text[i]; advances i past it.
    [[nodiscard]] const Glyph& next(std::string_view text, std::size_t& i) const;

    SDL_Renderer* renderer_;
    TTF_Font* font_ = nullptr;
    SDL_Texture* atlas_ = nullptr;
    int atlasW_ = 1, atlasH_ = 1;
    int lineHeight_ = 0;
    std::array<Glyph, kGlyphs> glyphs_{};
};

}  // namespace psb::app
