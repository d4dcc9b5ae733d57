#pragma once
/// \file
/// Stable particle handles.

#include <cstdint>
#include <functional>

namespace psb {

/// A stable handle to a particle: a slot index plus a generation counter. Removing a particle
/// never invalidates the id of another, and an id of a removed particle never aliases a new one
/// (its slot's generation has moved on). Callers hold ids, never indices or pointers.
struct ParticleId {
    std::uint32_t slot = UINT32_MAX;
    std::uint32_t generation = 0;

    [[nodiscard]] bool isNull() const { return slot == UINT32_MAX; }
    friend bool operator==(ParticleId a, ParticleId b) = default;
};

/// The id that names no particle.
inline constexpr ParticleId kNullParticle{};

/// The number a person reads for the particle `id`: 1, 2, 3, ... A world built from a scene
/// numbers its particles 1 to N in the scene's order (sceneFromWorld writes them in number
/// order); a new particle takes the lowest number no living particle has, so two balls
/// launched into an emptied box are 1 and 2; a particle keeps its number while it lives,
/// whatever is added, removed or stepped. Whatever shows or writes a particle for people (the
/// app's labels, panel, log and files, a report) uses this number; ids stay the program's
/// handles. It is the id's slot counted from 1 (World takes the lowest free slot).
[[nodiscard]] constexpr std::uint64_t particleNumber(ParticleId id) {
    return std::uint64_t{id.slot} + 1;
}

}  // namespace psb

template <>
struct std::hash<psb::ParticleId> {
    std::size_t operator()(psb::ParticleId id) const noexcept {
        return std::hash<std::uint64_t>{}((std::uint64_t{id.generation} << 32) | id.slot);
    }
};
