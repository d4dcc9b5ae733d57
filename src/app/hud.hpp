#pragma once
// What the player reads: the title, the status lines at the top-left, the help overlay and
// short messages. The text is made here without SDL (so it is tested as plain strings); the
// app draws it with a Font.

#include <string>
#include <utility>
#include <vector>

#include <particle_sandbox/math.hpp>
#include <particle_sandbox/solver_settings.hpp>
#include <particle_sandbox/step_profile.hpp>

namespace psb::app {

/// The numbers the HUD shows.
struct HudData {
    double fps = 0.0;
    double simTime = 0.0;    ///< seconds
    double timeScale = 1.0;  ///< simulated seconds per real second asked for
    /// Simulated seconds per real second reached (below timeScale when the steps cannot keep up).
    double reachedTimeScale = 1.0;
    std::size_t particles = 0;
    double kineticEnergy = 0.0;    ///< J
    Vec2 momentum = Vec2::Zero();  ///< kg·m/s
    double spawnMass = 0.0;        ///< kg
    double spawnRadius = 0.0;      ///< m
    double arrowSeconds = 0.0;     ///< arrow length per unit speed, s; 0 when arrows are off
    bool paused = false;
    double stepMs = 0.0;      ///< wall-clock ms of simulation per frame
    double drawMs = 0.0;      ///< wall-clock ms of drawing per frame
    std::string renderer;     ///< the render driver, e.g. "software"; "" not shown
    std::string mode;         ///< stepping mode, e.g. "substep x4"
    std::string broadphase;   ///< the broadphase in use ("grid", ...; the exact mode's cells)
    int threads = 1;          ///< threads the step may use
    double maxOverlap = 0.0;  ///< deepest overlap met by the last frame's steps, m
    double keDrift = 0.0;     ///< relative drift of the monitored energy since the last user
                              ///< action (monitoredEnergy); NaN: none
    std::string driftName = "KE drift";  ///< which energy: "KE drift", or "KE+PE drift"
    std::string overlays;         ///< analysis overlays that are on, e.g. "V L:all K D"; "" none
    double restitution = 1.0;     ///< the world's coefficient of restitution
    std::string gravity = "off";  ///< the world's gravity, as physics_controls' gravityText
    bool past = false;            ///< a recorded past frame is shown
    double secondsBack = 0.0;     ///< how far back it is, s
};

/// What the profile overlay shows.
struct ProfileData {
    StepProfile profile;  ///< the last step's stages (World::profile())
    StepMode mode = StepMode::Discrete;
    double eventsPerStep = 0.0;  ///< exact mode: events per step
    double frameStepMs = 0.0;    ///< wall-clock ms of simulation in the last frame
    double frameDrawMs = 0.0;    ///< wall-clock ms of drawing in the last frame
};

/// The window title: `Particle Sandbox - N particles`, plus ` - PAUSED`, plus ` - SCENE`
/// when a scene name is given.
[[nodiscard]] std::string windowTitle(std::size_t particles, bool paused,
                                      const std::string& scene = {});

/// The status lines, top to bottom. While paused the loop sleeps until an event, so the first
/// line gives the cost of a frame instead of a frame rate that only counts redraws; a time speed
/// the steps cannot keep up with shows what is reached.
[[nodiscard]] std::vector<std::string> hudLines(const HudData& d);

/// The profile overlay, one line per stage then the frame's step and draw times.
[[nodiscard]] std::vector<std::string> profileLines(const ProfileData& d);

/// Every control, as (keys, what it does), in the order the help overlay shows them.
[[nodiscard]] const std::vector<std::pair<std::string, std::string>>& controls();

/// The help overlay, one line per control.
[[nodiscard]] std::vector<std::string> helpLines();

}  // namespace psb::app
