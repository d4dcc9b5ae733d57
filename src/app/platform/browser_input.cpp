#include "platform/browser_input.hpp"

#include <cmath>

#include <SDL.h>
#include <emscripten.h>

namespace psb::app {

namespace {

/// How long ago the browser received the DOM event whose handler runs now, milliseconds (0
/// outside a pointer's handler, or from a page that does not say).
// clang-format off
EM_JS(double, psb_js_event_lag, (), {
    return typeof psbEventLag === "number" && psbEventLag > 0 ? psbEventLag : 0;
});
// clang-format on

int stamp(void*, SDL_Event* e) {
    switch (e->type) {
        case SDL_MOUSEMOTION:
        case SDL_MOUSEBUTTONDOWN:
        case SDL_MOUSEBUTTONUP:
        case SDL_FINGERDOWN:
        case SDL_FINGERMOTION:
        case SDL_FINGERUP: {
            const auto lag = static_cast<Uint32>(std::lround(psb_js_event_lag()));
            if (lag < e->common.timestamp) e->common.timestamp -= lag;
            break;
        }
        default:
            break;
    }
    return 1;
}

}  // namespace

void stampPointerEventsWithBrowserTimes() {
    SDL_AddEventWatch(stamp, nullptr);
}

}  // namespace psb::app
