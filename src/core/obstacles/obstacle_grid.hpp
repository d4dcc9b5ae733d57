#pragma once
// The broadphase for fixed obstacles: a uniform grid of their own, built once for a set of
// obstacles and kept while the set does not change (obstacles never move).
//
//   cellStart[c]   first slot of cell c in `entries`; cellStart[c + 1] is its end    cells + 1
//   entries[k]     obstacle indices, ascending within a cell                         one per
//                                                                                    (obstacle,
//                                                                                    cell)
//
// Padding. Each cell lists every obstacle that comes within `pad` metres of it, so that one
// lookup of the cell holding a point finds every obstacle whose surface lies within `pad` of
// that point: the contact stage makes one such lookup for each particle it looks at (those
// outside their free discs) whose reach (diameter plus this step's move) is at most `pad`, and
// a box query for the rare others. The stage chooses
// the pad from the particles' reach; it changes only the speed, never which obstacles a
// particle is tested against (the stage filters candidates by exact distance).
//
// The grid covers the bounding box of the obstacles widened by the pad. Cells are square and
// as wide as the pad (without a pad, about kCellsPerObstacle cells per obstacle over that box;
// at most kMaxCells cells either way), so that cells away from every obstacle are empty and a
// particle there costs one lookup. An obstacle is listed in each cell of its widened bounding
// box that comes within its radius plus the pad of its core (the exact distance from the core
// to the cell's rectangle), so a long diagonal wall costs cells along its length, not its box's
// area. A box query lists every obstacle of every cell a box touches, once each, in ascending
// order.
//
// Clearance. Per cell the grid also keeps its chessboard distance to the nearest cell that lists
// an obstacle (a distance transform, made once per build), so that a lower bound on the distance
// from a point to every obstacle comes from a few cells even far from all of them: the contact
// stage's free discs (discrete_obstacles.cpp).

#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>

#include <particle_sandbox/obstacle.hpp>

namespace psb {

class ObstacleGrid {
  public:
    static constexpr double kCellsPerObstacle = 16.0;
    static constexpr std::size_t kMaxCells = std::size_t{1} << 20;
    /// The pad is at most this many times the largest obstacle coordinate or radius (build()).
    static constexpr double kMaxPadScales = 1e6;
    /// How many rings of cells around a point's own clearance() looks at, at most.
    static constexpr int kClearanceRings = 3;

    /// Bins `obstacles`, which must be valid (World checks them), replacing any earlier set, with
    /// every cell listing the obstacles within `pad` metres (>= 0) of it.
    void build(const Obstacles& obstacles, double pad = 0.0);
    /// Whether the grid holds exactly `obstacles` (the same list the last build() was given).
    [[nodiscard]] bool builtFor(const Obstacles& obstacles) const {
        return built_ && obstacles == obstacles_;
    }
    /// Replaces `out` with the indices of the obstacles listed in the cells that the box
    /// [x0, x1] × [y0, y1] touches, ascending and without repeats. Empty when the box misses
    /// the grid. `out` keeps its capacity, so a warm query allocates nothing.
    void query(double x0, double y0, double x1, double y1, std::vector<std::uint32_t>& out) const;

    /// The obstacles listed for the cell that holds (x, y), ascending: every obstacle whose
    /// surface lies within pad() of the point, and maybe others nearby. Empty outside the grid.
    [[nodiscard]] std::span<const std::uint32_t> cellAt(double x, double y) const {
        // Written so that a NaN coordinate is outside.
        if (!(x >= x0_ && x <= x1_ && y >= y0_ && y <= y1_)) return {};
        const std::size_t c = std::size_t{row(y)} * nx_ + column(x);
        // One bit per cell first: the bitmap stays in cache where the cell starts would not.
        if (((occupied_[c >> 6] >> (c & 63)) & 1u) == 0) return {};
        return {entries_.data() + cellStart_[c], entries_.data() + cellStart_[c + 1]};
    }

    /// A lower bound on the distance from (x, y) to the surface of every obstacle (0 inside
    /// one). The cells around the point's are searched ring by ring, from the first ring that
    /// lists anything (the gap map says which) to kClearanceRings rings out: an obstacle listed
    /// in none of the cells seen lies more than the pad beyond their block, so the bound is the
    /// least of the exact distances to the obstacles listed there and the pad plus the point's
    /// distance to the block's edge; the search stops as soon as a further ring cannot change
    /// it. Past kClearanceRings empty rings, the bound of the empty block alone. Outside the
    /// grid, the pad plus the distance to the grid. 0 for a point that is not finite; infinite
    /// without obstacles.
    [[nodiscard]] double clearance(double x, double y) const;

    [[nodiscard]] const Obstacles& obstacles() const { return obstacles_; }
    [[nodiscard]] double pad() const { return pad_; }
    /// The largest radius (or half-thickness) among the obstacles, metres.
    [[nodiscard]] double maxRadius() const { return maxRadius_; }
    [[nodiscard]] std::size_t cellCount() const { return std::size_t{nx_} * ny_; }
    /// Entries over all cells: the total of every obstacle's cell count.
    [[nodiscard]] std::size_t entryCount() const { return entries_.size(); }
    [[nodiscard]] double cellSize() const { return cell_; }
    [[nodiscard]] std::size_t memoryBytes() const;

  private:
    void measureGaps();
    // Clamped into the grid; truncation is floor here because the clamp comes first.
    [[nodiscard]] std::uint32_t column(double x) const {
        const double f = (x - x0_) * invCell_;
        return static_cast<std::uint32_t>(f > 0.0 ? std::min(f, lastColumn_) : 0.0);
    }
    [[nodiscard]] std::uint32_t row(double y) const {
        const double f = (y - y0_) * invCell_;
        return static_cast<std::uint32_t>(f > 0.0 ? std::min(f, lastRow_) : 0.0);
    }

    bool built_ = false;
    Obstacles obstacles_;
    double x0_ = 0.0, y0_ = 0.0, x1_ = 0.0, y1_ = 0.0;  ///< the grid's extent, metres
    double cell_ = 1.0, invCell_ = 1.0;
    double pad_ = 0.0, maxRadius_ = 0.0;
    double lastColumn_ = 0.0, lastRow_ = 0.0;  ///< nx − 1, ny − 1
    std::uint32_t nx_ = 0, ny_ = 0;
    std::vector<std::uint32_t> cellStart_;
    std::vector<std::uint64_t> occupied_;  ///< bit c: cell c lists an obstacle
    /// Per cell, the chessboard distance (in cells, at most 255) to the nearest cell that lists
    /// an obstacle: 0 for such a cell; the cells less than that many rings out list nothing.
    std::vector<std::uint8_t> gap_;
    std::vector<std::uint32_t> entries_;
};

}  // namespace psb
