#pragma once
// The one overlap test every broadphase uses, so that they agree to the last bit.

#include <cstdint>

#include "support/periodic_box.hpp"

namespace psb {

/// Whether discs i and j overlap (centre distance < r_i + r_j; touching is not a contact).
/// Callers pass i < j: the subtraction is always x[j] - x[i], so the rounding, and therefore
/// the answer for a pair at the limit, is the same whichever broadphase asks.
[[nodiscard]] inline bool discsOverlap(const double* x, const double* y, const double* r,
                                       std::uint32_t i, std::uint32_t j) {
    const double dx = x[j] - x[i];
    const double dy = y[j] - y[i];
    const double rs = r[i] + r[j];
    return dx * dx + dy * dy < rs * rs;
}

/// discsOverlap in a periodic box: the nearest image of j (support/periodic_box.hpp). The same
/// arithmetic once the separation is brought to its image.
[[nodiscard]] inline bool discsOverlapPeriodic(const double* x, const double* y, const double* r,
                                               std::uint32_t i, std::uint32_t j,
                                               const periodic::Box& box) {
    const double dx = box.imageX(x[j] - x[i]);
    const double dy = box.imageY(y[j] - y[i]);
    const double rs = r[i] + r[j];
    return dx * dx + dy * dy < rs * rs;
}

}  // namespace psb
