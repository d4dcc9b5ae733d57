#include "obstacles/obstacle_grid.hpp"

#include <algorithm>
#include <cmath>

#include "obstacles/obstacle_geometry.hpp"

namespace psb {

void ObstacleGrid::build(const Obstacles& obstacles, double pad) {
    obstacles_ = obstacles;
    built_ = true;
    pad_ = std::isfinite(pad) && pad > 0.0 ? pad : 0.0;
    maxRadius_ = 0.0;
    cellStart_.clear();
    entries_.clear();
    occupied_.clear();
    gap_.clear();
    nx_ = ny_ = 0;
    if (obstacles.empty()) return;

    // The pad of a particle flung at an absurd speed could make the extent overflow (and the
    // cell counts not a number). A pad far wider than the obstacles' field and coordinates gains
    // nothing (every lookup lists them all), so it is capped there; only speed depends on it.
    double scale = 0.0;
    for (const Obstacle& o : obstacles) {
        scale = std::max({scale, std::abs(o.a.x()), std::abs(o.a.y()), std::abs(o.b.x()),
                          std::abs(o.b.y()), o.radius});
    }
    if (std::isfinite(scale)) pad_ = std::min(pad_, kMaxPadScales * scale);
    x0_ = y0_ = INFINITY;
    x1_ = y1_ = -INFINITY;
    for (const Obstacle& o : obstacles) {
        const double reach = o.radius + pad_;
        x0_ = std::min(x0_, std::min(o.a.x(), o.b.x()) - reach);
        y0_ = std::min(y0_, std::min(o.a.y(), o.b.y()) - reach);
        x1_ = std::max(x1_, std::max(o.a.x(), o.b.x()) + reach);
        y1_ = std::max(y1_, std::max(o.a.y(), o.b.y()) + reach);
        maxRadius_ = std::max(maxRadius_, o.radius);
    }
    const double w = x1_ - x0_, h = y1_ - y0_;
    const double n = static_cast<double>(obstacles.size());
    // Cells as wide as the pad: then a lookup's cell lies mostly within the pad of the point it
    // was made for, and few cells far from every obstacle list one.
    cell_ = pad_ > 0.0 ? pad_ : std::sqrt(w * h / (kCellsPerObstacle * n));
    // Never more than kMaxCells cells, nor more than that many along one side (a thin strip).
    const double maxCells = static_cast<double>(kMaxCells);
    cell_ = std::max({cell_, w / maxCells, h / maxCells, std::sqrt(w * h / maxCells)});
    if (!(cell_ > 0.0) || !std::isfinite(cell_)) cell_ = std::max(w, h);
    invCell_ = 1.0 / cell_;
    // Cells along a side: at least one, also where an extent near the largest double makes the
    // count not a number.
    const auto along = [&](double extent) {
        const double c = std::ceil(extent * invCell_);
        return static_cast<std::uint32_t>(c >= 1.0 ? std::min(c, maxCells) : 1.0);
    };
    nx_ = along(w);
    ny_ = along(h);
    while (std::size_t{nx_} * ny_ > kMaxCells) {  // rounding up both sides can overshoot
        cell_ *= 1.01;
        invCell_ = 1.0 / cell_;
        nx_ = along(w);
        ny_ = along(h);
    }
    lastColumn_ = static_cast<double>(nx_ - 1);
    lastRow_ = static_cast<double>(ny_ - 1);

    // Each obstacle's cells: those of its widened bounding box that come within its radius plus
    // the pad of its core.
    auto forEachCell = [&](const Obstacle& o, auto&& f) {
        // One cell is the whole extent, which holds every obstacle (and where the extent is too
        // large for a double, the cell's corners could not be computed).
        if (nx_ == 1 && ny_ == 1) {
            f(0);
            return;
        }
        const double widen = o.radius + pad_;
        const std::uint32_t c0 = column(std::min(o.a.x(), o.b.x()) - widen);
        const std::uint32_t c1 = column(std::max(o.a.x(), o.b.x()) + widen);
        const std::uint32_t r0 = row(std::min(o.a.y(), o.b.y()) - widen);
        const std::uint32_t r1 = row(std::max(o.a.y(), o.b.y()) + widen);
        for (std::uint32_t cy = r0; cy <= r1; ++cy) {
            for (std::uint32_t cx = c0; cx <= c1; ++cx) {
                const double lx = x0_ + cx * cell_, ly = y0_ + cy * cell_;
                // A hair of slack so that rounding never drops a cell at the limit.
                if (coreToRectangle(o, lx, ly, lx + cell_, ly + cell_) <= widen * (1.0 + 1e-12)) {
                    f(cy * nx_ + cx);
                }
            }
        }
    };
    cellStart_.assign(std::size_t{nx_} * ny_ + 1, 0);
    for (const Obstacle& o : obstacles)
        forEachCell(o, [&](std::uint32_t c) { ++cellStart_[c + 1]; });
    for (std::size_t c = 1; c < cellStart_.size(); ++c)
        cellStart_[c] += cellStart_[c - 1];
    entries_.resize(cellStart_.back());
    occupied_.assign((cellStart_.size() - 1 + 63) / 64, 0);
    for (std::size_t c = 0; c + 1 < cellStart_.size(); ++c) {
        if (cellStart_[c + 1] > cellStart_[c]) occupied_[c >> 6] |= std::uint64_t{1} << (c & 63);
    }
    measureGaps();
    std::vector<std::uint32_t> fill(cellStart_.begin(), cellStart_.end() - 1);
    for (std::size_t k = 0; k < obstacles.size(); ++k) {
        forEachCell(obstacles[k],
                    [&](std::uint32_t c) { entries_[fill[c]++] = static_cast<std::uint32_t>(k); });
    }
}

void ObstacleGrid::query(double x0, double y0, double x1, double y1,
                         std::vector<std::uint32_t>& out) const {
    out.clear();
    // Written so that a NaN coordinate misses the grid.
    if (!(x1 >= x0_ && x0 <= x1_ && y1 >= y0_ && y0 <= y1_)) return;
    const std::uint32_t c0 = column(x0), c1 = column(x1), r0 = row(y0), r1 = row(y1);
    for (std::uint32_t cy = r0; cy <= r1; ++cy) {
        const std::uint32_t* start = cellStart_.data() + std::size_t{cy} * nx_;
        out.insert(out.end(), entries_.begin() + start[c0], entries_.begin() + start[c1 + 1]);
    }
    // One cell's list is already ascending and without repeats; several may share obstacles.
    if (c0 != c1 || r0 != r1) {
        std::sort(out.begin(), out.end());
        out.erase(std::unique(out.begin(), out.end()), out.end());
    }
}

void ObstacleGrid::measureGaps() {
    // The chessboard distance transform in two passes (Rosenfeld and Pfaltz): each pass carries
    // the distance from the neighbours it has already visited.
    const std::size_t nx = nx_, ny = ny_;
    std::vector<std::uint16_t> d(nx * ny);
    for (std::size_t c = 0; c < d.size(); ++c)
        d[c] = ((occupied_[c >> 6] >> (c & 63)) & 1u) ? 0 : UINT16_MAX;
    auto relax = [&](std::size_t c, std::size_t from) {
        d[c] = std::min<std::uint16_t>(d[c], d[from] == UINT16_MAX ? UINT16_MAX : d[from] + 1);
    };
    for (std::size_t y = 0; y < ny; ++y) {
        for (std::size_t x = 0; x < nx; ++x) {
            const std::size_t c = y * nx + x;
            if (x > 0) relax(c, c - 1);
            if (y > 0) {
                relax(c, c - nx);
                if (x > 0) relax(c, c - nx - 1);
                if (x + 1 < nx) relax(c, c - nx + 1);
            }
        }
    }
    for (std::size_t y = ny; y-- > 0;) {
        for (std::size_t x = nx; x-- > 0;) {
            const std::size_t c = y * nx + x;
            if (x + 1 < nx) relax(c, c + 1);
            if (y + 1 < ny) {
                relax(c, c + nx);
                if (x + 1 < nx) relax(c, c + nx + 1);
                if (x > 0) relax(c, c + nx - 1);
            }
        }
    }
    gap_.resize(d.size());
    for (std::size_t c = 0; c < d.size(); ++c)
        gap_[c] = static_cast<std::uint8_t>(std::min<std::uint16_t>(d[c], UINT8_MAX));
}

double ObstacleGrid::clearance(double x, double y) const {
    if (!std::isfinite(x) || !std::isfinite(y)) return 0.0;
    if (obstacles_.empty()) return INFINITY;
    // Every obstacle's surface lies at least the pad inside the grid's extent.
    if (!(x >= x0_ && x <= x1_ && y >= y0_ && y <= y1_))
        return pad_ + pointToRectangle(x, y, x0_, y0_, x1_, y1_);
    const std::int64_t cx = column(x), cy = row(y);
    const double lx = x0_ + static_cast<double>(cx) * cell_;
    const double ly = y0_ + static_cast<double>(cy) * cell_;
    const double edge = std::max(0.0, std::min({x - lx, lx + cell_ - x, y - ly, ly + cell_ - y}));
    double nearest = INFINITY;  // exact, over the obstacles listed in the rings seen so far
    auto visit = [&](std::int64_t col, std::int64_t rw) {
        if (col < 0 || rw < 0 || col >= nx_ || rw >= ny_) return;  // lists nothing
        const std::size_t c = static_cast<std::size_t>(rw) * nx_ + static_cast<std::size_t>(col);
        if (((occupied_[c >> 6] >> (c & 63)) & 1u) == 0) return;
        for (std::uint32_t k = cellStart_[c]; k < cellStart_[c + 1]; ++k) {
            const Obstacle& o = obstacles_[entries_[k]];
            double qx, qy;
            nearestCorePoint(o, x, y, qx, qy);
            nearest =
                std::min(nearest, std::sqrt((x - qx) * (x - qx) + (y - qy) * (y - qy)) - o.radius);
        }
    };
    // The cells within gap − 1 rings of this one list nothing (measureGaps).
    const std::int64_t gap =
        gap_[static_cast<std::size_t>(cy) * nx_ + static_cast<std::size_t>(cx)];
    if (gap > kClearanceRings) return pad_ + static_cast<double>(gap - 1) * cell_ + edge;
    for (std::int64_t ring = gap;; ++ring) {
        if (ring == 0) {
            visit(cx, cy);
        } else {
            for (std::int64_t col = cx - ring; col <= cx + ring; ++col) {
                visit(col, cy - ring);
                visit(col, cy + ring);
            }
            for (std::int64_t rw = cy - ring + 1; rw <= cy + ring - 1; ++rw) {
                visit(cx - ring, rw);
                visit(cx + ring, rw);
            }
        }
        // An obstacle listed in none of the cells within `ring` of the point's cell stays more
        // than the pad away from all of them, so beyond the block's edge.
        const double beyond = pad_ + static_cast<double>(ring) * cell_ + edge;
        if (nearest <= beyond || ring >= kClearanceRings) {
            return std::max(0.0, std::min(nearest, beyond));
        }
    }
}

std::size_t ObstacleGrid::memoryBytes() const {
    return sizeof(std::uint32_t) * (cellStart_.capacity() + entries_.capacity()) +
           sizeof(std::uint64_t) * occupied_.capacity() + gap_.capacity() +
           sizeof(Obstacle) * obstacles_.capacity();
}

}  // namespace psb
