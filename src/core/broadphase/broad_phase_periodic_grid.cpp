#include "broadphase/broad_phase_periodic_grid.hpp"

#include <algorithm>
#include <cmath>

#include "broadphase/disc_overlap.hpp"
#include "support/parallel.hpp"

namespace psb {
namespace {

/// Relative slack on the cell size, so that rounding in x · cells-per-metre never puts two
/// overlapping discs two cells apart (as in broad_phase_grid.cpp).
constexpr double kRelativeSlack = 1e-7;

/// Whole cells of at least `minCell` metres across `extent`: at least one.
std::int64_t cellsAcross(double extent, double minCell) {
    const double k = std::floor(extent / minCell);
    return k >= 1.0 ? static_cast<std::int64_t>(std::min(k, 1e9)) : 1;
}

}  // namespace

void PeriodicGridBroadPhase::build(const ParticleArrays& p, const periodic::Box& box,
                                   double maxRadius, int threads) {
    const std::size_t n = p.size();
    box_ = box;
    const double rounding = 64.0 * std::max(box.width, box.height) * 2.220446049250313e-16;
    double minCell = 2.0 * maxRadius * (1.0 + kRelativeSlack) + rounding;
    const double most = std::max(1.0, kCellsPerParticle * static_cast<double>(n));
    minCell = std::max({minCell, std::sqrt(box.width * box.height / most), 1e-300});
    for (;;) {
        nx_ = cellsAcross(box.width, minCell);
        ny_ = cellsAcross(box.height, minCell);
        if (static_cast<double>(nx_) * static_cast<double>(ny_) <= most) break;
        minCell *= 1.0625;
    }
    invCellX_ = static_cast<double>(nx_) / box.width;
    invCellY_ = static_cast<double>(ny_) / box.height;
    const auto cells = static_cast<std::size_t>(nx_ * ny_);
    cellOf_.resize(n);
    entries_.resize(n);
    cellStart_.assign(cells + 1, 0);
    const double* x = p.x.data();
    const double* y = p.y.data();
    std::uint32_t* cellOf = cellOf_.data();
    parallel::forChunks(threads, parallel::chunksFor(threads, n), n,
                        [&](int, std::size_t begin, std::size_t end) {
                            for (std::size_t i = begin; i < end; ++i)
                                cellOf[i] = this->cellOf(x[i], y[i]);
                        });
    // Counting sort; the backward scatter leaves each cell's indices ascending.
    std::uint32_t* start = cellStart_.data();
    for (std::size_t i = 0; i < n; ++i)
        ++start[cellOf[i] + 1];
    for (std::size_t c = 0; c < cells; ++c)
        start[c + 1] += start[c];
    std::vector<std::uint32_t>& fill = sortScratchCells_;
    fill.assign(cellStart_.begin(), cellStart_.end() - 1);
    for (std::size_t i = 0; i < n; ++i)
        entries_[fill[cellOf[i]]++] = static_cast<std::uint32_t>(i);
}

std::uint32_t PeriodicGridBroadPhase::cellOf(double x, double y) const {
    const auto wrapped = [](double v, double perMetre, std::int64_t count) {
        const double f = std::floor(v * perMetre);
        if (!(f >= 0.0 && f < static_cast<double>(count))) {
            if (!std::isfinite(f)) return std::int64_t{0};
            const double m = f - static_cast<double>(count) * std::floor(f / count);
            return std::clamp(static_cast<std::int64_t>(m), std::int64_t{0}, count - 1);
        }
        return static_cast<std::int64_t>(f);
    };
    return static_cast<std::uint32_t>(wrapped(y, invCellY_, ny_) * nx_ +
                                      wrapped(x, invCellX_, nx_));
}

void PeriodicGridBroadPhase::queryCells(const ParticleArrays& p, int chunk, std::size_t begin,
                                        std::size_t end) {
    const double* x = p.x.data();
    const double* y = p.y.data();
    const double* r = p.radius.data();
    const std::uint32_t* start = cellStart_.data();
    const std::uint32_t* entries = entries_.data();
    std::size_t found = 0;
    const auto testRun = [&](std::uint32_t i, std::uint32_t k0, std::uint32_t k1) {
        ContactPair* buf = chunks_.room(chunk, found + (k1 - k0));
        for (std::uint32_t k = k0; k < k1; ++k) {
            const std::uint32_t j = entries[k];
            const std::uint32_t lo = std::min(i, j), hi = std::max(i, j);
            buf[found] = {lo, hi};
            found += static_cast<std::size_t>(discsOverlapPeriodic(x, y, r, lo, hi, box_));
        }
    };
    // Cells whose whole half stencil lies off the box's edge rows and columns: every particle
    // in them is inside the box (only a centre a step outside it lands in an edge cell, by the
    // wrap of cellOf), so two of them are less than half a box apart and the plain test is the
    // nearest-image test, bit for bit (minimumImage returns such a separation unchanged).
    const bool inner = nx_ >= 6 && ny_ >= 6;
    const auto stride = static_cast<std::uint32_t>(nx_);
    for (std::size_t c = begin; c < end; ++c) {
        const std::uint32_t a0 = start[c], a1 = start[c + 1];
        if (a0 == a1) continue;
        const std::int64_t cx = static_cast<std::int64_t>(c) % nx_;
        const std::int64_t cy = static_cast<std::int64_t>(c) / nx_;
        if (inner && cx >= 2 && cx <= nx_ - 3 && cy >= 1 && cy <= ny_ - 3) {
            const auto cell = static_cast<std::uint32_t>(c);
            // The east cell follows this one in `entries`; the three below are one run too.
            const std::uint32_t own1 = start[cell + 2];
            const std::uint32_t below0 = start[cell + stride - 1],
                                below1 = start[cell + stride + 2];
            ContactPair* buf = chunks_.room(
                chunk, found + std::size_t{a1 - a0} * ((own1 - a0) + (below1 - below0)));
            for (std::uint32_t a = a0; a < a1; ++a) {
                const std::uint32_t i = entries[a];
                for (std::uint32_t k = a + 1; k < own1; ++k) {
                    const std::uint32_t j = entries[k];
                    const std::uint32_t lo = std::min(i, j), hi = std::max(i, j);
                    buf[found] = {lo, hi};
                    found += static_cast<std::size_t>(discsOverlap(x, y, r, lo, hi));
                }
                for (std::uint32_t k = below0; k < below1; ++k) {
                    const std::uint32_t j = entries[k];
                    const std::uint32_t lo = std::min(i, j), hi = std::max(i, j);
                    buf[found] = {lo, hi};
                    found += static_cast<std::size_t>(discsOverlap(x, y, r, lo, hi));
                }
            }
            continue;
        }
        // The distinct neighbours with a higher index (fewer than eight in a box one or two
        // cells across, where they repeat).
        std::uint32_t later[8];
        int count = 0;
        for (std::int64_t oy = -1; oy <= 1; ++oy) {
            for (std::int64_t ox = -1; ox <= 1; ++ox) {
                const std::int64_t kx = (cx + ox + nx_) % nx_, ky = (cy + oy + ny_) % ny_;
                const auto d = static_cast<std::uint32_t>(ky * nx_ + kx);
                if (d <= c || std::find(later, later + count, d) != later + count) continue;
                later[count++] = d;
            }
        }
        for (std::uint32_t a = a0; a < a1; ++a) {
            const std::uint32_t i = entries[a];
            testRun(i, a + 1, a1);
            for (int m = 0; m < count; ++m)
                testRun(i, start[later[m]], start[later[m] + 1]);
        }
    }
    chunks_.setFound(chunk, found);
}

void PeriodicGridBroadPhase::findPairs(const ParticleArrays& p, int threads,
                                       std::vector<ContactPair>& out) {
    const std::size_t n = p.size();
    const auto cells = static_cast<std::size_t>(nx_ * ny_);
    const int chunks = parallel::chunksFor(threads, n);
    chunks_.prepare(chunks);
    parallel::forChunks(threads, chunks, cells, [&](int c, std::size_t begin, std::size_t end) {
        queryCells(p, c, begin, end);
    });
    const std::size_t before = out.size();
    out.resize(before + chunks_.total());
    chunks_.copyTo(out.data() + before);
    sortPairs(out, before, sortScratch_, static_cast<std::uint32_t>(n));
}

std::size_t PeriodicGridBroadPhase::memoryBytes() const {
    return sizeof(std::uint32_t) * (cellOf_.capacity() + cellStart_.capacity() +
                                    entries_.capacity() + sortScratchCells_.capacity()) +
           sizeof(ContactPair) * sortScratch_.capacity() + chunks_.memoryBytes();
}

}  // namespace psb
