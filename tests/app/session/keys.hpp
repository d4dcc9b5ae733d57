#pragma once
// The commands the keys that step a value send (E, G, T, ',' and '.'), as the key map makes
// them from the session's state (platform/input.cpp), for tests that press those keys without
// SDL.

#include "session/physics_controls.hpp"
#include "session/session.hpp"

namespace psb::app::keys {

/// E (-1) or Shift+E (+1).
[[nodiscard]] inline Command restitution(const Session& s, int direction) {
    return restitutionStep(s.world().def().restitution, direction);
}
/// G.
[[nodiscard]] inline Command gravity(const Session& s) {
    return gravityToggle(s.world().def().gravity, s.loadedWorld().def().gravity);
}
/// T.
[[nodiscard]] inline Command mode(const Session& s) {
    return modeStep(s.world().solver());
}
/// ',' (0.5) and '.' (2).
[[nodiscard]] inline Command timeSpeed(const Session& s, double factor) {
    return cmd::SetTimeScale{s.timeScale() * factor};
}

}  // namespace psb::app::keys
