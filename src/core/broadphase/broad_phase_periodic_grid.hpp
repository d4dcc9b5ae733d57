#pragma once
// Uniform-grid broadphase for a periodic box (WorldDef::periodic): every pair is measured
// between its nearest images (support/periodic_box.hpp).
//
// In a box at least three cells across each way (nearly every scene), the pairs come in three
// sets that do not meet:
//   - pairs that touch inside the box: the box grid (broad_phase_grid.hpp) over the particles
//     themselves, with its speed (border ring, runs of three cells, windows and bands) and the
//     cells the move stage wrote for it (cellsForMove), exactly as in a box with walls;
//   - pairs that touch across the left and right edges: a disc within the contact reach of the
//     left edge against those within it of the right one, the right strip sorted into bands at
//     least one reach long (no more bands than discs), so each left disc meets three bands,
//     one run of slots (two where they wrap), tested without a branch;
//   - pairs that touch across the bottom and top edges (and not across the sides as well, which
//     the second set holds): the same along the other axis.
// The discs near the edges are listed by the move stage as it wraps the centres
// (marksForMove), so finding them reads no position again; without its lists (the first step,
// larger discs added) build() finds them itself.
// Two discs that touch are less than a reach apart along each axis, and the box is at least
// three reaches across, so a pair across an edge has one disc in each of the two strips, no pair
// inside the box does, and the grid's plain distance is the nearest image's distance bit for
// bit. About one particle in √N is in a strip. The move stage wraps the centres into the box
// (discrete_step.hpp); a caller whose centres lie outside it (the broadphase is also used on
// any state the library is handed) gets a wrapped copy measured the same way, and every pair it
// finds tested again between nearest images on the particles themselves.
//
// In a box one or two cells across (a handful of particles), each cell is tested against itself
// and against each of its eight neighbours whose index is higher, each once even where the
// neighbours repeat: every pair of cells once, so every pair of particles once. Cells are split
// over threads in contiguous ranges, each into its own list; the union is sorted into the
// ascending (i, j) order every broadphase gives (contact_pair.hpp), so the result does not
// depend on the thread count.

#include <cstdint>
#include <optional>
#include <span>
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
    /// sorts the particles into them. `cellsFromMove`: the move stage wrote the cells of these
    /// positions where cellsForMove() said.
    void build(const ParticleArrays& p, const periodic::Box& box, const ParticleStats& stats,
               int threads, bool cellsFromMove = false, bool marksFromMove = false);
    /// Appends every overlapping pair (i < j), measured between nearest images, in ascending
    /// (i, j) order.
    void findPairs(const ParticleArrays& p, int threads, std::vector<ContactPair>& out);
    /// Where the move stage may write the cells of `n` wrapped centres for the next build, as
    /// GridBroadPhase::cellsForMove; nothing in a box one or two cells across.
    [[nodiscard]] std::optional<GridBroadPhase::MoveCells> cellsForMove(std::size_t n);
    /// Where the move stage may list, per block, the particles within `reach` of an edge (or
    /// outside the box) under the last plan, so that build() finds the strips without reading
    /// the positions again; nothing in a box one or two cells across.
    struct EdgeMarks {
        std::vector<std::uint32_t>* marked = nullptr;  ///< one list per block of `n` particles
        double reach = 0.0;
    };
    [[nodiscard]] std::optional<EdgeMarks> marksForMove(std::size_t n);
    /// The box grid that finds the pairs inside the box (World's reorder sorts the particles
    /// by its cells, the order it reads them in).
    [[nodiscard]] GridBroadPhase& boxGrid() { return grid_; }

    [[nodiscard]] std::int64_t nx() const { return nx_; }
    [[nodiscard]] std::int64_t ny() const { return ny_; }
    /// Bytes held by the scratch (capacities).
    [[nodiscard]] std::size_t memoryBytes() const;

  private:
    [[nodiscard]] std::uint32_t cellOf(double x, double y) const;
    void queryCells(const ParticleArrays& p, int chunk, std::size_t begin, std::size_t end);
    /// The discs within `reach_` of each edge of `q` (centres in the box).
    void collectStrips(const ParticleArrays& q);
    /// The same from the lists of marked particles the move stage wrote.
    void collectMarkedStrips(const ParticleArrays& q);
    /// The discs of `lists` (those near an edge) into the four strips they belong to.
    void sortIntoStrips(const ParticleArrays& q, std::span<const std::vector<std::uint32_t>> lists);
    /// Pairs of `low` (near the low edge of one axis) and `high` (near the high edge), `high`
    /// sorted into bands of the other axis; `skipAcrossX`: leave out pairs whose x separation
    /// also crosses the box (the first pass found them).
    void stripPairs(const ParticleArrays& p, const std::vector<std::uint32_t>& low,
                    const std::vector<std::uint32_t>& high, bool alongY, bool skipAcrossX);
    /// A wrapped copy of `p`'s centres, for a caller whose centres lie outside the box.
    void wrapCopy(const ParticleArrays& p);

    periodic::Box box_;
    std::int64_t nx_ = 1, ny_ = 1;
    double invCellX_ = 1.0, invCellY_ = 1.0;  ///< cells per metre
    std::vector<std::uint32_t> cellOf_, cellStart_, entries_;
    std::vector<std::uint32_t> sortScratchCells_;  ///< the counting sort's next slot per cell
    std::vector<ContactPair> sortScratch_;
    PairChunks chunks_;
    // Boxes three cells across or more.
    bool strips_ = false;
    bool copied_ = false;  ///< the grid holds wrapped copies of the centres (copy_)
    double reach_ = 0.0;   ///< the largest contact distance, with slack for rounding
    ParticleArrays copy_;  ///< x, y, radius wrapped, when the caller's centres are not
    std::vector<std::uint32_t> left_, right_, bottom_, top_;
    std::vector<std::uint32_t> candidates_;           ///< collectStrips' discs near an edge
    std::vector<std::vector<std::uint32_t>> marked_;  ///< per block, the marked particles
    double marksReach_ = -1.0;                        ///< the reach the lists were handed out for
    std::vector<std::uint32_t> bandStart_, bandEntries_;
    std::vector<double> bandX_, bandY_, bandR_;  ///< bandEntries_' centres and radii
    GridBroadPhase grid_;
    std::vector<ContactPair> found_, acrossEdges_;
};

}  // namespace psb
