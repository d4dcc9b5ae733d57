#pragma once
// What the player reads: the title, the status lines at the top-left, the help overlay and
// short messages. The text is made here without SDL (so it is tested as plain strings); the
// app draws it with a Font.

#include <string>
#include <utility>
#include <vector>

#include <particle_sandbox/math.hpp>

namespace psb::app {

/// The numbers the HUD shows.
struct HudData {
    double fps = 0.0;
    double simTime = 0.0;    ///< seconds
    double timeScale = 1.0;  ///< simulated seconds per real second
    std::size_t particles = 0;
    double kineticEnergy = 0.0;    ///< J
    Vec2 momentum = Vec2::Zero();  ///< kg·m/s
    double spawnMass = 0.0;        ///< kg
    double spawnRadius = 0.0;      ///< m
    double arrowSeconds = 0.0;     ///< arrow length per unit speed, s; 0 when arrows are off
    bool paused = false;
    double stepMs = 0.0;  ///< wall-clock ms of simulation per frame
    double drawMs = 0.0;  ///< wall-clock ms of drawing per frame
};

/// The window title: `Particle Sandbox - N particles`, plus ` - PAUSED`, plus ` - SCENE`
/// when a scene name is given.
[[nodiscard]] std::string windowTitle(std::size_t particles, bool paused,
                                      const std::string& scene = {});

/// The status lines, top to bottom.
[[nodiscard]] std::vector<std::string> hudLines(const HudData& d);

/// Every control, as (keys, what it does), in the order the help overlay shows them.
[[nodiscard]] const std::vector<std::pair<std::string, std::string>>& controls();

/// The help overlay, one line per control.
[[nodiscard]] std::vector<std::string> helpLines();

}  // namespace psb::app
