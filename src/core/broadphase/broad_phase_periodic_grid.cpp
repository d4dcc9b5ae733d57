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
                                   const ParticleStats& stats, int threads, bool cellsFromMove,
                                   bool marksFromMove) {
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
    strips_ = nx_ >= 3 && ny_ >= 3;
    if (strips_) {
        reach_ = 2.0 * maxRadius * (1.0 + kRelativeSlack) + rounding;
        const bool inBox = stats.minX >= 0.0 && stats.maxX < box.width && stats.minY >= 0.0 &&
                           stats.maxY < box.height;
        copied_ = !inBox;
        if (!copied_) {
            grid_.build(p, stats, threads, cellsFromMove);
            // Marks made for a smaller reach would miss discs (larger ones were added).
            if (marksFromMove && marksReach_ >= reach_ && marked_.size() == parallel::blockCount(n))
                collectMarkedStrips(p);
            else
                collectStrips(p);
            return;
        }
        wrapCopy(p);
        // The copy's bounds follow from the box; its radii are the particles' grown by a hair,
        // so rounding in the wrapped coordinates never loses a pair.
        const double grow = 1e-12 * std::max(box.width, box.height);
        ParticleStats s = stats;
        s.minX = 0.0;
        s.maxX = box.width;
        s.minY = 0.0;
        s.maxY = box.height;
        s.maxAbsCoordinate = std::max(box.width, box.height);
        s.minRadius += grow;
        s.meanRadius += grow;
        s.maxRadius += grow;
        for (double& r : copy_.radius)
            r += grow;
        reach_ += 2.0 * grow;
        grid_.build(copy_, s, threads);
        collectStrips(copy_);
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

std::optional<GridBroadPhase::MoveCells> PeriodicGridBroadPhase::cellsForMove(std::size_t n) {
    if (!strips_) return std::nullopt;
    return grid_.cellsForMove(n);
}

std::optional<PeriodicGridBroadPhase::EdgeMarks> PeriodicGridBroadPhase::marksForMove(
    std::size_t n) {
    if (!strips_) return std::nullopt;
    marked_.resize(parallel::blockCount(n));
    marksReach_ = reach_;
    return EdgeMarks{marked_.data(), reach_};
}

void PeriodicGridBroadPhase::wrapCopy(const ParticleArrays& p) {
    const std::size_t n = p.size();
    copy_.x.assign(p.x.begin(), p.x.end());
    copy_.y.assign(p.y.begin(), p.y.end());
    copy_.radius.assign(p.radius.begin(), p.radius.end());
    for (std::size_t i = 0; i < n; ++i) {
        double unwrap = 0.0;
        periodic::wrapInto(copy_.x[i], unwrap, box_.width);
        periodic::wrapInto(copy_.y[i], unwrap, box_.height);
        // A non-finite centre is left where it is: no pair can be found with it.
    }
}

void PeriodicGridBroadPhase::collectStrips(const ParticleArrays& q) {
    const std::size_t n = q.size();
    const double* x = q.x.data();
    const double* y = q.y.data();
    const double reach = reach_, right = box_.width - reach_, top = box_.height - reach_;
    candidates_.clear();
    for (std::size_t i = 0; i < n; ++i) {
        // Nearly every centre is in the interior: one test for the four edges.
        if (x[i] >= reach && x[i] < right && y[i] >= reach && y[i] < top) continue;
        candidates_.push_back(static_cast<std::uint32_t>(i));
    }
    sortIntoStrips(q, {&candidates_, 1});
}

void PeriodicGridBroadPhase::collectMarkedStrips(const ParticleArrays& q) {
    sortIntoStrips(q, {marked_.data(), parallel::blockCount(q.size())});
}

void PeriodicGridBroadPhase::sortIntoStrips(const ParticleArrays& q,
                                            std::span<const std::vector<std::uint32_t>> lists) {
    const double* x = q.x.data();
    const double* y = q.y.data();
    const double reach = reach_, right = box_.width - reach_, top = box_.height - reach_;
    std::size_t count = 0;
    for (const std::vector<std::uint32_t>& list : lists)
        count += list.size();
    // Each disc is written to every list and kept where it belongs: no branch on where.
    left_.resize(count);
    right_.resize(count);
    bottom_.resize(count);
    top_.resize(count);
    std::size_t nl = 0, nr = 0, nb = 0, nt = 0;
    for (const std::vector<std::uint32_t>& list : lists) {
        for (const std::uint32_t i : list) {
            left_[nl] = right_[nr] = bottom_[nb] = top_[nt] = i;
            nl += static_cast<std::size_t>(x[i] < reach);
            nr += static_cast<std::size_t>(x[i] >= right);
            nb += static_cast<std::size_t>(y[i] < reach);
            nt += static_cast<std::size_t>(y[i] >= top);
        }
    }
    left_.resize(nl);
    right_.resize(nr);
    bottom_.resize(nb);
    top_.resize(nt);
}

void PeriodicGridBroadPhase::stripPairs(const ParticleArrays& p,
                                        const std::vector<std::uint32_t>& low,
                                        const std::vector<std::uint32_t>& high, bool alongY,
                                        bool skipAcrossX) {
    if (low.empty() || high.empty()) return;
    const ParticleArrays& q = copied_ ? copy_ : p;
    // Bands along the strip, each at least one reach long: two discs that touch are in the
    // same band or in neighbouring ones (the first and the last are neighbours), three apart.
    const double length = alongY ? box_.height : box_.width;
    // No more bands than discs to sort into them: each band then holds one or two.
    const std::int64_t bands = std::max<std::int64_t>(
        3, std::min(cellsAcross(length, reach_), static_cast<std::int64_t>(high.size())));
    const double perMetre = static_cast<double>(bands) / length;
    const std::vector<double>& along = alongY ? q.y : q.x;
    const auto bandOf = [&](std::uint32_t i) {
        const double f = std::floor(along[i] * perMetre);
        return static_cast<std::int64_t>(std::clamp(f, 0.0, static_cast<double>(bands - 1)));
    };
    bandStart_.assign(static_cast<std::size_t>(bands) + 1, 0);
    for (const std::uint32_t j : high)
        ++bandStart_[static_cast<std::size_t>(bandOf(j)) + 1];
    for (std::size_t b = 0; b < static_cast<std::size_t>(bands); ++b)
        bandStart_[b + 1] += bandStart_[b];
    sortScratchCells_.assign(bandStart_.begin(), bandStart_.end() - 1);
    bandEntries_.resize(high.size());
    for (const std::uint32_t j : high)
        bandEntries_[sortScratchCells_[static_cast<std::size_t>(bandOf(j))]++] = j;
    const double* x = p.x.data();
    const double* y = p.y.data();
    const double* r = p.radius.data();
    // The banded discs' centres and radii in slot order: the tests below read them in a run
    // (the discs of a strip lie all over the particle arrays, a row of the box apart).
    bandX_.resize(high.size());
    bandY_.resize(high.size());
    bandR_.resize(high.size());
    for (std::size_t k = 0; k < high.size(); ++k) {
        const std::uint32_t j = bandEntries_[k];
        bandX_[k] = x[j];
        bandY_[k] = y[j];
        bandR_[k] = r[j];
    }
    const double* bx = bandX_.data();
    const double* by = bandY_.data();
    const double* br = bandR_.data();
    const double width = box_.width, height = box_.height;
    const double halfWidth = 0.5 * width, halfHeight = 0.5 * height;
    // Centres in the box (no copy) are less than a box apart: the nearest image is the
    // separation or one box off it, as minimumImage gives it bit for bit, without its division
    // and rounding. A copy's pairs are measured on the caller's centres, which may be further.
    const bool inBox = !copied_;
    const auto image = [](double d, double extent, double half) {
        return std::abs(d) <= half ? d : d - std::copysign(extent, d);
    };
    // Room for every candidate of the three bands of each disc (the fullest band thrice), so
    // that the loop below neither grows the list nor branches on it.
    std::uint32_t fullest = 0;
    for (std::size_t b = 0; b < static_cast<std::size_t>(bands); ++b)
        fullest = std::max(fullest, bandStart_[b + 1] - bandStart_[b]);
    std::size_t found = acrossEdges_.size();
    acrossEdges_.resize(found + low.size() * 3 * fullest);
    ContactPair* out = acrossEdges_.data();
    // Tests i against the discs in slots [k0, k1) of the bands, branch-free: every candidate is
    // written and kept (found advanced) only if it touches. The test is symmetric in i and j
    // to the last bit; the pairs kept are put in (i < j) order below.
    const auto testRange = [&](std::uint32_t i, std::uint32_t k0, std::uint32_t k1) {
        if (inBox) {
            const double xi = x[i], yi = y[i], ri = r[i];
            for (std::uint32_t k = k0; k < k1; ++k) {
                const double dx = image(bx[k] - xi, width, halfWidth);
                const double dy = image(by[k] - yi, height, halfHeight);
                const double rs = ri + br[k];
                bool touch = dx * dx + dy * dy < rs * rs;
                // Pairs across the sides as well as the top and bottom were found in the first
                // pass.
                if (skipAcrossX) touch = touch & (std::abs(bx[k] - xi) <= halfWidth);
                out[found] = {i, bandEntries_[k]};
                found += static_cast<std::size_t>(touch);
            }
            return;
        }
        for (std::uint32_t k = k0; k < k1; ++k) {
            const std::uint32_t j = bandEntries_[k];
            bool touch = discsOverlapPeriodic(x, y, r, i, j, box_);
            if (skipAcrossX) touch = touch & (std::abs(q.x[j] - q.x[i]) <= halfWidth);
            out[found] = {i, j};
            found += static_cast<std::size_t>(touch);
        }
    };
    const std::uint32_t* start = bandStart_.data();
    const auto last = static_cast<std::size_t>(bands - 1);
    for (const std::uint32_t i : low) {
        // The band of i and its two neighbours: one run of slots, or two where they wrap.
        const auto b = static_cast<std::size_t>(bandOf(i));
        if (b == 0) {
            testRange(i, start[0], start[2]);
            testRange(i, start[last], start[last + 1]);
        } else if (b == last) {
            testRange(i, start[last - 1], start[last + 1]);
            testRange(i, start[0], start[1]);
        } else {
            testRange(i, start[b - 1], start[b + 2]);
        }
    }
    acrossEdges_.resize(found);
    for (ContactPair& c : acrossEdges_) {
        if (c.i > c.j) std::swap(c.i, c.j);
    }
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
    if (strips_) {
        const std::size_t before = out.size();
        if (!copied_) {
            grid_.findPairs(p, threads, out);
        } else {
            found_.clear();
            grid_.findPairs(copy_, threads, found_);
            for (const ContactPair& f : found_) {
                if (discsOverlapPeriodic(p.x.data(), p.y.data(), p.radius.data(), f.i, f.j, box_))
                    out.push_back(f);
            }
        }
        // The pairs across the edges, far fewer, are sorted apart and merged in.
        acrossEdges_.clear();
        stripPairs(p, left_, right_, /*alongY=*/true, /*skipAcrossX=*/false);
        stripPairs(p, bottom_, top_, /*alongY=*/false, /*skipAcrossX=*/true);
        std::sort(acrossEdges_.begin(), acrossEdges_.end());
        // Merged from the back, in place: only the pairs after the first one across an edge
        // move, and no buffer is allocated (std::inplace_merge takes one at every call).
        std::size_t a = out.size();
        std::size_t b = acrossEdges_.size();
        out.resize(a + b);
        std::size_t w = out.size();
        while (b > 0) {
            out[--w] =
                a > before && acrossEdges_[b - 1] < out[a - 1] ? out[--a] : acrossEdges_[--b];
        }
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
    std::size_t marked = 0;
    for (const std::vector<std::uint32_t>& m : marked_)
        marked += sizeof(std::uint32_t) * m.capacity();
    return marked +
           sizeof(std::uint32_t) *
               (cellOf_.capacity() + cellStart_.capacity() + entries_.capacity() +
                sortScratchCells_.capacity() + left_.capacity() + right_.capacity() +
                bottom_.capacity() + top_.capacity() + candidates_.capacity() +
                bandStart_.capacity() + bandEntries_.capacity()) +
           sizeof(double) * (bandX_.capacity() + bandY_.capacity() + bandR_.capacity()) +
           sizeof(double) * (copy_.x.capacity() + copy_.y.capacity() + copy_.radius.capacity()) +
           sizeof(ContactPair) *
               (sortScratch_.capacity() + found_.capacity() + acrossEdges_.capacity()) +
           chunks_.memoryBytes() + grid_.memoryBytes();
}

}  // namespace psb
