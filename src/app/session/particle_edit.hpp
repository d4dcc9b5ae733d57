#pragma once
// A checked edit of a particle (edit_prompt.hpp) written into a world: every value set or none.
// In the session the document, the world's owner, writes it (Document::edit); applyEdit and
// editParticleValue check and write at once for a world on its own.

#include <array>
#include <string>
#include <string_view>

#include <particle_sandbox/axes.hpp>
#include <particle_sandbox/world.hpp>

#include "session/edit_prompt.hpp"

namespace psb::app {

struct EditResult {
    bool applied = false;
    std::string message;  ///< what changed, or why nothing did
};

/// Writes `edit` into `world` when it passed its checks: all its values or, should the world
/// refuse one, none. Otherwise changes nothing and says why. `axes`: how the message shows the
/// values.
EditResult writeEdit(World& world, const CheckedEdit& edit, const Axes& axes = {});

/// checkEdit, then writeEdit.
EditResult applyEdit(World& world, ParticleId id, const std::array<std::string, kEditFields>& texts,
                     const Axes& axes = {});
/// checkValue, then writeEdit.
EditResult editParticleValue(World& world, ParticleId id, ParticleField field,
                             std::string_view text, const Axes& axes = {});

}  // namespace psb::app
