#pragma once
// The hand (interaction.hpp) only reads the world; these apply what it means as the session
// does (session_hand.cpp), for tests of the hand without a session.

#include <optional>

#include <particle_sandbox/world.hpp>

#include "session/interaction.hpp"

namespace psb::app {

/// A press: a grabbed particle is kinematic while held.
inline void press(Interaction& in, World& w, const Vec2& point, double time, bool grab = true) {
    if (const auto id = in.press(w, point, time, grab)) w.setKinematic(*id, true);
}

/// The held particle to the hand.
inline void applyHold(const Interaction& in, World& w, double now, const LaunchSettings& ls) {
    if (const auto h = in.hold(w, now, ls)) {
        w.setPosition(h->id, h->position);
        w.setVelocity(h->id, h->velocity);
    }
}

/// A release: a held particle let go, a launched one added (its id in the result).
inline ReleaseResult release(Interaction& in, World& w, const Vec2& point, double time,
                             const SpawnSettings& spawn, const LaunchSettings& ls,
                             double launchSeconds) {
    ReleaseResult r = in.release(w, point, time, spawn, ls, launchSeconds);
    if (r.letGo) {
        w.setPosition(r.id, r.position);
        w.setVelocity(r.id, r.velocity);
        w.setKinematic(r.id, false);
    }
    if (r.kind == ReleaseResult::Kind::Launched) r.id = w.add(r.launch);
    return r;
}

/// Backspace while holding: the held particle removed; its last state.
inline std::optional<Particle> deleteHeld(Interaction& in, World& w) {
    if (in.mode() != Interaction::Mode::Holding || !w.contains(in.held())) return std::nullopt;
    const Particle p = w.get(in.held());
    w.remove(in.held());
    in.reset();
    return p;
}

}  // namespace psb::app
