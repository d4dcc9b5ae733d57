#include "cell_list.hpp"

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
    next_.assign(n, kNone);
    prev_.assign(n, kNone);
    cellOf_.assign(n, kNone);
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

std::uint32_t CellList::cell(std::int64_t kx, std::int64_t ky) const {
    if (wrap_) {
        kx %= nx_;
        if (kx < 0) kx += nx_;
        ky %= ny_;
        if (ky < 0) ky += ny_;
    } else if (kx < 0 || kx >= nx_ || ky < 0 || ky >= ny_) {
        return kNone;
    }
    return static_cast<std::uint32_t>(ky * nx_ + kx);
}

void CellList::clearMembers() {
    std::fill(head_.begin(), head_.end(), kNone);
    std::fill(next_.begin(), next_.end(), kNone);
    std::fill(prev_.begin(), prev_.end(), kNone);
    std::fill(cellOf_.begin(), cellOf_.end(), kNone);
}

void CellList::insert(std::uint32_t i, std::uint32_t c) {
    const std::uint32_t h = head_[c];
    next_[i] = h;
    prev_[i] = kNone;
    if (h != kNone) prev_[h] = i;
    head_[c] = i;
    cellOf_[i] = c;
}

void CellList::erase(std::uint32_t i) {
    const std::uint32_t c = cellOf_[i];
    const std::uint32_t a = prev_[i], b = next_[i];
    if (a != kNone) {
        next_[a] = b;
    } else {
        head_[c] = b;
    }
    if (b != kNone) prev_[b] = a;
    cellOf_[i] = kNone;
}

}  // namespace psb::exact
