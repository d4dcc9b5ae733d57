#pragma once
// The exact stepper's cells: the fine grid everyone's cell moves follow, the size levels above
// it, and the walks over them (the cells of a level in a range of fine cells, every particle
// near enough to touch one). Why cells have a skin and how the levels are cut: grid.cpp.
//
// The grid owns the cell lists and the levels' geometry; a particle's place in it (its fine
// cell kx, ky and its level) is kept in its Cold record, where its own events read it. The
// walks are templates and small helpers, inline in every search that uses them.

#include <algorithm>
#include <cstdint>
#include <vector>

#include <particle_sandbox/world_def.hpp>

#include "exact/body.hpp"
#include "exact/cell_list.hpp"

namespace psb::exact {

// Rounds towards minus infinity (cell coordinates may be negative when the grid wraps).
inline std::int64_t floorDiv(std::int64_t a, std::int64_t b) {
    const std::int64_t q = a / b;
    return (a % b != 0 && (a < 0) != (b < 0)) ? q - 1 : q;
}

class Grid {
  public:
    /// Sizes the fine cells and the size levels for `bodies` in the box of `def` (walls off:
    /// around the bulk of them) and writes each particle's level and fine cell into `cold`.
    /// Lists no one: insert() does.
    void setUp(const WorldDef& def, const std::vector<Body>& bodies, std::vector<Cold>& cold);
    /// Where each particle goes in cell order (fine cells in index order, particles of a cell
    /// in their current order): particle i becomes to[i].
    [[nodiscard]] std::vector<std::uint32_t> cellOrder(const std::vector<Cold>& cold) const;
    /// Empties every level's cells, keeping the geometry.
    void clearMembers();
    /// Lists particle i (its place in `c`) in its level's cell.
    void insert(std::uint32_t i, const Cold& c);
    /// A cell move: particle i crosses face `side` (-x, +x, -y, +y) of its fine cell into the
    /// next one; `c` and the lists follow. In a periodic box a move across an edge of the box
    /// takes the particle to the first cell on the other side; returns the whole boxes its
    /// centre must move by then along the axis crossed (-1, +1), else 0.
    int move(std::uint32_t i, Cold& c, std::int8_t side);
    /// Whether the cells tile a periodic box (WorldDef::periodic): fine cell coordinates stay in
    /// [0, nx) × [0, ny) and the faces of the box are crossed like any other, without a skin.
    [[nodiscard]] bool periodic() const { return periodic_; }

    /// Level 0's cells: the fine grid of every cell move.
    [[nodiscard]] const CellList& fine() const { return cells_; }
    /// How far (metres) a centre may stray out of its fine cell before it moves to the next.
    [[nodiscard]] double skinX() const { return skinX_; }
    [[nodiscard]] double skinY() const { return skinY_; }
    [[nodiscard]] double largestRadius() const {
        return *std::max_element(levelRadius_.begin(), levelRadius_.end());
    }
    [[nodiscard]] std::uint8_t levelCount() const { return levelCount_; }
    /// How many fine cells apart (per axis) a particle of level a and one of level b may be and
    /// still touch; 1 for two of level 0.
    [[nodiscard]] std::int64_t reach(std::uint8_t a, std::uint8_t b) const {
        return reach_[a * levelCount_ + b];
    }
    [[nodiscard]] const CellList& listOf(std::uint8_t level) const {
        return level == 0 ? cells_ : upper_[level - 1].cells;
    }
    /// The cell of its level's list that a particle at `c` is listed in.
    [[nodiscard]] std::uint32_t memberCell(const Cold& c) const;
    /// Calls f(cell) for every cell of `level`'s list that covers fine cells x0..x1, y0..y1.
    template <typename F>
    void forCells(std::uint8_t level, std::int64_t x0, std::int64_t x1, std::int64_t y0,
                  std::int64_t y1, F&& f) const;
    /// Calls f(q) for every particle q near enough to touch the particle at `c` (itself
    /// included): the cells of every level within its reach of its level.
    template <typename F>
    void forEachAround(const Cold& c, F&& f) const;

    /// Bytes held by every level's cells.
    [[nodiscard]] std::size_t memoryBytes() const;

