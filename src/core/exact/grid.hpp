#pragma once
// The exact stepper's walks over its cells (the grid and its size levels are grid.cpp's): the
// cells of a level in a range of fine cells, and every particle near enough to touch one.
// Templates and small helpers, inline in every search that uses them.

#include <algorithm>
#include <cstdint>

#include "exact/stepper.hpp"

namespace psb::exact {

// Rounds towards minus infinity (cell coordinates may be negative when the grid wraps).
inline std::int64_t floorDiv(std::int64_t a, std::int64_t b) {
    const std::int64_t q = a / b;
    return (a % b != 0 && (a < 0) != (b < 0)) ? q - 1 : q;
}

inline std::uint32_t ExactStepper::memberCell(std::uint32_t i) const {
    const Cold& c = cold_[i];
    if (c.level == 0) return cells_.cell(c.kx, c.ky);
    const Level& l = upper_[c.level - 1];
    return l.cells.cell(floorDiv(c.kx, l.block), floorDiv(c.ky, l.block));
}

template <typename F>
inline void ExactStepper::forCells(std::uint8_t level, std::int64_t x0, std::int64_t x1,
                                   std::int64_t y0, std::int64_t y1, F&& f) const {
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
inline void ExactStepper::forEachAround(std::uint32_t i, F&& f) const {
    const Cold& c = cold_[i];
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
