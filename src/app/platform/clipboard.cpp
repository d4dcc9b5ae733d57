#include "platform/clipboard.hpp"

#ifdef __EMSCRIPTEN__
#include <emscripten.h>

// The page's function (web/index.html), called if it has one; without it nothing is copied.
// clang-format off
EM_JS(int, psb_js_copy, (const char* text), {
    if (typeof psbCopy !== "function") return 0;
    psbCopy(UTF8ToString(text));
    return 1;
});
// clang-format on
#endif

namespace psb::app {

namespace {

/// The SDL event type of the page's answers (registered once; SDL hands out user types).
Uint32 answerType() {
    static const Uint32 type = SDL_RegisterEvents(1);
    return type;
}

}  // namespace

std::optional<cmd::ClipboardResult> putOnClipboard(const std::string& text) {
#ifdef __EMSCRIPTEN__
    (void)answerType();  // registered before any answer can come
    if (psb_js_copy(text.c_str()) == 0) {
        return cmd::ClipboardResult{false, "the page cannot reach the clipboard"};
    }
    return std::nullopt;
#else
    if (SDL_SetClipboardText(text.c_str()) != 0) {
        return cmd::ClipboardResult{false, std::string(SDL_GetError())};
    }
    return cmd::ClipboardResult{true, {}};
#endif
}

std::optional<cmd::ClipboardResult> clipboardResult(const SDL_Event& e) {
    if (e.type != answerType() || e.type == static_cast<Uint32>(-1)) return std::nullopt;
    cmd::ClipboardResult r{e.user.code != 0, {}};
    if (e.user.data1 != nullptr) {
        r.why = static_cast<const char*>(e.user.data1);
        SDL_free(e.user.data1);
    }
    return r;
}

std::string clipboardText() {
    char* text = SDL_GetClipboardText();
    if (text == nullptr) return {};
    std::string out(text);
    SDL_free(text);
    return out;
}

}  // namespace psb::app

#ifdef __EMSCRIPTEN__
/// The browser's answer to psbCopy: `copied` (1) or not, and why not (its words).
extern "C" EMSCRIPTEN_KEEPALIVE void psb_web_copied(int copied, const char* why) {
    SDL_Event e{};
    e.type = psb::app::answerType();
    e.user.code = copied;
    e.user.data1 = why != nullptr && *why != '\0' ? SDL_strdup(why) : nullptr;
    SDL_PushEvent(&e);
}
#endif
