#include "render/text.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include <SDL_ttf.h>

namespace psb::app {
namespace {

/// ASCII and Latin-1 characters that draw something (not the C0/C1 controls).
constexpr bool printable(int code) {
    return (code >= 32 && code <= 126) || (code >= 160 && code <= 255);
}

}  // namespace

std::size_t Font::slot(char32_t code) {
    if (code >= kFirst && code <= kLast) {
        return printable(static_cast<int>(code)) ? code - kFirst : std::string_view::npos;
    }
    for (std::size_t k = 0; k < kExtras.size(); ++k) {
        if (kExtras[k] == code) return kLast - kFirst + 1 + k;
    }
    return std::string_view::npos;
}

bool Font::drawable(char32_t code) {
    return slot(code) != std::string_view::npos;
}

Font::Font(SDL_Renderer* renderer, const std::filesystem::path& path, int pixelSize)
    : renderer_(renderer) {
    // TTF_Init is reference counted, so each Font holds one reference.
    if (TTF_Init() != 0) throw std::runtime_error(std::string("TTF_Init: ") + TTF_GetError());
    font_ = TTF_OpenFont(path.string().c_str(), pixelSize);
    if (font_ == nullptr) {
        const std::string why = TTF_GetError();
        TTF_Quit();
        throw std::runtime_error("cannot open font " + path.string() + ": " + why);
    }
    lineHeight_ = TTF_FontLineSkip(font_);

    // Render each glyph, then pack them in rows of an atlas whose sides are powers of two: a
    // texel's edge u = x / width is then exact in a float, and so is u × width. With any other
    // width SDL's software renderer, which truncates u × width to a texel, took some glyphs'
    // left edges one texel early and dropped a column ("(" in "energy (J)" lost its stroke).
    std::array<SDL_Surface*, kGlyphs> images{};
    int atlasWidth = 512;
    const auto codeOf = [](std::size_t k) {
        return k < static_cast<std::size_t>(kLast - kFirst + 1) ? static_cast<char32_t>(kFirst + k)
                                                                : kExtras[k - (kLast - kFirst + 1)];
    };
    for (std::size_t k = 0; k < kGlyphs; ++k) {
        const char32_t c = codeOf(k);
        if (slot(c) != k) continue;
        SDL_Surface* s =
            TTF_RenderGlyph32_Blended(font_, static_cast<Uint32>(c), SDL_Color{255, 255, 255, 255});
        images[k] = s;
        int minx = 0, maxx = 0, miny = 0, maxy = 0, advance = 0;
        TTF_GlyphMetrics32(font_, static_cast<Uint32>(c), &minx, &maxx, &miny, &maxy, &advance);
        glyphs_[k].advance = advance;
        while (s != nullptr && s->w > atlasWidth)
            atlasWidth *= 2;
    }
    int x = 0, y = 0, rowHeight = 0;
    for (std::size_t k = 0; k < kGlyphs; ++k) {
        const SDL_Surface* s = images[k];
        if (s == nullptr) continue;
        if (x + s->w > atlasWidth) {  // a new row, one transparent texel below the last
            x = 0;
            y += rowHeight + 1;
            rowHeight = 0;
        }
        glyphs_[k].atlas = {x, y, s->w, s->h};
        x += s->w + 1;
        rowHeight = std::max(rowHeight, s->h);
    }
    int height = 1;
    while (height < y + rowHeight)
        height *= 2;
    SDL_Surface* atlas =
        SDL_CreateRGBSurfaceWithFormat(0, atlasWidth, height, 32, SDL_PIXELFORMAT_ARGB8888);
    if (atlas == nullptr) throw std::runtime_error(std::string("glyph atlas: ") + SDL_GetError());
    SDL_FillRect(atlas, nullptr, SDL_MapRGBA(atlas->format, 255, 255, 255, 0));
    for (std::size_t k = 0; k < kGlyphs; ++k) {
        SDL_Surface* s = images[k];
        if (s == nullptr) continue;
        SDL_SetSurfaceBlendMode(s, SDL_BLENDMODE_NONE);
        SDL_Rect dst = glyphs_[k].atlas;
        SDL_BlitSurface(s, nullptr, atlas, &dst);
        SDL_FreeSurface(s);
    }
    atlasW_ = atlas->w;
    atlasH_ = atlas->h;
    atlas_ = SDL_CreateTextureFromSurface(renderer_, atlas);
    SDL_FreeSurface(atlas);
    if (atlas_ == nullptr) {
        TTF_CloseFont(font_);
        TTF_Quit();
        throw std::runtime_error(std::string("glyph atlas texture: ") + SDL_GetError());
    }
    SDL_SetTextureBlendMode(atlas_, SDL_BLENDMODE_BLEND);
}

void swap(Font& a, Font& b) noexcept {
    std::swap(a.renderer_, b.renderer_);
    std::swap(a.font_, b.font_);
    std::swap(a.atlas_, b.atlas_);
    std::swap(a.atlasW_, b.atlasW_);
    std::swap(a.atlasH_, b.atlasH_);
    std::swap(a.lineHeight_, b.lineHeight_);
    std::swap(a.glyphs_, b.glyphs_);
}

Font::~Font() {
    SDL_DestroyTexture(atlas_);
    TTF_CloseFont(font_);
    TTF_Quit();
}

const Font::Glyph& Font::next(std::string_view text, std::size_t& i) const {
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
    char32_t code = byte(i++);
    if (code >= 0x80) {
        // UTF-8: a lead byte and its continuation bytes; a character the atlas does not hold,
        // a stray continuation byte or a sequence cut short shows one '?'.
        const int more = code >= 0xF0 ? 3 : code >= 0xE0 ? 2 : code >= 0xC0 ? 1 : -1;
        bool whole = more > 0;
        code &= more == 3 ? 0x07u : more == 2 ? 0x0Fu : 0x1Fu;
        for (int k = 0; k < more; ++k) {
            if (i >= text.size() || (byte(i) & 0xC0) != 0x80) {
                whole = false;
                break;
            }
            code = (code << 6) | (byte(i++) & 0x3Fu);
        }
        if (!whole) code = '?';
    }
    const std::size_t k = slot(code);
    return glyphs_[k != std::string_view::npos ? k : '?' - kFirst];
}

int Font::measure(std::string_view text) const {
    int w = 0;
    for (std::size_t i = 0; i < text.size();)
        w += next(text, i).advance;
    return w;
}

void Font::layout(std::string_view text, float x, float y, SDL_Color color,
                  GeometryBatch& batch) const {
    const float iw = 1.0f / static_cast<float>(atlasW_), ih = 1.0f / static_cast<float>(atlasH_);
    // Glyphs one to one with screen pixels: drawn at a fraction of a pixel, the renderer
    // resamples them and thin strokes vanish or double ("1800.00" read as "18CC.C0").
    x = std::round(x);
    y = std::round(y);
    for (std::size_t i = 0; i < text.size();) {
        const bool space = text[i] == ' ';
        const Glyph& g = next(text, i);
        if (g.atlas.w > 0 && !space) {
            const SDL_Rect& r = g.atlas;
            batch.quad(x, y, x + static_cast<float>(r.w), y + static_cast<float>(r.h), color,
                       static_cast<float>(r.x) * iw, static_cast<float>(r.y) * ih,
                       static_cast<float>(r.x + r.w) * iw, static_cast<float>(r.y + r.h) * ih);
        }
        x += static_cast<float>(g.advance);
    }
}

void Font::draw(const GeometryBatch& batch) const {
    batch.draw(renderer_, atlas_);
}

}  // namespace psb::app
