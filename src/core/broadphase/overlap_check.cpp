#include "broadphase/overlap_check.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "obstacles/obstacle_geometry.hpp"
#include "obstacles/obstacle_grid.hpp"
#include "support/periodic_box.hpp"

namespace psb::detail {
namespace {

struct Entry {
    std::uint64_t cell;
    std::size_t index;
    friend bool operator<(const Entry& a, const Entry& b) {
        return a.cell != b.cell ? a.cell < b.cell : a.index < b.index;
    }
};

// 2^26 cells per axis keeps a cell key (x · 2^26 + y) inside 64 bits with room to spare.
constexpr double kMaxCellsPerAxis = 67108864.0;

}  // namespace

std::optional<std::pair<std::size_t, std::size_t>> findOverlap(const std::vector<ParticleDef>& p) {
    const std::size_t n = p.size();
    if (n < 2) return std::nullopt;
    double minX = p[0].position.x(), minY = p[0].position.y(), maxX = minX, maxY = minY;
    double maxR = 0.0;
    for (const ParticleDef& d : p) {
        minX = std::min(minX, d.position.x());
        maxX = std::max(maxX, d.position.x());
        minY = std::min(minY, d.position.y());
        maxY = std::max(maxY, d.position.y());
        maxR = std::max(maxR, d.radius);
    }
    // Two overlapping discs have centres closer than 2 maxR, so they sit in the same or
    // neighbouring cells. Cells may be made larger (never smaller) to bound the key range.
    const double extent = std::max(maxX - minX, maxY - minY);
    const double cell = std::max({2.0 * maxR, extent / (kMaxCellsPerAxis - 2.0), 1e-300});
    auto cellOf = [&](double v, double lo) {
        return static_cast<std::uint64_t>(
            std::min(std::floor((v - lo) / cell), kMaxCellsPerAxis - 1.0));
    };
    auto key = [](std::uint64_t cx, std::uint64_t cy) { return (cx << 26) | cy; };

    std::vector<Entry> entries(n);
    std::vector<std::uint64_t> cx(n), cy(n);
    for (std::size_t i = 0; i < n; ++i) {
        cx[i] = cellOf(p[i].position.x(), minX);
        cy[i] = cellOf(p[i].position.y(), minY);
        entries[i] = {key(cx[i], cy[i]), i};
    }
    std::sort(entries.begin(), entries.end());

    auto overlaps = [&](std::size_t i, std::size_t j) {
        const double dx = p[j].position.x() - p[i].position.x();
        const double dy = p[j].position.y() - p[i].position.y();
        const double reach = p[i].radius + p[j].radius;
        return dx * dx + dy * dy < reach * reach;
    };

    for (std::size_t i = 0; i < n; ++i) {
        std::size_t best = SIZE_MAX;
        for (int ox = -1; ox <= 1; ++ox) {
            for (int oy = -1; oy <= 1; ++oy) {
                if ((ox < 0 && cx[i] == 0) || (oy < 0 && cy[i] == 0)) continue;
                const std::uint64_t k = key(cx[i] + ox, cy[i] + oy);
                // Entries of one cell are sorted by index: start just after i.
                auto it = std::lower_bound(entries.begin(), entries.end(), Entry{k, i + 1});
                for (; it != entries.end() && it->cell == k && it->index < best; ++it) {
                    if (overlaps(i, it->index)) best = it->index;
                }
            }
        }
        if (best != SIZE_MAX) return std::pair{i, best};
    }
    return std::nullopt;
}

std::optional<std::pair<std::size_t, std::size_t>> findOverlapPeriodic(
    const std::vector<ParticleDef>& p, double width, double height) {
    const std::size_t n = p.size();
    if (n < 2) return std::nullopt;
    double maxR = 0.0;
    std::vector<double> x(n), y(n);
    for (std::size_t i = 0; i < n; ++i) {
        double unwrap = 0.0;
        x[i] = p[i].position.x();
        y[i] = p[i].position.y();
        periodic::wrapInto(x[i], unwrap, width);
        periodic::wrapInto(y[i], unwrap, height);
        maxR = std::max(maxR, p[i].radius);
    }
    const periodic::Box box{width, height};
    auto overlaps = [&](std::size_t i, std::size_t j) {
        const double dx = box.imageX(x[j] - x[i]);
        const double dy = box.imageY(y[j] - y[i]);
        const double reach = p[i].radius + p[j].radius;
        return dx * dx + dy * dy < reach * reach;
    };
    // Cells that tile the box, at least 2 maxR across, wrapping at the edges; a box fewer than
    // three cells across each way (a few discs) is searched pair by pair.
    const auto across = [&](double extent) {
        const double k = std::floor(extent / std::max(2.0 * maxR, 1e-300));
        return static_cast<std::uint64_t>(std::clamp(k, 1.0, kMaxCellsPerAxis));
    };
    const std::uint64_t nx = across(width), ny = across(height);
    if (nx < 3 || ny < 3) {
        for (std::size_t i = 0; i < n; ++i) {
            for (std::size_t j = i + 1; j < n; ++j) {
                if (overlaps(i, j)) return std::pair{i, j};
            }
        }
        return std::nullopt;
    }
    auto cellOf = [](double v, double extent, std::uint64_t count) {
        const double c = std::floor(v / extent * static_cast<double>(count));
        return static_cast<std::uint64_t>(std::clamp(c, 0.0, static_cast<double>(count - 1)));
    };
    auto key = [](std::uint64_t cx, std::uint64_t cy) { return (cx << 26) | cy; };
    std::vector<Entry> entries(n);
    std::vector<std::uint64_t> cx(n), cy(n);
    for (std::size_t i = 0; i < n; ++i) {
        cx[i] = cellOf(x[i], width, nx);
        cy[i] = cellOf(y[i], height, ny);
        entries[i] = {key(cx[i], cy[i]), i};
    }
    std::sort(entries.begin(), entries.end());
    for (std::size_t i = 0; i < n; ++i) {
        std::size_t best = SIZE_MAX;
        for (std::uint64_t ox = 0; ox < 3; ++ox) {
            for (std::uint64_t oy = 0; oy < 3; ++oy) {
                const std::uint64_t k = key((cx[i] + nx + ox - 1) % nx, (cy[i] + ny + oy - 1) % ny);
                auto it = std::lower_bound(entries.begin(), entries.end(), Entry{k, i + 1});
                for (; it != entries.end() && it->cell == k && it->index < best; ++it) {
                    if (overlaps(i, it->index)) best = it->index;
                }
            }
        }
        if (best != SIZE_MAX) return std::pair{i, best};
    }
    return std::nullopt;
}

std::optional<ObstacleOverlap> findObstacleOverlap(const std::vector<ParticleDef>& particles,
                                                   const Obstacles& obstacles) {
    if (obstacles.empty()) return std::nullopt;
    ObstacleGrid grid;
    grid.build(obstacles);
    std::vector<std::uint32_t> near;
    for (std::size_t i = 0; i < particles.size(); ++i) {
        const ParticleDef& d = particles[i];
        const double x = d.position.x(), y = d.position.y(), rad = d.radius;
        grid.query(x - rad, y - rad, x + rad, y + rad, near);
        for (const std::uint32_t k : near) {
            const Obstacle& o = obstacles[k];
            double qx, qy;
            nearestCorePoint(o, x, y, qx, qy);
            const double distance = std::hypot(x - qx, y - qy);
            if (distance < rad + o.radius) return ObstacleOverlap{i, k, distance};
        }
    }
    return std::nullopt;
}

}  // namespace psb::detail
