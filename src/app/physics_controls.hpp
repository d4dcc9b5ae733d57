#pragma once
// Restitution and gravity changed at run time (keys E, Shift+E and G). Each returns a message for
// the screen and leaves the world unchanged when the change is refused.
//
// Gravity: G switches it off, or on to the scene's own gravity when the scene as loaded had one,
// otherwise to appGravity(): Earth's 9.81 m/s² downwards in a box of human scale (up to 20 m),
// scaled up with the box beyond that. A 700 m box is the original's 700-pixel window rather than
// a real 700 m, and under 9.81 m/s² a fall across it would take 12 s; scaled, a fall across any
// box larger than 20 m takes the 2 s it takes across a 20 m box.
//
// Every mode has gravity, the exact one included.

#include <string>

#include <particle_sandbox/world.hpp>

namespace psb::app {

/// Change per E / Shift+E press.
inline constexpr double kRestitutionStep = 0.05;
/// Largest box side (m) that gets Earth's gravity unscaled.
inline constexpr double kHumanScaleBox = 20.0;
inline constexpr double kEarthGravity = 9.81;  ///< m/s²

struct ControlChange {
    bool changed = false;
    std::string message;
};

/// `e` moved one step (direction -1 or +1) on the 0.05 grid, within [0, 1].
[[nodiscard]] double steppedRestitution(double e, int direction);
/// Changes the world's restitution by one step down (-1) or up (+1).
ControlChange stepRestitution(World& world, int direction);

/// The gravity G turns on for a world without a scene gravity, m/s² (y down).
[[nodiscard]] Vec2 appGravity(const WorldDef& def);
/// Gravity off when it is on; otherwise `sceneGravity` if it is not zero, else appGravity.
ControlChange toggleGravity(World& world, const Vec2& sceneGravity);

/// "off" or "[gx, gy] m/s^2", for the HUD and messages.
[[nodiscard]] std::string gravityText(const Vec2& g);

}  // namespace psb::app
