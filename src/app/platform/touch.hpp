#pragma once
// Two fingers pan and pinch-zoom (the web build, for tablets and touch Chromebooks). One finger
// is the left mouse button already: SDL turns it into mouse events, which the control panel and
// Input take as they take the mouse's (grab, fling, launch). A second finger ends that drag where
// the mouse is, and from then on, until every finger is lifted, the mouse events that SDL makes
// of the fingers are ignored and the two fingers pan (their midpoint moves the world) and zoom
// (about the midpoint, by the change of their distance).

#include <map>
#include <vector>

#include <SDL.h>

#include <particle_sandbox/math.hpp>

#include "session/command.hpp"

namespace psb::app {

/// Whether the app reads gestures: the web build; a desktop's touch stays SDL's mouse alone.
#ifdef __EMSCRIPTEN__
inline constexpr bool kTouchGestures = true;
#else
inline constexpr bool kTouchGestures = false;
#endif

class TouchGestures {
  public:
    /// The commands a finger event means. `output` is the drawable size, pixels (SDL gives
    /// finger positions as fractions of the window); `mouse` where the mouse is, pixels.
    [[nodiscard]] std::vector<Command> translate(const SDL_TouchFingerEvent& e, SDL_Point output,
                                                 Vec2 mouse);
    /// Two fingers are (or were, some still down) on the screen: the mouse events SDL makes of
    /// fingers mean nothing now.
    [[nodiscard]] bool pinching() const { return pinching_; }

  private:
    [[nodiscard]] Vec2 midpoint() const;
    [[nodiscard]] double spread() const;

    std::map<SDL_FingerID, Vec2> fingers_;  ///< down now, pixels
    bool pinching_ = false;
};

}  // namespace psb::app
