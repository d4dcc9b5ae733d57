#include "exact/cell_list.hpp"

#include <algorithm>
#include <cmath>

namespace psb::exact {

void CellList::reset(double ox, double oy, double sx, double sy, std::int64_t nx, std::int64_t ny,
                     bool wrap, std::uint32_t n) {
    ox_ = ox;
    oy_ = oy;
    sx_ = sx;
    sy_ = sy;
    nx_ = nx;
    ny_ = ny;
    wrap_ = wrap;
    head_.assign(static_cast<std::size_t>(nx * ny), kNone);
    link_.assign(n, Link{kNone, kNone, kNone});
}

std::int64_t CellList::coord(double v, double o, double s, std::int64_t n) const {
    const double k = std::floor((v - o) / s);
    if (!wrap_) {
        if (!(k > 0.0)) return 0;  // also catches NaN
        return k >= static_cast<double>(n - 1) ? n - 1 : static_cast<std::int64_t>(k);
    }
    // Keep far-flung coordinates representable; past 2^62 cells the fold is still correct.
    constexpr double kLimit = 4.0e18;
    if (!(k > -kLimit)) return static_cast<std::int64_t>(-kLimit);
    if (k > kLimit) return static_cast<std::int64_t>(kLimit);
    return static_cast<std::int64_t>(k);
}

void CellList::clearMembers() {
    std::fill(head_.begin(), head_.end(), kNone);
    std::fill(link_.begin(), link_.end(), Link{kNone, kNone, kNone});
}

void CellList::insert(std::uint32_t i, std::uint32_t c) {
    const std::uint32_t h = head_[c];
    link_[i] = {h, kNone, c};
    if (h != kNone) link_[h].prev = i;
    head_[c] = i;
}

void CellList::erase(std::uint32_t i) {
    const Link l = link_[i];
    if (l.prev != kNone) {
        link_[l.prev].next = l.next;
    } else {
        head_[l.cell] = l.next;
    }
    if (l.next != kNone) link_[l.next].prev = l.prev;
    link_[i].cell = kNone;
}

}  // namespace psb::exact
