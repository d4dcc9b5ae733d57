#include "platform/clipboard.hpp"

#include <SDL.h>

namespace psb::app {

std::optional<std::string> putOnClipboard(const std::string& text) {
    if (SDL_SetClipboardText(text.c_str()) != 0) return std::string(SDL_GetError());
    return std::nullopt;
}

std::string clipboardText() {
    char* text = SDL_GetClipboardText();
    if (text == nullptr) return {};
    std::string out(text);
    SDL_free(text);
    return out;
}

}  // namespace psb::app
