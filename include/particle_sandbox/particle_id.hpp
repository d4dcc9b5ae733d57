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

}  // namespace psb

template <>
struct std::hash<psb::ParticleId> {
    std::size_t operator()(psb::ParticleId id) const noexcept {
        return std::hash<std::uint64_t>{}((std::uint64_t{id.generation} << 32) | id.slot);
    }
};
