#pragma once
// Uniform-grid broadphase, rebuilt every step by counting sort.
//
// Layout (the "cell start / cell entries" grid of GPU particle codes):
//
//   cellOf[i]      cell of particle i, or kLarge                                   one per particle
//                  (row-major inside a ring of empty border cells: (cy+1)·(nx+2) + cx+1)
//   cellStart[c]   first slot of cell c in `entries`; cellStart[c + 1] is its end   cells + 1
//   entries[k]     particle indices, sorted by cell, ascending within a cell       one per particle
//                  (small particles first, then the large ones in index order)
//
// Building is one pass for the cell of each particle, then a counting sort (histogram, prefix
// sum, backward scatter, which leaves each cell's indices ascending); with several threads each
// owns a range of cells, so the sort is parallel without atomics and its result is the same.
// Because cells are row-major, three neighbouring cells of one row are one contiguous run of
// `entries`; the border ring means no stencil needs a bounds check.
//
// Cell size. Cells are at least twice the largest "small" radius, so two overlapping small
// particles are in the same or adjacent cells (with a relative margin for rounding; clamping
// cell coordinates into the grid is 1-Lipschitz, so particles outside the box or far from the
// rest stay correct, only slower). The cell count is capped at kCellsPerParticle per particle:
// in a dilute scene the cells grow instead, which bounds memory at 4 bytes per cell.
//
// Large particles. A particle is "large" when its radius exceeds twice the mean radius. Large
// particles stay out of the cells (so a few big discs do not force big cells on everyone); each
// one queries the cells its disc can reach, and large–large pairs are tested directly (about
// L²/2 tests for L large particles, which is why `auto` leaves scenes with many of them to the
// quadtree).
//
// Query. Slots are visited in cell order with a half stencil: the rest of the particle's own
// cell plus the east cell (one contiguous run of `entries`), then the three cells of the row
// below (another run). Each pair is tested exactly once and the loop is branch-free; per
// particle that is two short loops and, in the gas benchmark (two cells per particle), about
// 2.3 candidates. When all radii are equal the contact distance is a constant and no radius is
// read.
//
// Output order. Pairs are found in cell order and then sorted into ascending (i, j) order, the
// order all-pairs gives, by an LSD radix sort over the pair list (cost proportional to the
// pairs, which are few in a gas). Queries run in parallel over contiguous slot ranges, each into
// its own list; the sorted union is the same whatever the ranges (see parallel.hpp). Pairs with
// a large particle are appended before the sort.

#include <cstdint>
#include <vector>

#include <particle_sandbox/particle_arrays.hpp>

#include "contact_pair.hpp"
#include "pair_chunks.hpp"
#include "particle_stats.hpp"

namespace psb {

class GridBroadPhase {
  public:
    /// At most this many cells per small particle (memory: 4 bytes per cell). Two cells per
    /// particle halves the candidates of one, for 4 more bytes per particle.
    static constexpr double kCellsPerParticle = 2.0;

    /// Chooses the cell size and origin for `p` (described by `stats`) and sorts the particles
    /// into cells. After build(), order() lists every particle index sorted by cell.
    void build(const ParticleArrays& p, const ParticleStats& stats, int threads);
    /// Appends every overlapping pair (i < j) of the particles given to build(), in ascending
    /// (i, j) order.
    void findPairs(const ParticleArrays& p, int threads, std::vector<ContactPair>& out);

    /// Every particle index, sorted by cell (large particles last). Valid after build(); the
    /// caller may consume it (World's reorder does), which invalidates the grid until the next
    /// build().
    [[nodiscard]] std::vector<std::uint32_t>& order() { return entries_; }
    [[nodiscard]] double cellSize() const { return cell_; }
    [[nodiscard]] std::size_t cellCount() const { return std::size_t{nx_} * ny_; }
    [[nodiscard]] std::size_t largeCount() const { return large_.size(); }
    /// Bytes held by this grid's scratch (capacities, not sizes).
    [[nodiscard]] std::size_t memoryBytes() const;

  private:
    static constexpr std::uint32_t kLarge = UINT32_MAX;

    [[nodiscard]] std::uint32_t cellX(double x) const;
    [[nodiscard]] std::uint32_t cellY(double y) const;
    void plan(const ParticleArrays& p, const ParticleStats& stats);
    void findLargePairs(const ParticleArrays& p);

    double originX_ = 0.0, originY_ = 0.0;
    double cell_ = 1.0, invCell_ = 1.0;
    std::uint32_t nx_ = 1, ny_ = 1;
    double largeAbove_ = 0.0;  ///< radius above which a particle is large
    double smallMaxRadius_ = 0.0;
    double equalRadius_ = 0.0;  ///< the radius of every particle when all are equal, else 0
    std::vector<std::uint32_t> cellOf_;
    std::vector<std::uint32_t> cellStart_;
    std::vector<std::uint32_t> entries_;
    std::vector<std::uint32_t> large_;
    std::vector<std::uint32_t> partTotals_;  ///< particles in the cell ranges before each part
    std::vector<ContactPair> largePairs_;
    std::vector<ContactPair> sortScratch_;
    PairChunks chunks_;
};

}  // namespace psb
