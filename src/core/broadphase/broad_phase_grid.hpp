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
// Plan reuse. The move stage can write every particle's cell itself, under the last build's
// plan (origin, cell size, cell counts), while the moved particle is still in cache
// (cellsForMove()); build() then skips its own pass over the positions. Any plan whose cells
// are large enough finds every pair (see Cell size), so build() keeps the last plan while it
// still fits: cells at least as large as the current radii need, no more cells than a fresh
// plan may have, no coarser than a fresh plan by more than kCoarserPlan, and every particle
// within a cell of the grid's edge. Otherwise (particles spread out, radii grew, large
// particles appeared) it plans afresh and computes the cells itself. Pairs do not depend on the
// plan, so neither does the result.
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
// below (another run). Each pair is tested exactly once. In the gas benchmark (two cells per
// particle) a run holds about one particle, so loops over runs of varying length would
// mispredict their exit about twice per particle; instead the first kWindowOwn and kWindowBelow
// slots of the two runs are tested unconditionally, each result masked by whether the slot is
// in its run, and only the rare longer run loops over the rest. When all radii are equal the
// contact distance is a constant and no radius is read.
//
// Slot pairs. A test records the pair of slots (a, k), not of particle indices, so the value
// it stores is ready at once instead of waiting for the candidate's index to load; slot pairs
// become particle pairs at the end of the chunk (pairs are few). Worth 1.5 to 2 ns a
// particle-step in the gas benchmark.
//
// Bands. Reading a candidate's position through `entries` is a chain of dependent loads
// (slot, particle index, position), and once the arrays outgrow the caches a link can miss. So
// each query chunk walks its slots in bands of up to kMaxBand slots: a simple loop first copies
// the positions of the band and of every slot its stencils reach (about one row more) into a
// small buffer in slot order, with the band's cells, and the stencil tests then read only that
// buffer. The copy is one pass of independent loads that the processor overlaps freely. At 10^6
// particles this saves about 1 ns a particle-step; in cache it neither gains nor loses. A band
// whose stencils reach more than twice its length (rows far longer than a band, as in a thin
// strip of particles) is tested in place instead, so the buffer stays small: at most
// 2·kMaxBand slots, 20 bytes a slot (28 with radii), per chunk.
//
// Output order. Pairs are found in cell order and then sorted into ascending (i, j) order, the
// order all-pairs gives, by an LSD radix sort over the pair list (cost proportional to the
// pairs, which are few in a gas). Queries run in parallel over contiguous slot ranges, each into
// its own list; the sorted union is the same whatever the ranges (see parallel.hpp). Pairs with
// a large particle are appended before the sort.

#include <algorithm>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include <particle_sandbox/particle_arrays.hpp>

#include "broadphase/contact_pair.hpp"
#include "broadphase/pair_chunks.hpp"
#include "broadphase/particle_stats.hpp"

namespace psb {

class GridBroadPhase {
  public:
    /// At most this many cells per small particle (memory: 4 bytes per cell). Two cells per
    /// particle halves the candidates of one, for 4 more bytes per particle.
    static constexpr double kCellsPerParticle = 2.0;

    /// Maps a point to its cell under one plan: interior coordinates clamped into the grid,
    /// stored with the border ring ((cy + 1) · (nx + 2) + cx + 1). A NaN coordinate maps to
    /// the first column or row.
    struct CellMap {
        double originX = 0.0, originY = 0.0;  ///< metres
        double invCell = 1.0;                 ///< 1 / cell size, 1/metres
        std::uint32_t nx = 1, ny = 1;         ///< interior cells per row, per column

        [[nodiscard]] std::uint32_t cellX(double x) const { return clamped(x, originX, nx); }
        [[nodiscard]] std::uint32_t cellY(double y) const { return clamped(y, originY, ny); }
        [[nodiscard]] std::uint32_t cellOf(double x, double y) const {
            return (cellY(y) + 1) * (nx + 2) + cellX(x) + 1;
        }

      private:
        // Branch-free (min/max of doubles) and through int32 (cell counts are below 2^31), so
        // that a loop over particles vectorises with plain SSE2.
        [[nodiscard]] std::uint32_t clamped(double v, double origin, std::uint32_t n) const {
            const double f = (v - origin) * invCell;
            const double last = static_cast<double>(n - 1);
            return static_cast<std::uint32_t>(
                static_cast<std::int32_t>(f > 0.0 ? (f < last ? f : last) : 0.0));
        }
    };

    /// Cells the move stage writes ahead of build(): cellOf[i] = map.cellOf(x[i], y[i]).
    struct MoveCells {
        CellMap map;
        std::uint32_t* cellOf = nullptr;  ///< one per particle
    };

