#pragma once
// The app's step of its world, the one its frames and its timeline's replays both take. A
// measurement steps without an event budget (World::step finishes exactly, however long); a
// window's frame must end, so in the exact mode a step that would take more than
// kFrameEventsPerParticle events per particle ends at its first event left. The state shown is
// then exact but behind the time asked for; the clock (sim_clock.hpp) counts that frame as
// falling behind, and the HUD shows the speed reached.

#include <cstdint>

#include <particle_sandbox/world.hpp>

namespace psb::app {

/// Ten thousand events per particle in one frame: 10⁴ wall hits of a lone disc, or 10⁶ in all
/// in a 100-disc gas (about a second of computing), far more than any preset takes.
inline constexpr std::uint64_t kFrameEventsPerParticle = 10000;

/// Steps `world` by `dt` under the frame's event budget; returns the seconds simulated.
inline double stepFrame(World& world, double dt) {
    world.setExactEventBudget(kFrameEventsPerParticle);
    return world.step(dt);
}

}  // namespace psb::app
