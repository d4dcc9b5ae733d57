#pragma once
// The commands the keys that step or flip a value send (E, G, T, ',' '.', A, S, V, L, K, D, O), as
// the key map makes them from the session's state (platform/input.cpp), for tests that press those
// keys without SDL.

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

/// A, S, V, K, D, O: `option` flipped.
[[nodiscard]] inline Command show(const Session& s, ShowOption option) {
    return cmd::SetShow{option, !s.view().shown(option)};
}
/// L: the next trail mode.
[[nodiscard]] inline Command trails(const Session& s) {
    return cmd::SetTrails{static_cast<int>(nextTrailMode(s.view().trails))};
}

}  // namespace psb::app::keys
