#pragma once
// The arithmetic of a periodic box (WorldDef::periodic): a coordinate wrapped back into
// [0, extent), what the wrap took off it kept for the unwrapped position, and the minimum image
// of a separation. Shared by every step mode, so that they wrap and measure alike.
//
// Why the minimum image is enough. World keeps every particle's diameter at most half of each
// side (world/periodic_fit.hpp), so two touching discs are at most half a side apart along each
// axis: of all the images of a partner, only the nearest can touch.

#include <cmath>

namespace psb::periodic {

/// Brings `v` into [0, extent) by whole extents, adding to `unwrap` what it took off (so that
/// v + unwrap does not change but for rounding). Leaves a non-finite v alone.
inline void wrapInto(double& v, double& unwrap, double extent) {
    if (v >= 0.0 && v < extent) return;
    if (!std::isfinite(v)) return;
    const double images = std::floor(v / extent);
    const double shift = images * extent;
    v -= shift;
    unwrap += shift;
    // Rounding: a tiny negative v plus the extent can round to the extent itself.
    if (v >= extent) {
        v -= extent;
        unwrap += extent;
    }
    if (v < 0.0) v = 0.0;
}

/// The separation d (of two coordinates along an axis of the given extent) brought to its
/// nearest image, in [-extent/2, extent/2]. A separation already within half the extent is
/// returned bit for bit.
[[nodiscard]] inline double minimumImage(double d, double extent) {
    return std::abs(d) <= 0.5 * extent ? d : d - extent * std::nearbyint(d / extent);
}

/// The extents of a periodic box, metres: what a broadphase needs to measure across its edges.
struct Box {
    double width = 0.0, height = 0.0;

    [[nodiscard]] double imageX(double dx) const { return minimumImage(dx, width); }
    [[nodiscard]] double imageY(double dy) const { return minimumImage(dy, height); }
};

}  // namespace psb::periodic
