// The glyph atlas: every character the Font draws is its glyph as SDL_ttf renders it, whole,
// pixel for pixel, at the sizes the app uses.

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>
#include <vector>

#include <SDL_ttf.h>

#include "platform/assets.hpp"
#include "render/offscreen_test.hpp"
#include "render/text.hpp"

namespace psb::app {
namespace {

class TextTest : public OffscreenTest {
  protected:
    TextTest() : OffscreenTest(64) {}

    /// The red channel of pixel (x, y) (white text on black: the glyph's coverage).
    [[nodiscard]] int coverage(int x, int y) const { return pixel(x, y).r; }
    void clear() {
        SDL_SetRenderDrawColor(sdl_, 0, 0, 0, 255);
        SDL_RenderClear(sdl_);
    }
};

std::string utf8(int code) {
    if (code < 0x80) return std::string(1, static_cast<char>(code));
    if (code < 0x800) {
        return {static_cast<char>(0xC0 | (code >> 6)), static_cast<char>(0x80 | (code & 0x3F))};
    }
    return {static_cast<char>(0xE0 | (code >> 12)), static_cast<char>(0x80 | ((code >> 6) & 0x3F)),
            static_cast<char>(0x80 | (code & 0x3F))};
}

TEST_F(TextTest, EveryGlyphIsDrawnWholeAtTheAppsSizes) {
    ASSERT_EQ(TTF_Init(), 0);
    const std::filesystem::path path = findAsset("fonts/DejaVuSansMono.ttf");
    for (const int size : {12, 14}) {
        const Font font(sdl_, path, size);
        TTF_Font* ttf = TTF_OpenFont(path.string().c_str(), size);
        ASSERT_NE(ttf, nullptr);
        int wrong = 0;
        // Latin-1, and the characters beyond it the app writes: a shortened message's "…" was
        // a '?'.
        std::vector<int> codes;
        for (int code = 33; code <= 255; ++code) {
            if (code <= 126 || code >= 161) codes.push_back(code);
        }
        for (const char32_t code : Font::kExtras)
            codes.push_back(static_cast<int>(code));
        for (const int code : codes) {
            if (wrong >= 5) break;
            // The glyph as SDL_ttf renders it, copied unscaled: the reference.
            SDL_Surface* image = TTF_RenderGlyph32_Blended(ttf, static_cast<Uint32>(code),
                                                           SDL_Color{255, 255, 255, 255});
            if (image == nullptr) continue;  // no glyph (the soft hyphen): nothing drawn
            SDL_Texture* t = SDL_CreateTextureFromSurface(sdl_, image);
            SDL_SetTextureBlendMode(t, SDL_BLENDMODE_BLEND);
            const SDL_Rect at{10, 10, image->w, image->h};
            clear();
            SDL_RenderCopy(sdl_, t, nullptr, &at);
            SDL_RenderPresent(sdl_);
            std::vector<int> want;
            for (int y = 0; y < at.h; ++y)
                for (int x = 0; x < at.w; ++x)
                    want.push_back(coverage(at.x + x, at.y + y));
            SDL_DestroyTexture(t);
            SDL_FreeSurface(image);

            clear();
            GeometryBatch batch;
            font.layout(utf8(code), 10.f, 10.f, SDL_Color{255, 255, 255, 255}, batch);
            font.draw(batch);
            SDL_RenderPresent(sdl_);
            int differ = 0;
            for (int y = 0; y < at.h; ++y)
                for (int x = 0; x < at.w; ++x)
                    differ += std::abs(coverage(at.x + x, at.y + y) -
                                       want[static_cast<std::size_t>(y * at.w + x)]) > 8;
            if (differ > 0) {
                ++wrong;
                ADD_FAILURE() << "character " << code << " ('" << utf8(code) << "') at " << size
                              << " px: " << differ << " pixels differ from its glyph";
            }
        }
        TTF_CloseFont(ttf);
    }
    TTF_Quit();
}

}  // namespace
}  // namespace psb::app
