#pragma once
// Uniform-grid broadphase for a periodic box (WorldDef::periodic): the cells tile the box
// exactly and wrap, so the cell east of the last column is the first column, and every pair is
// measured between its nearest images (support/periodic_box.hpp).
//
//   cellOf[i]     cell of particle i (its centre wrapped into the box first: between the move
//                 and the wrap stages a centre may be a step's travel outside it)
//   cellStart[c]  first slot of cell c in `entries`, cellStart[c + 1] its end
//   entries[k]    particle indices sorted by cell (counting sort, ascending within a cell)
//
// Cells are nx × ny, each at least one largest diameter wide (with slack for rounding), so two
// overlapping discs are in the same cell or in neighbouring ones, across an edge too. The cell
// count is capped at kCellsPerParticle per particle, as in the box grid (broad_phase_grid.hpp).
//
// Query. Each cell is tested against itself (every later slot) and against each of its eight
// neighbours whose index is higher, each neighbour once even where the box is only one or two
// cells across (the neighbours then repeat): every pair of cells once, so every pair of
// particles once. A cell whose half stencil stays off the edge rows and columns (most of them)
// takes the box grid's shortcut instead: the rest of its own cell and the east cell are one run
// of `entries`, the three cells below another, and the plain overlap test is the nearest-image
// one there (its particles are all inside the box). Cells are split over threads in contiguous
// ranges, each into its own list; the union is sorted into the ascending (i, j) order every
// broadphase gives (contact_pair.hpp), so the result does not depend on the thread count.
//
// Why not the box grid with wrapping added. That grid's speed comes from its border ring of
// empty cells and its runs of three contiguous cells, both of which an edge that wraps would
// break; a world without periodic boundaries keeps it untouched, and pays nothing for this one.

#include <cstdint>
#include <vector>

#include <particle_sandbox/particle_arrays.hpp>

#include "broadphase/contact_pair.hpp"
#include "broadphase/pair_chunks.hpp"
#include "support/periodic_box.hpp"

namespace psb {

class PeriodicGridBroadPhase {
  public:
    static constexpr double kCellsPerParticle = 2.0;

    /// Chooses the cells for the box and the largest radius, and sorts the particles into them.
    void build(const ParticleArrays& p, const periodic::Box& box, double maxRadius, int threads);
    /// Appends every overlapping pair (i < j), measured between nearest images, in ascending
    /// (i, j) order.
    void findPairs(const ParticleArrays& p, int threads, std::vector<ContactPair>& out);

    [[nodiscard]] std::int64_t nx() const { return nx_; }
    [[nodiscard]] std::int64_t ny() const { return ny_; }
    /// Bytes held by the scratch (capacities).
    [[nodiscard]] std::size_t memoryBytes() const;

  private:
    [[nodiscard]] std::uint32_t cellOf(double x, double y) const;
    void queryCells(const ParticleArrays& p, int chunk, std::size_t begin, std::size_t end);

    periodic::Box box_;
    std::int64_t nx_ = 1, ny_ = 1;
    double invCellX_ = 1.0, invCellY_ = 1.0;  ///< cells per metre
    std::vector<std::uint32_t> cellOf_, cellStart_, entries_;
    std::vector<std::uint32_t> sortScratchCells_;  ///< the counting sort's next slot per cell
    std::vector<ContactPair> sortScratch_;
    PairChunks chunks_;
};

}  // namespace psb
