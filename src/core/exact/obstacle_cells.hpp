#pragma once
// Which fixed obstacles each cell of the exact mode's fine grid may reach (the stepper's
// cell list knows its particles; this knows its obstacles).
//
// A particle's centre stays within its cell widened by the skin until its next cell move
// (grid.cpp, "Cells with a skin"). A cell therefore lists every obstacle whose surface
// comes within the largest particle radius of that widened cell (the exact distance from the
// obstacle's core to the rectangle), and a particle's prediction tests only its cell's list.
// That is enough: an obstacle a particle would reach later is not in its cell's list only if
// the particle leaves the cell first, and its cell move tests the new cell's list.
//
//   start[c]    first slot of cell c in `entries`; start[c + 1] is its end          cells + 1
//   entries[k]  obstacle indices, ascending within a cell                 one per (obstacle, cell)
//
// Built once per rebuild (obstacles never move), for the grid the rebuild chose. With walls
// off the grid folds onto itself (cell_list.hpp), so a cell's coordinates name several places
// at once: then the lists are computed per query for the one place the particle is, through
// an ObstacleGrid of the obstacles (a scene without walls and with obstacles is rare).

#include <cstdint>
#include <span>
#include <vector>

#include <particle_sandbox/obstacle.hpp>

#include "exact/cell_list.hpp"
#include "obstacles/obstacle_grid.hpp"

namespace psb::exact {

class ObstacleCells {
  public:
    /// Lists, for every cell of `cells` widened by (skinX, skinY), the obstacles whose surface
    /// comes within `reach` (the largest particle radius) of it. Empty `obstacles`: nothing.
    void build(const Obstacles& obstacles, const CellList& cells, double skinX, double skinY,
               double reach);
    [[nodiscard]] bool empty() const { return obstacles_.empty(); }
    [[nodiscard]] const Obstacle& operator[](std::uint32_t k) const { return obstacles_[k]; }

    /// The obstacles a particle in cell (kx, ky) of `cells` (the grid given to build) may reach
    /// before its next cell move, ascending.
    [[nodiscard]] std::span<const std::uint32_t> near(const CellList& cells, std::int64_t kx,
                                                      std::int64_t ky) const;

    [[nodiscard]] std::size_t memoryBytes() const;

  private:
    // The widened rectangle of cell (kx, ky), metres.
    void rectangle(const CellList& cells, std::int64_t kx, std::int64_t ky, double& x0, double& y0,
                   double& x1, double& y1) const;

    Obstacles obstacles_;
    double skinX_ = 0.0, skinY_ = 0.0, reach_ = 0.0;
    bool perQuery_ = false;  // walls off: lists computed per query
    std::vector<std::uint32_t> start_, entries_;
    ObstacleGrid grid_;                           // walls off only
    mutable std::vector<std::uint32_t> scratch_;  // walls off only: the last query's list
};

}  // namespace psb::exact
