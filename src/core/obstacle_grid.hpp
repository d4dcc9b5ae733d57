#pragma once
// The broadphase for fixed obstacles: a uniform grid of their own, built once for a set of
// obstacles and kept while the set does not change (obstacles never move).
//
//   cellStart[c]   first slot of cell c in `entries`; cellStart[c + 1] is its end    cells + 1
//   entries[k]     obstacle indices, ascending within a cell                         one per
//                                                                                    (obstacle,
//                                                                                    cell)
//
// The grid covers the bounding box of the obstacles. Cells are square; their size makes about
// kCellsPerObstacle cells per obstacle over that box (at most kMaxCells cells), so a peg
// usually sits in one to four cells. A segment is listed in each cell of its bounding box that
// it comes near (the distance from the cell's centre to its core is at most its radius plus the
// cell's half diagonal), so a long diagonal wall costs cells along its length, not its box's
// area. A query lists every obstacle of every cell a box touches, once each, in ascending order:
// the candidates the contact stage then tests exactly.

#include <cstdint>
#include <vector>

#include <particle_sandbox/obstacle.hpp>

namespace psb {

class ObstacleGrid {
  public:
    static constexpr double kCellsPerObstacle = 4.0;
    static constexpr std::size_t kMaxCells = std::size_t{1} << 20;

    /// Bins `obstacles`, which must be valid (World checks them), replacing any earlier set.
    void build(const Obstacles& obstacles);
    /// Whether the grid holds exactly `obstacles` (the same list the last build() was given).
    [[nodiscard]] bool builtFor(const Obstacles& obstacles) const {
        return built_ && obstacles == obstacles_;
    }
    /// Replaces `out` with the indices of the obstacles listed in the cells that the box
    /// [x0, x1] × [y0, y1] touches, ascending and without repeats. Empty when the box misses
    /// the grid. `out` keeps its capacity, so a warm query allocates nothing.
    void query(double x0, double y0, double x1, double y1, std::vector<std::uint32_t>& out) const;

    [[nodiscard]] const Obstacles& obstacles() const { return obstacles_; }
    [[nodiscard]] std::size_t cellCount() const { return std::size_t{nx_} * ny_; }
    /// Entries over all cells: the total of every obstacle's cell count.
    [[nodiscard]] std::size_t entryCount() const { return entries_.size(); }
    [[nodiscard]] double cellSize() const { return cell_; }
    [[nodiscard]] std::size_t memoryBytes() const;

  private:
    [[nodiscard]] std::uint32_t column(double x) const;
    [[nodiscard]] std::uint32_t row(double y) const;

    bool built_ = false;
    Obstacles obstacles_;
    double x0_ = 0.0, y0_ = 0.0, x1_ = 0.0, y1_ = 0.0;  ///< the grid's extent, metres
    double cell_ = 1.0, invCell_ = 1.0;
    std::uint32_t nx_ = 0, ny_ = 0;
    std::vector<std::uint32_t> cellStart_;
    std::vector<std::uint32_t> entries_;
};

}  // namespace psb
