#pragma once
// The world keeps one collision log (collision_log.hpp); more than one instrument reads it (the
// Data section's recording, the last collision card). Before each step the instruments merge
// what they want and have the world record that; after the step each takes what it follows
// from the same records (instruments.hpp). In the session the document, the world's owner,
// calls listen() and heard() (Document::listen, Document::heard).

#include <optional>
#include <vector>

#include <particle_sandbox/collision_log.hpp>
#include <particle_sandbox/world.hpp>

namespace psb::app {

/// What two instruments want together: every collision if either wants every one, else the
/// collisions of the ids either chose; none if neither wants any.
[[nodiscard]] std::optional<CollisionLog> mergeWanted(const std::optional<CollisionLog>& a,
                                                      const std::optional<CollisionLog>& b);

/// Has `world` record `wanted` from its next step (nothing when none), leaving its log empty: a
/// world put back by an undo or rebuilt for a past frame carries the log it had then, which no
/// instrument heard being made. A log that chooses the same already is kept (no reallocation).
void listen(World& world, const std::optional<CollisionLog>& wanted);

/// What the world recorded in the step just made, leaving its log empty (none when it records
/// nothing).
[[nodiscard]] std::vector<Collision> heard(World& world);

}  // namespace psb::app