    /// Chooses the cell size and origin for `p` (described by `stats`) and sorts the particles
    /// into cells. After build(), order() lists every particle index sorted by cell.
    /// `cellsFromMove`: the cells handed out by cellsForMove() were written for these positions;
    /// build() keeps them, and the plan they were made with, while that plan still fits.
    void build(const ParticleArrays& p, const ParticleStats& stats, int threads,
               bool cellsFromMove = false);
    /// Where the move stage may write the cells of `n` particles under the last plan, or
    /// nothing when that plan cannot be reused (no build yet, or it set large particles apart).
    [[nodiscard]] std::optional<MoveCells> cellsForMove(std::size_t n);
    /// Appends every overlapping pair (i < j) of the particles given to build(), in ascending
    /// (i, j) order.
    void findPairs(const ParticleArrays& p, int threads, std::vector<ContactPair>& out);

    /// Every particle index, sorted by cell (large particles last). Valid after build(); the
    /// caller may consume it (World's reorder does), which invalidates the grid until the next
    /// build().
    [[nodiscard]] std::span<std::uint32_t> order() {
        return {entries_.data(), entries_.size() - std::min(entries_.size(), kPadding)};
    }
    [[nodiscard]] double cellSize() const { return cell_; }
    [[nodiscard]] std::size_t cellCount() const { return std::size_t{map_.nx} * map_.ny; }
    [[nodiscard]] std::size_t largeCount() const { return large_.size(); }
    /// Whether the last build() kept the plan of the build before it (for tests).
    [[nodiscard]] bool keptPlan() const { return keptPlan_; }
    /// Bytes held by this grid's scratch (capacities, not sizes).
    [[nodiscard]] std::size_t memoryBytes() const;

  private:
    static constexpr std::uint32_t kLarge = UINT32_MAX;
    /// Slots of the own-and-east run and of the row-below run tested without a loop.
    static constexpr std::uint32_t kWindowOwn = 2, kWindowBelow = 3;
    /// Slots after the last entry, so that a window starting at any slot stays in the array.
    static constexpr std::size_t kPadding = kWindowBelow;
    /// A kept plan's cells may be at most this much larger than a fresh plan's.
    static constexpr double kCoarserPlan = 1.125;

    /// A chunk's copy of one band of slots for the query: centres (and radii, when they differ)
    /// in slot order for the band and every slot its stencils reach, cells for the band.
    struct Band {
        std::vector<double> x, y, r;
        std::vector<std::uint32_t> cell;
        /// Room for `slots` slots; grows, then stays.
        void makeRoom(std::size_t slots, bool radii) {
            if (x.size() < slots) {
                x.resize(slots);
                y.resize(slots);
                cell.resize(slots);
            }
            if (radii && r.size() < slots) r.resize(slots);
        }
        /// Copies slots [a, reach) (cells of [a, b)), then kPadding zero slots.
        void gather(const ParticleArrays& p, const std::uint32_t* entries,
                    const std::uint32_t* cellOf, std::size_t a, std::size_t b, std::size_t reach,
                    bool radii);
        [[nodiscard]] std::size_t memoryBytes() const {
            return sizeof(double) * (x.capacity() + y.capacity() + r.capacity()) +
                   sizeof(std::uint32_t) * cell.capacity();
        }
    };
    /// Bands per chunk when the chunk is short, and the shortest and longest band, in slots.
    static constexpr std::size_t kBandsPerChunk = 32, kMinBand = 16, kMaxBand = 4096;

    void plan(const ParticleArrays& p, const ParticleStats& stats);
    template <bool kEqualRadii>
    void queryChunk(const ParticleArrays& p, int c, std::size_t begin, std::size_t end,
                    std::size_t bandSlots);
    [[nodiscard]] bool planStillFits(const ParticleStats& stats, std::size_t n) const;
    void findLargePairs(const ParticleArrays& p);

    CellMap map_;
    double cell_ = 1.0;
    bool planned_ = false;     ///< a build() has chosen a plan
    bool keptPlan_ = false;    ///< the last build() kept the plan before it
    double largeAbove_ = 0.0;  ///< radius above which a particle is large
    double smallMaxRadius_ = 0.0;
    double equalRadius_ = 0.0;  ///< the radius of every particle when all are equal, else 0
    std::vector<std::uint32_t> cellOf_;
    std::vector<std::uint32_t> cellStart_;
    std::vector<std::uint32_t> entries_;  ///< plus kPadding slots for the query's fixed windows
    std::vector<std::uint32_t> large_;
    std::vector<std::uint32_t> partTotals_;  ///< particles in the cell ranges before each part
    std::vector<ContactPair> largePairs_;
    std::vector<ContactPair> sortScratch_;
    PairChunks chunks_;
    std::vector<Band> bands_;  ///< one per query chunk
};

}  // namespace psb
