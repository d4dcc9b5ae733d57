#pragma once
// The selected particle on screen: an outline around its disc, and a panel (bottom-right)
// with its state in SI units, or the edit prompt while it is open. The panel's text is made
// without SDL so it is tested as plain strings.

#include <string>
#include <vector>

#include <SDL.h>

#include <particle_sandbox/particle.hpp>

#include "camera.hpp"
#include "edit_prompt.hpp"

namespace psb::app {

/// The panel's lines for `p`: position (m), velocity (m/s), speed (m/s), momentum (kg m/s),
/// kinetic energy (J), mass (kg), radius (m); while `prompt` is active on p, its four fields
/// (the active one marked) and the last refusal instead of the key hint.
[[nodiscard]] std::vector<std::string> inspectorLines(const Particle& p, const EditPrompt& prompt);

/// Rings around the disc of `p` (3 and 4 pixels outside its rim, at least 6 pixels from its
/// centre, so a particle smaller than a pixel is still marked).
void drawSelectionOutline(SDL_Renderer* renderer, const Camera& camera, const Particle& p);

}  // namespace psb::app
