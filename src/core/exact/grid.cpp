// The exact stepper's cells: the fine cells everyone's cell moves follow, the size levels above
// them, and the order that sorts the particles into cell order. The walks are grid.hpp's.
//
// Cells with a skin. Cells are at least one largest diameter (of level 0, below) plus twice a
// skin wide, and a particle moves to the next cell only once its centre is a skin's width past
// the face (not at the face). Two touching discs of level 0 are then still in neighbouring
// cells, and a particle that just moved is a skin inside its new cell, so it does not flicker
// across a face: about half as many cell moves as with plain cells at the same search cost.
//
// Size levels. Cells sized by the largest disc would make a gas with one big disc search
// cells hundreds of small discs wide. Instead radii fall into levels: level 0 holds every disc
// up to 1.25 mean spacings across (the cells are about a spacing wide anyway) or twice the
// smallest radius, whichever is larger, and levels above it double (empty ones dropped). The fine
// grid is sized by level 0 alone, and every particle, whatever its level, has a fine cell and
// makes fine cell moves. Particles of levels a and b are neighbours when their fine cells are
// at most reach(a, b) apart along each axis, the distance at which two such discs can still
// touch (1 for two of level 0: the 3 × 3 search). The relation is symmetric and changes only
// at a cell move of one of the two, which searches the strip of cells that just came within
// reach, at every level: that is all the argument of stepper_prediction.cpp ("Two scheduled
// events") needs. Level 0 is listed in the fine cells; level l > 0 in cells of block × block fine
// cells (block = 2 reach(0, l) + 1), so that a small disc looks at a few cells of each upper level,
// and a big disc's search is the (2 reach + 1)² fine cells around it, mostly inside the disc
// itself and so empty. A scene of one size has one level and runs the code it ran before levels
// existed, bit for bit.

#include <algorithm>
#include <cmath>
#include <type_traits>

#include "exact/grid.hpp"
#include "exact/time_of_impact.hpp"

