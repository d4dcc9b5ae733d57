#pragma once
// SDL events to commands: the key map and the mouse. The only input code that knows SDL; what
// an event means is decided here, what it does is the session's (Session::apply).
//
// Keys repeat only where repeating makes sense (pan, single step, spawn mass, stepping through
// time, undo and redo); a held Space or S
// must not flicker. While the edit prompt is open only its keys (Tab, Backspace, Enter, Esc) and
// F12 mean anything, and typed characters arrive as text.

#include <vector>

#include <SDL.h>

#include <particle_sandbox/math.hpp>
#include <particle_sandbox/solver_settings.hpp>

#include "platform/touch.hpp"
#include "session/command.hpp"
#include "session/dialog.hpp"
#include "session/view_options.hpp"

namespace psb::app {

class Session;

/// What the keys read from the session: whether the prompt has the keyboard, and the values
/// the keys that step one (E, G, T, ',' and '.') step from.
struct KeyState {
    bool editing = false;  ///< the edit prompt is open
    /// The dialog open (its keys: Enter answers with the default, Esc cancels), its proposal
    /// and defaults.
    Dialog dialog = {};
    double restitution = 1.0;
    Vec2 gravity = Vec2::Zero();
    Vec2 sceneGravity = Vec2::Zero();  ///< of the scene as loaded
    SolverSettings solver = {};
    double timeScale = 1.0;
    ViewOptions view = {};   ///< what is shown (the keys that show or hide something flip it)
    bool recording = false;  ///< trajectories are being recorded (X stops, else starts)
};
/// The session's KeyState now.
[[nodiscard]] KeyState keyState(const Session& session);

/// Pan per arrow key press, pixels (the original panned by 50 / zoom world units).
inline constexpr double kPanKeyPixels = 50.0;
/// Simulated seconds PageUp / PageDown go back / forward through the recorded past.
inline constexpr double kSeekKeySeconds = 1.0;
/// Zoom factor per wheel notch.
inline constexpr double kWheelZoomStep = 1.15;

/// The command a key press means (none for an unbound key or a repeat that should not repeat),
/// in the state `state`.
[[nodiscard]] std::vector<Command> commandsForKey(const SDL_KeyboardEvent& key,
                                                  const KeyState& state);

class Input {
  public:
    /// The commands `e` means. `pixelRatio` is drawable pixels per window point (mouse events
    /// come in points, the camera works in pixels); `output` is the drawable size, pixels.
    [[nodiscard]] std::vector<Command> translate(const SDL_Event& e, const KeyState& state,
                                                 double pixelRatio, SDL_Point output);

  private:
    TouchGestures touch_;        ///< two fingers (the web build)
    bool panning_ = false;       ///< right or middle button held
    Vec2 mouse_ = Vec2::Zero();  ///< pixels
};

}  // namespace psb::app
