#pragma once
// Restitution and gravity changed at run time (keys E, Shift+E and G). Each returns a message for
// the screen and leaves the world unchanged when the change is refused.
//
// Gravity: G switches it off, or on to the scene's own gravity when the scene as loaded had one,
// otherwise to Earth's 9.81 m/s² downwards. It is never scaled with the box: scenes are at the
// scale of what they show (the default is the original's at 1 px = 1 cm, a 7 m box).
//
// Every mode has gravity, the exact one included.

#include <string>

#include <particle_sandbox/world.hpp>

namespace psb::app {

/// Change per E / Shift+E press.
inline constexpr double kRestitutionStep = 0.05;
inline constexpr double kEarthGravity = 9.81;  ///< m/s²

struct ControlChange {
    bool changed = false;
    std::string message;
};

/// `e` moved one step (direction -1 or +1) on the 0.05 grid, within [0, 1].
[[nodiscard]] double steppedRestitution(double e, int direction);
/// Changes the world's restitution by one step down (-1) or up (+1).
ControlChange stepRestitution(World& world, int direction);

/// The gravity G turns on for a world without a scene gravity: 9.81 m/s² down (y down).
[[nodiscard]] Vec2 appGravity();
/// Gravity off when it is on; otherwise `sceneGravity` if it is not zero, else appGravity.
ControlChange toggleGravity(World& world, const Vec2& sceneGravity);

/// "off" or "[gx, gy] m/s^2", for the HUD and messages.
[[nodiscard]] std::string gravityText(const Vec2& g);

}  // namespace psb::app
