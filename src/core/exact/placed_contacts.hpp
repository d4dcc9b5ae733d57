#pragma once
// Pairs of the exact stepper placed overlapping from outside (spawned, dragged, clamped into a
// box too small for its lattice): rounding alone leaves overlaps of a few ulps only. Each such
// pair keeps the distance it was placed at as its contact distance until a prediction finds it
// apart; from then on it is an ordinary pair. Colliding it at whatever distance it happens to
// have instead would be a ratchet: every time it drifts apart the gain is kept, so in a box too
// full for its discs the overlaps are squeezed out into the gaps of everyone else until the
// pile jams and the collision rate diverges.
//
// Pairs are keyed by storage indices (the world's, stable while the stepper re-sorts its
// own); both particles of a pair carry kPlacedOverlapping, so that an ordinary pair's test
// never looks the table up.

#include <cstdint>
#include <unordered_map>
#include <vector>

#include "exact/body.hpp"
#include "exact/grid.hpp"
#include "support/periodic_box.hpp"

namespace psb::exact {

class PlacedContacts {
  public:
    /// Forgets every pair, then records those of `bodies` that overlap now (held pairs pass
    /// through each other and are left out) and flags both of each kPlacedOverlapping.
    /// `order` maps the stepper's indices to storage indices; `grid` lists the particles. In a
    /// periodic box (grid.periodic()) pairs are measured between nearest images in `box`.
    void record(std::vector<Body>& bodies, const std::vector<Cold>& cold,
                const std::vector<std::uint32_t>& order, const Grid& grid,
                const periodic::Box& box = {});

    /// The contact distance of the pair of storage indices a and b, whose centres are (rx, ry)
    /// apart, given `sigma` (the sum of their radii): the distance it was placed at while it is
    /// inside sigma; sigma for a pair not recorded, or found apart at last (then forgotten).
    [[nodiscard]] double contactDistance(std::uint32_t a, std::uint32_t b, double rx, double ry,
                                         double sigma) {
        const auto it = contacts_.find(pairKey(a, b));
        if (it == contacts_.end()) return sigma;
        // Apart at last: from now on the pair is an ordinary one.
        if (rx * rx + ry * ry >= sigma * sigma) {
            contacts_.erase(it);
            return sigma;
        }
        return it->second.distance;
    }

    /// The deepest overlap (metres) of the pairs still kept at their placed distance.
    [[nodiscard]] double deepest() const;

    /// Bytes held by the table.
    [[nodiscard]] std::size_t memoryBytes() const;

  private:
    [[nodiscard]] static std::uint64_t pairKey(std::uint32_t a, std::uint32_t b) {
        return a < b ? (std::uint64_t{a} << 32) | b : (std::uint64_t{b} << 32) | a;
    }

    // The contact distance a pair keeps, and how deep that is inside contact (r₁ + r₂ minus
    // it, metres).
    struct Contact {
        double distance;
        double depth;
    };
    std::unordered_map<std::uint64_t, Contact> contacts_;
};

}  // namespace psb::exact
