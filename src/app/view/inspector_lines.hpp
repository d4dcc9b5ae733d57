#pragma once
// The selected particle's panel (bottom-right): its state in SI units, or the edit prompt while
// it is open, as lines of text. The outline around its disc is drawn by
// render/selection_outline.hpp.

#include <string>
#include <vector>

#include <particle_sandbox/particle.hpp>

#include "session/edit_prompt.hpp"

namespace psb::app {

/// The panel's lines for `p`: position (m), velocity (m/s), speed (m/s), momentum (kg m/s),
/// kinetic energy (J), mass (kg), radius (m); while `prompt` is active on p, its four fields
/// (the active one marked) and the last refusal instead of the key hint. `readings` false: the
/// prompt without the readings, for a window too small for both.
[[nodiscard]] std::vector<std::string> inspectorLines(const Particle& p, const EditPrompt& prompt,
                                                      bool readings = true);

}  // namespace psb::app
