#include "exact/obstacle_cells.hpp"

#include <algorithm>

#include "obstacles/obstacle_geometry.hpp"

namespace psb::exact {
namespace {

// Slack on every distance compared, relative to the cell, so that rounding never drops an
// obstacle at the limit (a longer list costs a few tests; a shorter one a missed impact).
constexpr double kSlack = 1e-6;

}  // namespace

void ObstacleCells::rectangle(const CellList& cells, std::int64_t kx, std::int64_t ky, double& x0,
                              double& y0, double& x1, double& y1) const {
    x0 = cells.faceX(kx) - skinX_;
    x1 = cells.faceX(kx + 1) + skinX_;
    y0 = cells.faceY(ky) - skinY_;
    y1 = cells.faceY(ky + 1) + skinY_;
}

void ObstacleCells::build(const Obstacles& obstacles, const CellList& cells, double skinX,
                          double skinY, double reach) {
    obstacles_ = obstacles;
    start_.clear();
    entries_.clear();
    scratch_.clear();
    if (obstacles.empty()) return;
    const double side = std::max(cells.faceX(1) - cells.faceX(0), cells.faceY(1) - cells.faceY(0));
    skinX_ = skinX;
    skinY_ = skinY;
    reach_ = reach + kSlack * side;
    perQuery_ = cells.wraps();
    if (perQuery_) {
        grid_.build(obstacles);
        return;
    }
    // Each obstacle's cells: those of its widened bounding box within its radius plus the reach
    // of its core.
    const auto forEachCell = [&](const Obstacle& o, auto&& f) {
        const double widen = o.radius + reach_;
        const std::int64_t c0 = cells.coordX(std::min(o.a.x(), o.b.x()) - widen - skinX_);
        const std::int64_t c1 = cells.coordX(std::max(o.a.x(), o.b.x()) + widen + skinX_);
        const std::int64_t r0 = cells.coordY(std::min(o.a.y(), o.b.y()) - widen - skinY_);
        const std::int64_t r1 = cells.coordY(std::max(o.a.y(), o.b.y()) + widen + skinY_);
        for (std::int64_t ky = r0; ky <= r1; ++ky) {
            for (std::int64_t kx = c0; kx <= c1; ++kx) {
                double x0, y0, x1, y1;
                rectangle(cells, kx, ky, x0, y0, x1, y1);
                if (coreToRectangle(o, x0, y0, x1, y1) <= widen) f(cells.cell(kx, ky));
            }
        }
    };
    start_.assign(static_cast<std::size_t>(cells.nx() * cells.ny()) + 1, 0);
    for (const Obstacle& o : obstacles)
        forEachCell(o, [&](std::uint32_t c) { ++start_[c + 1]; });
    for (std::size_t c = 1; c < start_.size(); ++c)
        start_[c] += start_[c - 1];
    entries_.resize(start_.back());
    std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
    for (std::size_t k = 0; k < obstacles.size(); ++k) {
        forEachCell(obstacles[k],
                    [&](std::uint32_t c) { entries_[fill[c]++] = static_cast<std::uint32_t>(k); });
    }
}

std::span<const std::uint32_t> ObstacleCells::near(const CellList& cells, std::int64_t kx,
                                                   std::int64_t ky) const {
    if (obstacles_.empty()) return {};
    if (!perQuery_) {
        const std::uint32_t c = cells.cell(kx, ky);
        return {entries_.data() + start_[c], entries_.data() + start_[c + 1]};
    }
    double x0, y0, x1, y1;
    rectangle(cells, kx, ky, x0, y0, x1, y1);
    const double widen = grid_.maxRadius() + reach_;
    grid_.query(x0 - widen, y0 - widen, x1 + widen, y1 + widen, scratch_);
    std::erase_if(scratch_, [&](std::uint32_t k) {
        const Obstacle& o = obstacles_[k];
        return coreToRectangle(o, x0, y0, x1, y1) > o.radius + reach_;
    });
    return scratch_;
}

std::size_t ObstacleCells::memoryBytes() const {
    return sizeof(Obstacle) * obstacles_.capacity() +
           sizeof(std::uint32_t) * (start_.capacity() + entries_.capacity() + scratch_.capacity()) +
           grid_.memoryBytes();
}

}  // namespace psb::exact
