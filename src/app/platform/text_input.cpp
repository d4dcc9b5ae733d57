#include "platform/text_input.hpp"

#include <algorithm>
#include <cstring>
#include <string>

#include <SDL.h>

#ifdef __EMSCRIPTEN__
#include <emscripten.h>

// The page's function (web/index.html), called if it has one.
// clang-format off
EM_JS(void, psb_js_typing, (int on), {
    if (typeof psbTyping === "function") psbTyping(!!on);
});
EM_JS(void, psb_js_typing_at, (float x, float y, float w, float h), {
    if (typeof psbTypingAt === "function") psbTypingAt(x, y, w, h);
});
// clang-format on
#endif

namespace psb::app {

void setTextInput(bool on) {
    if (on) {
        SDL_StartTextInput();
    } else {
        SDL_StopTextInput();
    }
#ifdef __EMSCRIPTEN__
    psb_js_typing(on ? 1 : 0);
#endif
}

void placeTextInput([[maybe_unused]] float x, [[maybe_unused]] float y, [[maybe_unused]] float w,
                    [[maybe_unused]] float h) {
#ifdef __EMSCRIPTEN__
    psb_js_typing_at(x, y, w, h);
#endif
}

}  // namespace psb::app

#ifdef __EMSCRIPTEN__
/// The page's typing field took `text` (UTF-8) from an on-screen keyboard: SDL's text events, as
/// a real keyboard's keys would make them (SDL_TEXTINPUT holds 31 bytes; longer text is split
/// between whole characters).
extern "C" EMSCRIPTEN_KEEPALIVE void psb_web_type(const char* text) {
    if (text == nullptr || SDL_IsTextInputActive() == SDL_FALSE) return;
    constexpr std::size_t kRoom = sizeof(SDL_TextInputEvent::text) - 1;
    const std::string all(text);
    std::size_t at = 0;
    while (at < all.size()) {
        std::size_t n = std::min(kRoom, all.size() - at);
        // Back to the start of a character: a UTF-8 continuation byte is 10xxxxxx.
        while (n > 0 && at + n < all.size() &&
               (static_cast<unsigned char>(all[at + n]) & 0xC0) == 0x80)
            --n;
        SDL_Event e{};
        e.type = SDL_TEXTINPUT;
        e.text.timestamp = SDL_GetTicks();
        std::memcpy(e.text.text, all.data() + at, n);
        e.text.text[n] = '\0';
        SDL_PushEvent(&e);
        at += n;
    }
}

/// The on-screen keyboard's delete: a Backspace pressed and released (such keyboards send no
/// key the page can read, only the field's change).
extern "C" EMSCRIPTEN_KEEPALIVE void psb_web_backspace() {
    for (const Uint32 type : {SDL_KEYDOWN, SDL_KEYUP}) {
        SDL_Event e{};
        e.type = type;
        e.key.timestamp = SDL_GetTicks();
        e.key.state = type == SDL_KEYDOWN ? SDL_PRESSED : SDL_RELEASED;
        e.key.keysym.scancode = SDL_SCANCODE_BACKSPACE;
        e.key.keysym.sym = SDLK_BACKSPACE;
        SDL_PushEvent(&e);
    }
}
#endif