namespace psb::exact {

namespace {

// Cells a little wider than the largest diameter, so that a centre a few ulps outside the cell
// its events say it is in is still found by its neighbours' 3 × 3 searches.
constexpr double kCellSlack = 1.0 + 1e-9;
// Target cell side, in mean particle spacings sqrt(area / N). Larger cells mean fewer
// cell-face events but more pair tests per prediction; measured on the dilute-gas benchmark.
constexpr double kCellSpacings = 1.0;
// Discs up to this many mean spacings across stay in level 0 (one level as before levels
// existed): cells sized by them cost little more than cells a spacing wide. Measured on the
// 1:10 mix of exact_gas_bench (radii 1-10 m, packing 0.2, spacing 18 m): one level was faster
// than levels split at twice the smallest radius.
constexpr double kLevelZeroSpacings = 1.25;
// A level above 0 with fewer than one particle per kSparseCells fine cells is sparse (a few big
// discs); a populous one gets cells of its own size and a thinner skin (setUpLevels).
constexpr double kSparseCells = 32.0;
// The skin, as a fraction of the cell, when a populous level lies above level 0 (0.1 and 0.05
// measured on the 1:10 mix of exact_gas_bench; 0.05 was ~7 % faster).
constexpr double kCrowdedSkin = 0.05;

}  // namespace

void Grid::setUp(const WorldDef& def, const std::vector<Body>& bodies, std::vector<Cold>& cold) {
    const auto n = static_cast<std::uint32_t>(bodies.size());
    // Unbounded, so the grid folds onto itself (cell_list.hpp) and need not cover every
    // particle: it is sized for the bulk of them (the middle 90 % along each axis), so
    // that one particle flung far away does not make every cell huge.
    const auto spread = [&](auto coord) {
        if (n < 2) return 0.0;
        std::vector<double> v(n);
        for (std::uint32_t i = 0; i < n; ++i)
            v[i] = coord(bodies[i]);
        const auto lo = v.begin() + n / 20, hi = v.begin() + (n - 1 - n / 20);
        std::nth_element(v.begin(), lo, v.end());
        const double a = *lo;
        std::nth_element(v.begin(), hi, v.end());
        return *hi - a;
    };
    double bulkW = def.width, bulkH = def.height;
    periodic_ = def.periodic;
    // A periodic box is tiled like a walled one; its cells wrap (its edges are faces).
    const bool tiled = def.walls || def.periodic;
    if (!tiled) {
        bulkW = spread([](const Body& b) { return b.x; });
        bulkH = spread([](const Body& b) { return b.y; });
    }
    double dmax = 0.0;
    assignLevels(bodies, cold, std::sqrt(bulkW * bulkH / std::max(n, 1u)), dmax);
    const double minSide = std::max(dmax * kCellSlack, 1e-300);
    // At most a few cells per particle: enough for the 3 × 3 searches to see ~1 particle each,
    // and memory stays O(N) however large the box.
    const double maxCells = 4.0 * n + 64.0;
    if (tiled) {
        const double area = def.width * def.height;
        double side = std::max(minSide, kCellSpacings * std::sqrt(area / std::max(n, 1u)));
        side = std::max(side, std::sqrt(area / maxCells));
        const auto count = [&](double extent) {
            // Three cells or fewer: the 3 × 3 search of the middle one already sees the whole
            // width, so one cell sees as much from everywhere and has no faces to cross (in a
            // nearly empty box, cell moves would otherwise outnumber collisions two to one).
            // Never more than maxCells along one side: a box 10^-300 m high makes the side tiny
            // and the count of the other axis beyond any integer.
            const double k = std::min(extent / side, maxCells);
            return k < 4.0 ? std::int64_t{1} : static_cast<std::int64_t>(k);
        };
        const std::int64_t nx = count(def.width), ny = count(def.height);
        cells_.reset(0.0, 0.0, def.width / static_cast<double>(nx),
                     def.height / static_cast<double>(ny), nx, ny, def.periodic, n);
    } else {
        const double w = bulkW + 2.0 * minSide;
        const double h = bulkH + 2.0 * minSide;
        double side = std::max(minSide, kCellSpacings * std::sqrt(w * h / std::max(n, 1u)));
        side = std::max(side, std::sqrt(w * h / maxCells));
        const auto count = [&](double extent) {
            // At least 3, at most maxCells (a thin spread of particles along one axis), and 3
            // where the spread is too wide for a double (the count is then not a number).
            const double k = std::ceil(extent / side);
            return k > 3.0 ? static_cast<std::int64_t>(std::min(k, maxCells)) : std::int64_t{3};
        };
        cells_.reset(0.0, 0.0, side, side, count(w), count(h), true, n);
    }
    // A particle may stray a skin's width out of its cell before it is moved to the next one:
    // two touching discs are then still at most one cell apart (side >= dmax + 2 skin), and a
    // particle that has just moved is a skin's width inside its new cell, so it does not
    // flicker back and forth across a face.
    const double sx = cells_.faceX(1) - cells_.faceX(0), sy = cells_.faceY(1) - cells_.faceY(0);
    skinX_ = std::max(0.0, 0.5 * (sx - minSide));
    skinY_ = std::max(0.0, 0.5 * (sy - minSide));
    if (populousUpperLevel()) {
        // Every reach across levels grows by twice the skin: with many particles above level
        // 0 (cells sized by their spacing, not by level 0's discs), a skin of a tenth of the
        // cell keeps most reaches at one cell (the 3 × 3 search) for a few more cell moves.
        skinX_ = std::min(skinX_, kCrowdedSkin * sx);
        skinY_ = std::min(skinY_, kCrowdedSkin * sy);
    }
    for (std::uint32_t i = 0; i < n; ++i) {
        cold[i].kx = cells_.coordX(bodies[i].x);
        cold[i].ky = cells_.coordY(bodies[i].y);
        if (periodic_) {
            // Centres are wrapped into the box (rebuild); rounding at its far edge can still
            // give the count itself.
            cold[i].kx = std::clamp<std::int64_t>(cold[i].kx, 0, cells_.nx() - 1);
            cold[i].ky = std::clamp<std::int64_t>(cold[i].ky, 0, cells_.ny() - 1);
        }
    }
    setUpLevels(n);
}

void Grid::assignLevels(const std::vector<Body>& bodies, std::vector<Cold>& cold, double spacing,
                        double& fineDiameter) {
    const auto n = static_cast<std::uint32_t>(bodies.size());
    double rmin = kNever;
    for (const Body& b : bodies)
        rmin = std::min(rmin, b.r);
    // Level 0 holds every disc the cells would be wide enough for anyway (cells are about a
    // mean spacing wide): up to kLevelZeroSpacings spacings across, and at least twice the
    // smallest radius. Above it, levels by factors of two; empty levels are dropped.
    const double level0 = std::max(2.0 * rmin, 0.5 * kLevelZeroSpacings * spacing);
    constexpr int kMaxRaw = 64;
    std::uint8_t raw[kMaxRaw + 1] = {};
    const auto rawLevel = [&](double r) {
        int l = 0;
        for (double limit = level0; r > limit && l < kMaxRaw; limit *= 2.0)
            ++l;
        return l;
    };
    for (const Body& b : bodies)
        raw[rawLevel(b.r)] = 1;
    std::uint8_t compact[kMaxRaw + 1];
    std::uint8_t count = 0;
    for (int l = 0; l <= kMaxRaw; ++l) {
        compact[l] = count;
        if (raw[l]) ++count;
    }
    levelCount_ = std::max<std::uint8_t>(count, 1);
    levelRadius_.assign(levelCount_, 0.0);
    levelMembers_.assign(levelCount_, 0);
    for (std::uint32_t i = 0; i < n; ++i) {
        const std::uint8_t l = compact[rawLevel(bodies[i].r)];
        cold[i].level = l;
        levelRadius_[l] = std::max(levelRadius_[l], bodies[i].r);
        ++levelMembers_[l];
    }
    fineDiameter = 2.0 * levelRadius_[0];
}

void Grid::setUpLevels(std::uint32_t n) {
    const double sx = cells_.faceX(1) - cells_.faceX(0), sy = cells_.faceY(1) - cells_.faceY(0);
    reach_.assign(std::size_t{levelCount_} * levelCount_, 1);
    for (std::uint8_t a = 0; a < levelCount_; ++a) {
        for (std::uint8_t b = 0; b < levelCount_; ++b) {
            if (a == 0 && b == 0) continue;  // the cells are sized for it: the 3 × 3 search
            // Centres in cells k apart along x are at least (k − 1)·sx − 2·skin apart: they can
            // touch only if that is at most the sum of the radii.
            const double sigma = (levelRadius_[a] + levelRadius_[b]) * kCellSlack;
            const double kx = 1.0 + std::floor((sigma + 2.0 * skinX_) / sx);
            const double ky = 1.0 + std::floor((sigma + 2.0 * skinY_) / sy);
            // Capped far beyond any grid (a range wider than the grid is clipped to it), so that
            // a disc of any size gives a representable reach.
            reach_[a * levelCount_ + b] =
                static_cast<std::int64_t>(std::min(std::max(kx, ky), 1e15));
        }
    }
    upper_.resize(levelCount_ - 1u);
    for (std::uint8_t l = 1; l < levelCount_; ++l) {
        Level& level = upper_[l - 1];
        // A sparse level (a few big discs) is listed in blocks as wide as a small disc's reach
        // to it, so that a small disc reads a few empty lists, not (2 reach + 1)²; a populous
        // one in the fine cells themselves, so that no one tests more candidates than its
        // reach holds (a head read costs far less than a candidate's test).
        level.block = populous(l) ? 1 : 2 * reach(0, l) + 1;
        const auto blocks = [&](std::int64_t cells) {
            return std::max<std::int64_t>(1, (cells + level.block - 1) / level.block);
        };
        const auto b = static_cast<double>(level.block);
        level.cells.reset(0.0, 0.0, sx * b, sy * b, blocks(cells_.nx()), blocks(cells_.ny()),
                          cells_.wraps(), n);
    }
}

bool Grid::populous(std::uint8_t level) const {
    // More than one particle in kSparseCells fine cells.
    return static_cast<double>(levelMembers_[level]) * kSparseCells >=
           static_cast<double>(cells_.nx() * cells_.ny());
}

bool Grid::populousUpperLevel() const {
    for (std::uint8_t l = 1; l < levelCount_; ++l) {
        if (populous(l)) return true;
    }
    return false;
}

void Grid::insert(std::uint32_t i, const Cold& c) {
    CellList& list = c.level == 0 ? cells_ : upper_[c.level - 1].cells;
    list.insert(i, memberCell(c));
}

void Grid::clearMembers() {
    cells_.clearMembers();
    for (Level& l : upper_)
        l.cells.clearMembers();
}

std::vector<std::uint32_t> Grid::cellOrder(const std::vector<Cold>& cold) const {
    const auto n = static_cast<std::uint32_t>(cold.size());
    const auto cellCount = static_cast<std::size_t>(cells_.nx() * cells_.ny());
    std::vector<std::uint32_t> start(cellCount + 1, 0), cellOf(n), to(n);
    for (std::uint32_t i = 0; i < n; ++i) {
        cellOf[i] = cells_.cell(cold[i].kx, cold[i].ky);
        ++start[cellOf[i] + 1];
    }
    for (std::size_t c = 0; c < cellCount; ++c)
        start[c + 1] += start[c];
    for (std::uint32_t i = 0; i < n; ++i)
        to[i] = start[cellOf[i]]++;
    return to;
}

std::size_t Grid::memoryBytes() const {
    std::size_t bytes = cells_.memoryBytes();
    for (const Level& level : upper_)
        bytes += level.cells.memoryBytes();
    return bytes;
}

}  // namespace psb::exact
