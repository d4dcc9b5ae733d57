#pragma once
// The selected particle's panel (bottom-right): its state in SI units, or the edit prompt while
// it is open, as lines of text. The outline around its disc is drawn by
// render/selection_outline.hpp.

#include <string>
#include <vector>

#include <particle_sandbox/axes.hpp>
#include <particle_sandbox/particle.hpp>

#include "session/edit_prompt.hpp"

namespace psb::app {

/// A particle's turning and its energies, as the inspector and the panel show them.
struct SpinReading {
    double translational = 0.0;  ///< ½ m v², J
    double rotational = 0.0;     ///< ½ I ω² with I = k m r², J
    /// ω in turns a minute, positive turning +x toward the shown +y (Axes::spin).
    double revPerMin = 0.0;
};
[[nodiscard]] SpinReading spinReading(const Particle& p, const Axes& axes = {});

/// The panel's lines for `p`: position (m), velocity (m/s), speed (m/s), momentum (kg m/s),
/// kinetic energy (J), mass (kg), radius (m); in a world that keeps rotation (`rotation`:
/// World::rotationInUse) also the angular velocity (rad/s and rev/min, or "fixed rotation"),
/// the kinetic energy of translation and of rotation, and the inertia factor k. While `prompt`
/// is active on p, its fields (the active one marked) and the last refusal instead of the key
/// hint. `readings` false: the prompt without the readings, for a window too small for both.
/// In `axes` (the y up option). On a touch screen (`touch`: Session::touch) the hints name no
/// key the screen lacks: the panel's Selected particle edits.
[[nodiscard]] std::vector<std::string> inspectorLines(const Particle& p, const EditPrompt& prompt,
                                                      bool readings = true, bool rotation = false,
                                                      const Axes& axes = {}, bool touch = false);

}  // namespace psb::app
