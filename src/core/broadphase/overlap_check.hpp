#pragma once
// Finding two overlapping discs among up to a million, for validating scenes.

#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

#include <particle_sandbox/obstacle.hpp>
#include <particle_sandbox/particle.hpp>

namespace psb::detail {

/// The overlapping pair (i < j) with the smallest i, and for it the smallest j, or nullopt.
/// Discs that only touch (distance == r_i + r_j) do not overlap. Positions and radii must be
/// finite. Uniform grid of cells twice the largest radius, sorted by cell: O(n log n).
[[nodiscard]] std::optional<std::pair<std::size_t, std::size_t>> findOverlap(
    const std::vector<ParticleDef>& particles);

/// The same in a periodic box `width` × `height` (WorldDef::periodic): distances between
/// nearest images, so two discs at opposite edges overlap across them. Centres anywhere (they
/// are wrapped into the box first); a disc's diameter at most half of each side (as World
/// keeps it).
[[nodiscard]] std::optional<std::pair<std::size_t, std::size_t>> findOverlapPeriodic(
    const std::vector<ParticleDef>& particles, double width, double height);

/// A particle overlapping an obstacle: their indices and the distance from the particle's
/// centre to the obstacle's core (a peg's centre, a segment's line), metres.
struct ObstacleOverlap {
    std::size_t particle = 0;
    std::size_t obstacle = 0;
    double distance = 0.0;
};

/// The first particle (by index) that overlaps an obstacle, with the first such obstacle, or
/// nullopt. Touching (distance == sum of radii) is not overlapping. Through an ObstacleGrid.
[[nodiscard]] std::optional<ObstacleOverlap> findObstacleOverlap(
    const std::vector<ParticleDef>& particles, const Obstacles& obstacles);

}  // namespace psb::detail
