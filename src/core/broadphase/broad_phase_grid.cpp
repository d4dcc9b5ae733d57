#include "broadphase/broad_phase_grid.hpp"

#include <algorithm>
#include <cmath>

#include "broadphase/disc_overlap.hpp"
#include "support/parallel.hpp"

namespace psb {
namespace {

/// Relative slack added to the cell size and to query reaches so that rounding in
/// (x - origin) / cell can never put two overlapping particles two cells apart.
constexpr double kRelativeSlack = 1e-7;

/// Smallest cell size that finds every pair of discs up to `smallMax` metres in radius:
/// twice the radius, plus slack for rounding in the coordinates themselves.
double minCellSize(double smallMax, double maxAbsCoordinate) {
    return 2.0 * smallMax * (1.0 + kRelativeSlack) +
           64.0 * maxAbsCoordinate * 2.220446049250313e-16;
}

/// At most this many cells for `small` particles in the cells.
double maxCells(std::size_t small) {
    return std::max(1.0, GridBroadPhase::kCellsPerParticle * static_cast<double>(small));
}

/// The cell size a fresh plan picks for bounds w x h metres: the smallest that finds every pair
/// and keeps the cell count within `most`.
double freshCellSize(double minCell, double w, double h, double most) {
    double cell = std::max({minCell, std::sqrt(w * h / most), 1e-300});
    auto cellsFor = [&](double c) { return (std::floor(w / c) + 1.0) * (std::floor(h / c) + 1.0); };
    while (cellsFor(cell) > most)
        cell *= 1.0625;
    return cell;
}

}  // namespace

void GridBroadPhase::plan(const ParticleArrays& p, const ParticleStats& s) {
    const std::size_t n = p.size();
    large_.clear();
    largeAbove_ = 2.0 * s.meanRadius;
    smallMaxRadius_ = s.maxRadius;
    equalRadius_ = s.minRadius == s.maxRadius ? s.maxRadius : 0.0;
    if (s.maxRadius > largeAbove_) {
        smallMaxRadius_ = 0.0;
        const double* r = p.radius.data();
        for (std::size_t i = 0; i < n; ++i) {
            if (r[i] > largeAbove_) {
                large_.push_back(static_cast<std::uint32_t>(i));
            } else {
                smallMaxRadius_ = std::max(smallMaxRadius_, r[i]);
            }
        }
    }
    const std::size_t small = n - large_.size();
    const double w = s.maxX - s.minX, h = s.maxY - s.minY;
    // Rounding slack for coordinates up to twice today's, so that a plan kept for the next
    // steps does not have to be given up as soon as a particle moves further from the origin.
    const double cell = freshCellSize(minCellSize(smallMaxRadius_, 2.0 * s.maxAbsCoordinate), w, h,
                                      maxCells(small));
    cell_ = cell;
    map_.invCell = 1.0 / cell;
    map_.originX = s.minX;
    map_.originY = s.minY;
    map_.nx = static_cast<std::uint32_t>(std::floor(w / cell)) + 1;
    map_.ny = static_cast<std::uint32_t>(std::floor(h / cell)) + 1;
    planned_ = true;
}

bool GridBroadPhase::planStillFits(const ParticleStats& s, std::size_t n) const {
    // The cells were written for every particle, so none may be large now; then the small
    // radius is the largest.
    if (!large_.empty() || s.maxRadius > 2.0 * s.meanRadius) return false;
    const double minCell = minCellSize(s.maxRadius, s.maxAbsCoordinate);
    if (cell_ < minCell || static_cast<double>(cellCount()) > maxCells(n)) return false;
    const double w = s.maxX - s.minX, h = s.maxY - s.minY;
    if (cell_ > kCoarserPlan * freshCellSize(minCell, w, h, maxCells(n))) return false;
    // Particles beyond the edge share the edge cells; allow one cell of that.
    const double x0 = map_.originX - cell_, x1 = map_.originX + (map_.nx + 1) * cell_;
    const double y0 = map_.originY - cell_, y1 = map_.originY + (map_.ny + 1) * cell_;
    return s.minX >= x0 && s.maxX <= x1 && s.minY >= y0 && s.maxY <= y1;
}

std::optional<GridBroadPhase::MoveCells> GridBroadPhase::cellsForMove(std::size_t n) {
    if (!planned_ || !large_.empty()) return std::nullopt;
    cellOf_.resize(n);
    return MoveCells{map_, cellOf_.data()};
}

void GridBroadPhase::build(const ParticleArrays& p, const ParticleStats& stats, int threads,
                           bool cellsFromMove) {
    const std::size_t n = p.size();
    keptPlan_ = cellsFromMove && cellOf_.size() == n && planStillFits(stats, n);
    if (keptPlan_) {
        // Same geometry; the radius figures follow the particles (none is large).
        largeAbove_ = 2.0 * stats.meanRadius;
        smallMaxRadius_ = stats.maxRadius;
        equalRadius_ = stats.minRadius == stats.maxRadius ? stats.maxRadius : 0.0;
    } else {
        plan(p, stats);
    }
    cellOf_.resize(n);
    entries_.resize(n + kPadding);
    // Padding slots name particle 0: a window reading them tests a real particle, masked out.
    std::fill(entries_.begin() + static_cast<std::ptrdiff_t>(n), entries_.end(), 0u);
    const std::size_t cells = std::size_t{map_.nx + 2} * (map_.ny + 2);
    std::uint32_t* cellOf = cellOf_.data();
    if (!keptPlan_) {
        const double* x = p.x.data();
        const double* y = p.y.data();
        const double* r = p.radius.data();
        const double largeAbove = large_.empty() ? INFINITY : largeAbove_;
        const CellMap map = map_;
        parallel::forChunks(threads, parallel::chunksFor(threads, n), n,
                            [&](int, std::size_t begin, std::size_t end) {
                                for (std::size_t i = begin; i < end; ++i) {
                                    cellOf[i] = r[i] > largeAbove ? kLarge : map.cellOf(x[i], y[i]);
                                }
                            });
    }
    // Counting sort: histogram, inclusive prefix sum, backward scatter. Scattering from the
    // last particle down with pre-decrement leaves cellStart[c] at the start of cell c and
    // each cell's indices ascending.
    //
    // In parallel, each part owns a contiguous range of cells and does every pass for its
    // cells only: all parts read all of cellOf (4 bytes a particle, sequentially), but no cell
    // is touched by two threads, and each cell's slots come out exactly as in one pass, so
    // `entries` does not depend on the thread count.
    cellStart_.resize(cells + 1);
    std::uint32_t* start = cellStart_.data();
    std::uint32_t* entries = entries_.data();
    const int parts = parallel::chunksFor(threads, n) > 1 ? threads : 1;
    partTotals_.assign(static_cast<std::size_t>(parts) + 1, 0);
    auto cellBegin = [&](int part) { return (cells + 1) * part / parts; };
    parallel::forEachIndex(threads, parts, [&](std::size_t part) {
        const std::size_t lo = cellBegin(static_cast<int>(part));
        const std::size_t hi = cellBegin(static_cast<int>(part) + 1);
        std::fill(start + lo, start + hi, 0u);
        std::uint32_t count = 0;
        for (std::size_t i = 0; i < n; ++i) {
            const std::size_t c = cellOf[i];  // kLarge is beyond every range
            if (c - lo < hi - lo) {
                ++start[c];
                ++count;
            }
        }
        partTotals_[part + 1] = count;
    });
    for (int part = 0; part < parts; ++part)
        partTotals_[part + 1] += partTotals_[part];
    // The prefix sum starts at the particles of the parts before, so each part's slots follow
    // theirs without another pass over the cells.
    parallel::forEachIndex(threads, parts, [&](std::size_t part) {
        const std::size_t lo = cellBegin(static_cast<int>(part));
        const std::size_t hi = cellBegin(static_cast<int>(part) + 1);
        std::uint32_t sum = partTotals_[part];
        for (std::size_t c = lo; c < hi; ++c) {
            sum += start[c];
            start[c] = sum;
        }
        for (std::size_t i = n; i-- > 0;) {
            const std::size_t c = cellOf[i];
            if (c - lo < hi - lo) entries[--start[c]] = static_cast<std::uint32_t>(i);
        }
    });
    const std::uint32_t sum = partTotals_[parts];
    std::copy(large_.begin(), large_.end(), entries_.begin() + static_cast<std::ptrdiff_t>(sum));
}

void GridBroadPhase::findLargePairs(const ParticleArrays& p) {
    largePairs_.clear();
    const double* x = p.x.data();
    const double* y = p.y.data();
    const double* r = p.radius.data();
    const std::uint32_t* start = cellStart_.data();
    const std::uint32_t* entries = entries_.data();
    const std::uint32_t stride = map_.nx + 2;
    for (std::size_t a = 0; a < large_.size(); ++a) {
        const std::uint32_t l = large_[a];
        // A small particle overlapping l has its centre within r_l + smallMax of l's centre.
        const double reach = (r[l] + smallMaxRadius_) * (1.0 + kRelativeSlack) + cell_ * 1e-9;
        const std::uint32_t x0 = map_.cellX(x[l] - reach), x1 = map_.cellX(x[l] + reach);
        const std::uint32_t y0 = map_.cellY(y[l] - reach), y1 = map_.cellY(y[l] + reach);
        for (std::uint32_t cy = y0; cy <= y1; ++cy) {
            const std::uint32_t row = (cy + 1) * stride + 1;
            const std::uint32_t end = start[row + x1 + 1];
            for (std::uint32_t k = start[row + x0]; k < end; ++k) {
                const std::uint32_t j = entries[k];
                const std::uint32_t lo = std::min(l, j), hi = std::max(l, j);
                if (discsOverlap(x, y, r, lo, hi)) largePairs_.push_back({lo, hi});
            }
        }
        for (std::size_t b = a + 1; b < large_.size(); ++b) {
            const std::uint32_t m = large_[b];  // large_ is ascending, so l < m
            if (discsOverlap(x, y, r, l, m)) largePairs_.push_back({l, m});
        }
    }
}

namespace {

/// A slot's centre and radius, wherever the query reads them from.
struct SlotDisc {
    double x, y, r;
};

/// Tests slot `a` (in cell `cell`, disc `di`) against the later slots of its half stencil:
/// the rest of its cell and the east cell (one contiguous run of slots), then the three cells
/// of the row below (another run). The other four neighbours find it from their side; the
/// border ring of empty cells spares bounds checks. `at(k)` gives slot k's disc. Writes the
/// overlapping slot pairs (a, k) after the `found` already in the buffer `room(most)` returns,
/// and returns the new count.
template <bool kEqualRadii, std::uint32_t kWindowOwn, std::uint32_t kWindowBelow, typename At,
          typename Room>
inline std::size_t testStencil(std::uint32_t a, std::uint32_t cell, SlotDisc di,
                               const std::uint32_t* start, std::uint32_t stride, double contact,
                               At at, Room room, std::size_t found) {
    const std::uint32_t k0 = a + 1, k1 = start[cell + 2];
    const std::uint32_t k2 = start[cell + stride - 1], k3 = start[cell + stride + 2];
    ContactPair* buf = room(found + kWindowOwn + kWindowBelow + (k1 - k0) + (k3 - k2));
    // discsOverlap's arithmetic; it is symmetric in i and j to the last bit
    // (x[i] - x[j] is exactly -(x[j] - x[i])), so which of the two comes first does not
    // matter. Branch-free: most candidates miss, and a slot outside its run is masked out.
    auto test = [&](std::uint32_t k, bool inRun) {
        const SlotDisc dj = at(k);
        const double dx = dj.x - di.x;
        const double dy = dj.y - di.y;
        const double rs = kEqualRadii ? contact : di.r + dj.r;
        buf[found] = {a, k};
        found += static_cast<std::size_t>(inRun & (dx * dx + dy * dy < rs * rs));
    };
    for (std::uint32_t t = 0; t < kWindowOwn; ++t)
        test(k0 + t, k0 + t < k1);
    for (std::uint32_t t = 0; t < kWindowBelow; ++t)
        test(k2 + t, k2 + t < k3);
    for (std::uint32_t k = k0 + kWindowOwn; k < k1; ++k)
        test(k, true);
    for (std::uint32_t k = k2 + kWindowBelow; k < k3; ++k)
        test(k, true);
    return found;
}

}  // namespace

void GridBroadPhase::Band::gather(const ParticleArrays& p, const std::uint32_t* entries,
                                  const std::uint32_t* cellOf, std::size_t a, std::size_t b,
                                  std::size_t reach, bool radii) {
    const double* px = p.x.data();
    const double* py = p.y.data();
    const double* pr = p.radius.data();
    double* bx = x.data();
    double* by = y.data();
    double* br = r.data();
    std::uint32_t* bc = cell.data();
    for (std::size_t s = a; s < b; ++s) {
        const std::uint32_t i = entries[s];
        bx[s - a] = px[i];
        by[s - a] = py[i];
        bc[s - a] = cellOf[i];
    }
    for (std::size_t s = b; s < reach; ++s) {
        const std::uint32_t i = entries[s];
        bx[s - a] = px[i];
        by[s - a] = py[i];
    }

    if (radii) {
        for (std::size_t s = a; s < reach; ++s)
            br[s - a] = pr[entries[s]];
    }
    // Slots a window may read past the reach (always masked out).
    for (std::size_t k = reach - a; k < reach - a + kPadding; ++k) {
        bx[k] = by[k] = 0.0;
        if (radii) br[k] = 0.0;
    }
}

template <bool kEqualRadii>
void GridBroadPhase::queryChunk(const ParticleArrays& p, int c, std::size_t begin, std::size_t end,
                                std::size_t bandSlots) {
    const double* x = p.x.data();
    const double* y = p.y.data();
    const double* r = p.radius.data();
    const std::uint32_t* cellOf = cellOf_.data();
    const std::uint32_t* start = cellStart_.data();
    const std::uint32_t* entries = entries_.data();
    const std::uint32_t stride = map_.nx + 2;
    // kEqualRadii: every particle has the same radius (common: gases, most presets), so the
    // contact distance is one constant and no radius is read. Same arithmetic: r + r is
    // exactly the constant.
    const double contact = equalRadius_ + equalRadius_;
    // The slots any stencil of slots [a, b) reaches end here (cells ascend with the slots).
    auto reachOf = [&](std::size_t b) {
        return std::size_t{start[cellOf[entries[b - 1]] + stride + 2]};
    };
    auto room = [&](std::size_t most) { return chunks_.room(c, most); };
    Band& band = bands_[static_cast<std::size_t>(c)];
    const std::size_t capacity = 2 * bandSlots;
    band.makeRoom(capacity + kPadding, !kEqualRadii);
    std::size_t found = 0;
    for (std::size_t a = begin; a < end;) {
        const std::size_t b = std::min(end, a + bandSlots);
        const std::size_t reach = reachOf(b);
        if (reach - a > capacity) {
            // Rows far longer than a band (a thin strip of particles): query these slots where
            // the particles are.
            for (std::size_t s = a; s < b; ++s) {
                const std::uint32_t i = entries[s];
                found = testStencil<kEqualRadii, kWindowOwn, kWindowBelow>(
                    static_cast<std::uint32_t>(s), cellOf[i], {x[i], y[i], r[i]}, start, stride,
                    contact,
                    [&](std::uint32_t k) {
                        const std::uint32_t j = entries[k];
                        return SlotDisc{x[j], y[j], kEqualRadii ? 0.0 : r[j]};
                    },
                    room, found);
            }
            a = b;
            continue;
        }
        band.gather(p, entries, cellOf, a, b, reach, !kEqualRadii);
        const double* bx = band.x.data();
        const double* by = band.y.data();
        const double* br = band.r.data();
        const std::uint32_t* bc = band.cell.data();
        const std::uint32_t first = static_cast<std::uint32_t>(a);
        auto at = [&](std::uint32_t k) {
            return SlotDisc{bx[k - first], by[k - first], kEqualRadii ? 0.0 : br[k - first]};
        };
        for (std::size_t s = a; s < b; ++s) {
            const std::uint32_t slot = static_cast<std::uint32_t>(s);
            found = testStencil<kEqualRadii, kWindowOwn, kWindowBelow>(
                slot, bc[s - a], at(slot), start, stride, contact, at, room, found);
        }
        a = b;
    }
    // Slot pairs to particle pairs, lower index first.
    ContactPair* buf = chunks_.room(c, found);
    for (std::size_t f = 0; f < found; ++f) {
        const std::uint32_t i = entries[buf[f].i], j = entries[buf[f].j];
        buf[f] = {std::min(i, j), std::max(i, j)};
    }
    chunks_.setFound(c, found);
}

void GridBroadPhase::findPairs(const ParticleArrays& p, int threads,
                               std::vector<ContactPair>& out) {
    const std::size_t n = p.size();
    const std::size_t small = n - large_.size();
    // Chunks are ranges of slots (cell order), not of particle indices.
    const int chunks = parallel::chunksFor(threads, small);
    chunks_.prepare(chunks);
    if (bands_.size() < static_cast<std::size_t>(chunks)) bands_.resize(chunks);
    const std::size_t bandSlots = std::clamp<std::size_t>(
        small / (kBandsPerChunk * static_cast<std::size_t>(chunks)), kMinBand, kMaxBand);
    const bool equalRadii = equalRadius_ > 0.0;
    parallel::forChunks(threads, chunks, small, [&](int c, std::size_t begin, std::size_t end) {
        if (equalRadii) {
            queryChunk<true>(p, c, begin, end, bandSlots);
        } else {
            queryChunk<false>(p, c, begin, end, bandSlots);
        }
    });
    const std::size_t before = out.size();
    std::size_t total = chunks_.total();
    if (!large_.empty()) {
        findLargePairs(p);
        total += largePairs_.size();
    }
    out.resize(before + total);
    ContactPair* dst = chunks_.copyTo(out.data() + before);
    std::copy(largePairs_.begin(), largePairs_.end(), dst);
    // Found in cell order; the resolve stage needs ascending (i, j).
    sortPairs(out, before, sortScratch_, static_cast<std::uint32_t>(n));
}

std::size_t GridBroadPhase::memoryBytes() const {
    std::size_t bytes = sizeof(std::uint32_t) * (cellOf_.capacity() + cellStart_.capacity() +
                                                 entries_.capacity() + large_.capacity());
    bytes += sizeof(ContactPair) * (largePairs_.capacity() + sortScratch_.capacity());
    for (const Band& band : bands_)
        bytes += band.memoryBytes();
    return bytes + chunks_.memoryBytes();
}

}  // namespace psb
