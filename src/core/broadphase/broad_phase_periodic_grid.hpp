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
// Query, in a box at least three cells across each way (nearly every scene): the box grid
// (broad_phase_grid.hpp) finds the pairs among the particles and images of those near two of
// the edges, a half shell. A copy of every centre, wrapped into the box, and for a centre
// within the contact reach of an edge an image shifted across the box: by +width for one near
// the left edge, +height for one near the bottom, +width +height and +width −height for one
// near the left edge and the bottom or top. For every separation s a pair can need (one of the
// eight shifts), exactly one of s and −s is in that set, so a pair across an edge is found once,
// between one particle and the other's image; pairs of two images repeat pairs of particles and
// are dropped. The copy's radii are a hair larger (10⁻¹² of the box), so rounding in the
// shifted coordinates never loses a pair, and every pair found is tested again between nearest
// images on the world's own arrays: the pairs are the nearest-image ones bit for bit, whichever
// path found them. The box grid's speed (its border ring, runs of three cells, windows and
// bands) is kept, for one more copy of the centres a step and the images (about one particle
// in √N). One pass over the particles writes the copy, the images and the copy's cells under
// the box grid's last plan (kept while it fits, as for the cells the box's move stage writes),
// so the grid does not read the positions again.
//
// In a box one or two cells across (a handful of particles), each cell is tested against itself
// and against each of its eight neighbours whose index is higher, each once even where the
// neighbours repeat: every pair of cells once, so every pair of particles once. Cells are split
// over threads in contiguous ranges, each into its own list; the union is sorted into the
// ascending (i, j) order every broadphase gives (contact_pair.hpp), so the result does not
// depend on the thread count.

#include <cstdint>
#include <vector>

#include <particle_sandbox/particle_arrays.hpp>

#include "broadphase/broad_phase_grid.hpp"
#include "broadphase/contact_pair.hpp"
#include "broadphase/pair_chunks.hpp"
#include "broadphase/particle_stats.hpp"
#include "support/periodic_box.hpp"

namespace psb {

class PeriodicGridBroadPhase {
  public:
    static constexpr double kCellsPerParticle = 2.0;

    /// Chooses the cells for the box and the particles' radii (`stats`, measured on `p`), and
    /// sorts the particles into them.
    void build(const ParticleArrays& p, const periodic::Box& box, const ParticleStats& stats,
               int threads);
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
    /// The copy of the centres and the half shell of images, for `reach` metres; what the box
    /// grid needs to know of them, from the particles' `stats`.
    ParticleStats buildImages(const ParticleArrays& p, const ParticleStats& stats, double reach);

    periodic::Box box_;
    std::int64_t nx_ = 1, ny_ = 1;
    double invCellX_ = 1.0, invCellY_ = 1.0;  ///< cells per metre
    std::vector<std::uint32_t> cellOf_, cellStart_, entries_;
    std::vector<std::uint32_t> sortScratchCells_;  ///< the counting sort's next slot per cell
    std::vector<ContactPair> sortScratch_;
    PairChunks chunks_;
    // The half shell (boxes three cells across or more).
    bool images_ = false;
    ParticleArrays copy_;                  ///< x, y, radius: the centres wrapped, then the images
    std::vector<std::uint32_t> source_;    ///< the particle each image is of
    std::vector<double> imageX_, imageY_;  ///< the images' centres, before they join the copy
    std::vector<std::uint8_t> edge_;       ///< per particle: its centre is off the interior
    bool cellsWritten_ = false;            ///< buildImages wrote the copy's cells (the grid's plan)
    GridBroadPhase grid_;
    std::vector<ContactPair> found_, acrossEdges_;
};

}  // namespace psb
