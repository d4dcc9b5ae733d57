#pragma once
// The keys that step a value of the world (E, Shift+E, G, T): each sends the control panel's
// Set... command (command.hpp) with the value the step leads to, so that a key and the panel
// share one command, one rule and one message.
//
// Gravity: G switches it off, or on to the scene's own gravity when the scene as loaded had one,
// otherwise to Earth's 9.81 m/s² downwards. It is never scaled with the box: scenes are at the
// scale of what they show (the default is the original's at 1 px = 1 cm, a 7 m box).
//
// Every mode has gravity, the exact one included.

#include <string>

#include <particle_sandbox/axes.hpp>
#include <particle_sandbox/math.hpp>
#include <particle_sandbox/solver_settings.hpp>

#include "session/command.hpp"

namespace psb::app {

/// E / Shift+E presses from 0 to 1 (a step of 0.05).
inline constexpr int kRestitutionSteps = 20;
inline constexpr double kEarthGravity = 9.81;  ///< m/s²
/// Substeps per dt the mode key uses when it switches to substep mode from a solver with fewer
/// than two (one substep would be the discrete mode again).
inline constexpr int kAppSubsteps = 4;

/// `e` moved one step (direction -1 or +1) on the 0.05 grid, within [0, 1]: the double
/// nearest the grid's decimal (0.7, not 14 × 0.05 = 0.7000000000000001, which a saved scene
/// would show).
[[nodiscard]] double steppedRestitution(double e, int direction);
/// What E (-1) and Shift+E (+1) send for a world of restitution `e`.
[[nodiscard]] cmd::SetRestitution restitutionStep(double e, int direction);

/// The gravity G turns on for a world without a scene gravity: 9.81 m/s² down (y down).
[[nodiscard]] Vec2 appGravity();
/// What G sends for a world of gravity `gravity` whose scene as loaded had `sceneGravity`:
/// off when it is on; otherwise `sceneGravity` if it is not zero, else appGravity.
[[nodiscard]] cmd::SetGravity gravityToggle(const Vec2& gravity, const Vec2& sceneGravity);
/// The gravity `c` asks for (zero when off).
[[nodiscard]] Vec2 gravityOf(const cmd::SetGravity& c);

/// The mode the mode key selects after `mode`: discrete -> substep -> exact -> discrete.
[[nodiscard]] StepMode nextMode(StepMode mode);
/// What T sends for a world stepped by `solver`: the next mode, keeping the scene's substeps
/// (kAppSubsteps when it has fewer than two).
[[nodiscard]] cmd::SetMode modeStep(const SolverSettings& solver);

/// "off" or "[gx, gy] m/s^2" in `axes` (y up: Earth's is [0, -9.81]), for the messages.
[[nodiscard]] std::string gravityText(const Vec2& g, const Axes& axes);
/// "discrete", "substep x4", "exact".
[[nodiscard]] std::string modeName(const SolverSettings& solver);

}  // namespace psb::app
