#pragma once
// The live accuracy indicators of the HUD.
//
// Indicators, both O(1) or O(N) per frame and nothing more:
// - Largest overlap: the deeper of what this frame's steps met (StepCounters::maxOverlap, a
//   running maximum the monitor clears before the steps) and the overlap of the state as drawn
//   (psb::maxOverlap, one broadphase pass), so that pairs placed overlapping by a drag, a spawn
//   or an edit show while paused and in the exact mode, whose events meet overlaps only at
//   collisions.
// - Kinetic energy drift: (KE - KE_ref) / KE_ref, where KE_ref is taken at the last user
//   action (grab, release, launch, spawn, delete, mode change, scene load). KE itself is the
//   O(N) sum the HUD shows anyway.

#include <algorithm>
#include <cstdint>
#include <string>

#include <particle_sandbox/solver_settings.hpp>
#include <particle_sandbox/world.hpp>

namespace psb::app {

/// The energy whose drift the HUD shows: kinetic (of translation and rotation), plus potential
/// when the world has gravity (under gravity kinetic energy alone is not conserved, so its drift
/// would look like energy lost or made).
[[nodiscard]] double monitoredEnergy(const World& world);

class AccuracyMonitor {
  public:
    /// A user action happened: kinetic energy is measured from `kineticEnergy` on.
    void resetReference(double kineticEnergy);
    /// Before a frame's steps: clears the world's running counters so that their maximum
    /// overlap covers only the coming steps.
    void beginSteps(World& world);
    /// After a frame's steps: records the overlap and events of those steps (if any ran).
    void endSteps(const World& world);
    /// The state as it will be drawn: records its deepest overlap now.
    void measureState(const World& world);
    /// The steps' detection covers the state: forget the last measurement.
    void clearState() { stateOverlap_ = 0.0; }

    /// Relative drift of `kineticEnergy` from the reference; NaN without a reference or when
    /// the reference is 0 (nothing moving).
    [[nodiscard]] double drift(double kineticEnergy) const;
    /// Deepest overlap met by the last frame that stepped or present in the state measured
    /// last, metres.
    [[nodiscard]] double overlap() const { return std::max(overlap_, stateOverlap_); }
    /// Exact-mode events processed per step in the last frame that stepped.
    [[nodiscard]] double eventsPerStep() const { return eventsPerStep_; }

  private:
    double reference_ = -1.0;  // < 0: none yet
    double overlap_ = 0.0;
    double stateOverlap_ = 0.0;
    double eventsPerStep_ = 0.0;
};

}  // namespace psb::app
