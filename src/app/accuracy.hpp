#pragma once
// Switching the stepping mode from the keyboard, and the live accuracy indicators of the HUD.
//
// Mode switch: discrete -> substep -> exact -> discrete. The world validates the choice; a
// refusal (psb::InvalidArgument) is reported as a message and the world keeps its mode, so a
// key press can never take the app down.
//
// Indicators, both O(1) or O(N) per frame and nothing more:
// - Largest overlap: the world's counters already record the deepest overlap its detection met
//   (StepCounters::maxOverlap, taken from the broadphase pairs the step finds anyway, and from
//   the exact stepper's own checks). The counter is a running maximum, so the monitor resets
//   the counters before each frame's steps and reads them after: the figure is the deepest
//   overlap of this frame's steps, at no cost beyond the step itself.
// - Kinetic energy drift: (KE - KE_ref) / KE_ref, where KE_ref is taken at the last user
//   action (grab, release, launch, spawn, delete, mode change, scene load). KE itself is the
//   O(N) sum the HUD shows anyway.

#include <cstdint>
#include <string>

#include <particle_sandbox/solver_settings.hpp>
#include <particle_sandbox/world.hpp>

namespace psb::app {

/// The mode the switch key selects after `mode`.
[[nodiscard]] StepMode nextMode(StepMode mode);

/// Substeps per dt the app uses when it switches to substep mode from a solver with fewer than
/// two (one substep would be the discrete mode again).
inline constexpr int kAppSubsteps = 4;

struct ModeSwitch {
    bool changed = false;
    std::string message;  ///< for the screen: the new mode, or a short reason for the refusal
    std::string detail;   ///< for the log: the world's full message on a refusal
};

/// Moves `world` to the next mode. On refusal the world is unchanged and the message says why.
ModeSwitch switchToNextMode(World& world);

/// "discrete", "substep x4", "exact".
[[nodiscard]] std::string modeName(const SolverSettings& solver);

class AccuracyMonitor {
  public:
    /// A user action happened: kinetic energy is measured from `kineticEnergy` on.
    void resetReference(double kineticEnergy);
    /// Before a frame's steps: clears the world's running counters so that their maximum
    /// overlap covers only the coming steps.
    void beginSteps(World& world);
    /// After a frame's steps: records the overlap and events of those steps (if any ran).
    void endSteps(const World& world);

    /// Relative drift of `kineticEnergy` from the reference; NaN without a reference or when
    /// the reference is 0 (nothing moving).
    [[nodiscard]] double drift(double kineticEnergy) const;
    [[nodiscard]] double referenceEnergy() const { return reference_; }
    /// Deepest overlap met by the last frame that stepped, metres.
    [[nodiscard]] double overlap() const { return overlap_; }
    /// Exact-mode events processed per step in the last frame that stepped.
    [[nodiscard]] double eventsPerStep() const { return eventsPerStep_; }

  private:
    double reference_ = -1.0;  // < 0: none yet
    double overlap_ = 0.0;
    double eventsPerStep_ = 0.0;
};

}  // namespace psb::app
