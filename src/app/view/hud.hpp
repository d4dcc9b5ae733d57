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

/// The numbers the HUD shows: what must stay on the box while the control panel (which has the
/// rest, and the engine's figures) is open or folded.
struct HudData {
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
    /// The deepest overlap of particles now, m, shown while it is deeper than a twentieth of
    /// the scene's typical radius (a held particle pressed into others, a coarse step); 0: none.
    double overlap = 0.0;
    bool past = false;         ///< a recorded past frame is shown
    double secondsBack = 0.0;  ///< how far back it is, s
    /// Trajectories are being recorded (the Data section, key X): the first line says REC.
    bool recording = false;
    /// The scene's lightest and heaviest masses, kg, while they differ (mass_shade.hpp: the
    /// discs' shades show them); 0 when every particle has one mass.
    double lightestMass = 0.0, heaviestMass = 0.0;
    /// The lines a video holds (docs/app-instruments.md, "Video"): the readings for whoever watches
    /// it, without what is for the user at the keys (H: help, the launch's New:, REC (X stops), the
    /// keys that step through the past).
    bool forVideo = false;
    /// A touch screen is the user's hands (Session::touch): the lines name buttons, not keys.
    bool touch = false;
    /// A narrow window (a phone held upright, hudIsNarrow): the readings in short words, without
    /// what a launch would make and the way to the help, so that the box keeps the screen (at
    /// 160 % on a 390-pixel phone the full lines wrapped to 12 and left the box 260 pixels).
    bool narrow = false;
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
/// when a scene name is given; with unsaved changes it starts with "* " and ends with
/// " (unsaved changes)".
[[nodiscard]] std::string windowTitle(std::size_t particles, bool paused,
                                      const std::string& scene = {}, bool unsaved = false);

/// The status lines, top to bottom, numbers at human scale (quantity() of units.hpp); a time
/// speed the steps cannot keep up with shows what is reached. `d.forVideo`: a video's.
[[nodiscard]] std::vector<std::string> hudLines(const HudData& d);
/// The HUD's note while the side column's charts are folded away (sideColumnFits), with the
/// way to get them back: fold the control panel while it is open (its key, or on a touch
/// screen its button), else widen the window; in short words in a `narrow` window.
[[nodiscard]] std::string foldedChartsNote(bool controlsOpen, bool touch = false,
                                           bool narrow = false);
/// The HUD's note while `count` labels (S) are left out: where others were in the way, or with
/// no side of their disc in the window (`offWindow`), with what to do about it; in short words
/// in a `narrow` window.
[[nodiscard]] std::string labelsLeftOutNote(std::size_t count, bool offWindow, bool narrow = false);

/// The profile overlay, one line per stage then the frame's step and draw times.
[[nodiscard]] std::vector<std::string> profileLines(const ProfileData& d);

/// Every control, as (keys, what it does), in the order the help overlay shows them. In a web
/// page (`inPage`) the list is the page's: no video recording (desktop-only), New scene from
/// the panel (browsers keep Ctrl+N), and Esc never quits.
[[nodiscard]] const std::vector<std::pair<std::string, std::string>>& controls(bool inPage = false);

/// The help overlay, one line per control.
[[nodiscard]] std::vector<std::string> helpLines(bool inPage = false);

}  // namespace psb::app
