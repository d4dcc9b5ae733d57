#include "broadphase/broad_phase_periodic_grid.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

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
                                   const ParticleStats& stats, int threads) {
    const double maxRadius = stats.maxRadius;
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
    images_ = nx_ >= 3 && ny_ >= 3;
    if (images_) {
        const double reach = 2.0 * maxRadius * (1.0 + kRelativeSlack) + rounding;
        const ParticleStats copyStats = buildImages(p, stats, reach);
        grid_.build(copy_, copyStats, threads, cellsWritten_);
        return;
    }
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

ParticleStats PeriodicGridBroadPhase::buildImages(const ParticleArrays& p,
                                                  const ParticleStats& stats, double reach) {
    const std::size_t n = p.size();
    const double w = box_.width, h = box_.height;
    const double grow = 1e-12 * std::max(w, h);
    copy_.x.resize(n);
    copy_.y.resize(n);
    copy_.radius.resize(n);
    source_.clear();
    imageX_.clear();
    imageY_.clear();
    const auto image = [&](std::size_t i, double x, double y) {
        source_.push_back(static_cast<std::uint32_t>(i));
        imageX_.push_back(x);
        imageY_.push_back(y);
    };
    // One pass over the particles writes the copy, its cells under the box grid's last plan
    // (which the grid keeps while it fits, as it keeps the cells the box's move stage writes)
    // and marks the centres off the interior; it has no branch, so it vectorises. A second
    // pass over the marks wraps those centres and makes their images: the positions are read
    // once, while in cache.
    const std::optional<GridBroadPhase::MoveCells> cells = grid_.cellsForMove(n);
    std::uint32_t* cellOf = cells ? cells->cellOf : nullptr;
    const GridBroadPhase::CellMap map = cells ? cells->map : GridBroadPhase::CellMap{};
    const double* px = p.x.data();
    const double* py = p.y.data();
    const double* r = p.radius.data();
    double* cx = copy_.x.data();
    double* cy = copy_.y.data();
    double* cr = copy_.radius.data();
    edge_.resize(n);
    std::uint8_t* edge = edge_.data();
    const double top = h - reach;
    for (std::size_t i = 0; i < n; ++i) {
        const double x = px[i], y = py[i];
        cx[i] = x;
        cy[i] = y;
        cr[i] = r[i] + grow;
        edge[i] = static_cast<std::uint8_t>(!(x >= reach) | !(x < w) | !(y >= reach) | !(y < top));
    }
    if (cellOf) {
        for (std::size_t i = 0; i < n; ++i)
            cellOf[i] = map.cellOf(cx[i], cy[i]);
    }
    for (std::size_t i = 0; i < n; ++i) {
        if (edge[i] == 0) continue;
        double x = cx[i], y = cy[i];
        // Wrapped as the wrap stage will (a centre may be a step's travel outside the box).
        double unwrap = 0.0;
        periodic::wrapInto(x, unwrap, w);
        periodic::wrapInto(y, unwrap, h);
        cx[i] = x;
        cy[i] = y;
        if (cellOf) cellOf[i] = map.cellOf(x, y);
        const bool left = x < reach, bottom = y < reach, high = y >= top;
        if (left) image(i, x + w, y);
        if (bottom) image(i, x, y + h);
        if (left && bottom) image(i, x + w, y + h);
        if (left && high) image(i, x + w, y - h);
    }
    const std::size_t images = source_.size();
    copy_.x.insert(copy_.x.end(), imageX_.begin(), imageX_.end());
    copy_.y.insert(copy_.y.end(), imageY_.begin(), imageY_.end());
    copy_.radius.resize(n + images);
    for (std::size_t k = 0; k < images; ++k)
        copy_.radius[n + k] = copy_.radius[source_[k]];
    if (cells) {
        cellOf = grid_.cellsForMove(n + images)->cellOf;  // the first n kept
        for (std::size_t k = 0; k < images; ++k)
            cellOf[n + k] = map.cellOf(imageX_[k], imageY_[k]);
    }
    cellsWritten_ = cells.has_value();
    // The copy's bounds follow from the box and the reach; its radii are the particles' (grown).
    ParticleStats s = stats;
    s.count = copy_.x.size();
    s.minX = 0.0;
    s.maxX = w + reach;
    s.minY = -reach;
    s.maxY = h + reach;
    s.maxAbsCoordinate = std::max(w, h) + reach;
    s.minRadius += grow;
    s.meanRadius += grow;
    s.maxRadius += grow;
    return s;
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
    for (std::size_t c = begin; c < end; ++c) {
        const std::uint32_t a0 = start[c], a1 = start[c + 1];
        if (a0 == a1) continue;
        const std::int64_t cx = static_cast<std::int64_t>(c) % nx_;
        const std::int64_t cy = static_cast<std::int64_t>(c) / nx_;
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
    if (images_) {
        found_.clear();
        grid_.findPairs(copy_, threads, found_);
        // Pairs of two particles come first and ascending; those with an image, far fewer, are
        // sorted apart and merged in.
        const std::size_t before = out.size();
        acrossEdges_.clear();
        const double* x = p.x.data();
        const double* y = p.y.data();
        const double* r = p.radius.data();
        for (const ContactPair& f : found_) {
            if (f.i >= n) continue;  // two images (f.i < f.j)
            if (f.j < n) {
                if (discsOverlapPeriodic(x, y, r, f.i, f.j, box_)) out.push_back(f);
                continue;
            }
            const std::uint32_t j = source_[f.j - n];
            if (j == f.i) continue;  // a particle and its own image
            const ContactPair pair{std::min(f.i, j), std::max(f.i, j)};
            if (discsOverlapPeriodic(x, y, r, pair.i, pair.j, box_)) acrossEdges_.push_back(pair);
        }
        std::sort(acrossEdges_.begin(), acrossEdges_.end());
        const std::size_t middle = out.size();
        out.insert(out.end(), acrossEdges_.begin(), acrossEdges_.end());
        std::inplace_merge(out.begin() + static_cast<std::ptrdiff_t>(before),
                           out.begin() + static_cast<std::ptrdiff_t>(middle), out.end());
        return;
    }
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
    return sizeof(std::uint32_t) *
               (cellOf_.capacity() + cellStart_.capacity() + entries_.capacity() +
                sortScratchCells_.capacity() + source_.capacity()) +
           sizeof(double) * (copy_.x.capacity() + copy_.y.capacity() + copy_.radius.capacity() +
                             imageX_.capacity() + imageY_.capacity()) +
           edge_.capacity() +
           sizeof(ContactPair) *
               (sortScratch_.capacity() + found_.capacity() + acrossEdges_.capacity()) +
           chunks_.memoryBytes() + grid_.memoryBytes();
}

}  // namespace psb