  private:
    // A size class above level 0: its members are listed in cells of block × block fine cells
    // (cells_ is level 0's list and the fine grid everyone's cell moves follow).
    struct Level {
        CellList cells;
        std::int64_t block = 1;
    };

    void assignLevels(const std::vector<Body>& bodies, std::vector<Cold>& cold, double spacing,
                      double& fineDiameter);
    void setUpLevels(std::uint32_t n);
    [[nodiscard]] bool populous(std::uint8_t level) const;
    [[nodiscard]] bool populousUpperLevel() const;

    CellList cells_;                    // level 0's members; the fine grid of every cell move
    bool periodic_ = false;             // the cells tile a periodic box
    double skinX_ = 0.0, skinY_ = 0.0;  // how far a centre may stray out of its cell
    std::vector<Level> upper_;          // levels 1, 2, ...
    std::uint8_t levelCount_ = 1;
    // reach_[a · levelCount_ + b]: see reach().
    std::vector<std::int64_t> reach_;
    std::vector<double> levelRadius_;          // largest radius of each level
    std::vector<std::uint32_t> levelMembers_;  // particles of each level
};

inline std::uint32_t Grid::memberCell(const Cold& c) const {
    if (c.level == 0) return cells_.cell(c.kx, c.ky);
    const Level& l = upper_[c.level - 1];
    return l.cells.cell(floorDiv(c.kx, l.block), floorDiv(c.ky, l.block));
}

inline int Grid::move(std::uint32_t i, Cold& c, std::int8_t side) {
    const std::uint32_t oldCell = memberCell(c);
    switch (side) {
        case 0:
            --c.kx;
            break;
        case 1:
            ++c.kx;
            break;
        case 2:
            --c.ky;
            break;
        default:
            ++c.ky;
            break;
    }
    int boxes = 0;
    if (periodic_) {
        std::int64_t& k = side < 2 ? c.kx : c.ky;
        const std::int64_t n = side < 2 ? cells_.nx() : cells_.ny();
        if (k < 0) {
            k += n;
            boxes = 1;
        } else if (k >= n) {
            k -= n;
            boxes = -1;
        }
    }
    if (c.level == 0) {
        cells_.erase(i);
        cells_.insert(i, cells_.cell(c.kx, c.ky));
    } else if (const std::uint32_t cell = memberCell(c); cell != oldCell) {
        CellList& list = upper_[c.level - 1].cells;
        list.erase(i);
        list.insert(i, cell);
    }
    return boxes;
}

template <typename F>
inline void Grid::forCells(std::uint8_t level, std::int64_t x0, std::int64_t x1, std::int64_t y0,
                           std::int64_t y1, F&& f) const {
    const CellList& list = listOf(level);
    if (level > 0) {
        const std::int64_t b = upper_[level - 1].block;
        x0 = floorDiv(x0, b);
        x1 = floorDiv(x1, b);
        y0 = floorDiv(y0, b);
        y1 = floorDiv(y1, b);
    }
    if (list.wraps()) {
        // A range wider than the grid would visit cells twice.
        x1 = std::min(x1, x0 + list.nx() - 1);
        y1 = std::min(y1, y0 + list.ny() - 1);
    } else {
        x0 = std::max<std::int64_t>(x0, 0);
        y0 = std::max<std::int64_t>(y0, 0);
        x1 = std::min(x1, list.nx() - 1);
        y1 = std::min(y1, list.ny() - 1);
    }
    for (std::int64_t ky = y0; ky <= y1; ++ky) {
        for (std::int64_t kx = x0; kx <= x1; ++kx) {
            const std::uint32_t c = list.cell(kx, ky);
            if (c != CellList::kNone) f(c);
        }
    }
}

template <typename F>
inline void Grid::forEachAround(const Cold& c, F&& f) const {
    for (std::uint8_t l = 0; l < levelCount_; ++l) {
        const CellList& list = listOf(l);
        const std::int64_t k = reach(c.level, l);
        forCells(l, c.kx - k, c.kx + k, c.ky - k, c.ky + k, [&](std::uint32_t cell) {
            for (std::uint32_t q = list.head(cell); q != CellList::kNone; q = list.next(q))
                f(q);
        });
    }
}

}  // namespace psb::exact
