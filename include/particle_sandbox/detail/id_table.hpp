#pragma once
/// \file
/// Slot table behind stable particle ids (an implementation detail of World, shown here only
/// because World holds it by value).

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include <particle_sandbox/particle_id.hpp>

namespace psb::detail {

/// Maps ids (slot + generation) to dense storage indices. A freed slot's generation is bumped,
/// so stale ids are recognised; a new id takes the lowest free slot (particleNumber counts on
/// it: a world's particles are numbered 1, 2, ... with no gap a new particle could skip).
class IdTable {
  public:
    /// A new id pointing at dense index `index`.
    ParticleId allocate(std::uint32_t index);
    /// Frees a live id.
    void release(ParticleId id);
    /// Points a live id at a new dense index (after a swap-remove moved it).
    void relocate(ParticleId id, std::uint32_t index);
    [[nodiscard]] std::optional<std::uint32_t> find(ParticleId id) const;
    void clear();
    void reserve(std::size_t slots);
    [[nodiscard]] std::size_t memoryBytes() const;

  private:
    static constexpr std::uint32_t kFree = UINT32_MAX;
    std::vector<std::uint32_t> index_;       ///< per slot: dense index, or kFree
    std::vector<std::uint32_t> generation_;  ///< per slot
    std::vector<std::uint32_t> freeSlots_;   ///< a min-heap: the lowest free slot first
};

}  // namespace psb::detail
