#pragma once
// Finding two overlapping discs among up to a million, for validating scenes.

#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

#include <particle_sandbox/particle.hpp>

namespace psb::detail {

/// The overlapping pair (i < j) with the smallest i, and for it the smallest j, or nullopt.
/// Discs that only touch (distance == r_i + r_j) do not overlap. Positions and radii must be
/// finite. Uniform grid of cells twice the largest radius, sorted by cell: O(n log n).
[[nodiscard]] std::optional<std::pair<std::size_t, std::size_t>> findOverlap(
    const std::vector<ParticleDef>& particles);

}  // namespace psb::detail
