// Pairs of the exact stepper placed overlapping: found at a rebuild, kept at their placed
// distance until they are apart. Why: placed_contacts.hpp.

#include "exact/placed_contacts.hpp"

#include <algorithm>
#include <cmath>

#include "support/periodic_box.hpp"

namespace psb::exact {

void PlacedContacts::record(std::vector<Body>& bodies, const std::vector<Cold>& cold,
                            const std::vector<std::uint32_t>& order, const Grid& grid,
                            const periodic::Box& box) {
    // A pair that overlaps here was placed so from outside: its contact distance is the
    // distance it has now, until it is found apart (contactDistance).
    contacts_.clear();
    const auto n = static_cast<std::uint32_t>(bodies.size());
    for (std::uint32_t i = 0; i < n; ++i) {
        const Body& a = bodies[i];
        grid.forEachAround(cold[i], [&](std::uint32_t q) {
            Body& b = bodies[q];
            if (q <= i || ((a.flags & kImmovable) && (b.flags & kImmovable))) return;
            double rx = b.x - a.x, ry = b.y - a.y;
            if (grid.periodic()) {
                // Overlapping, so at most half a box apart (support/periodic_box.hpp).
                rx = periodic::minimumImage(rx, box.width);
                ry = periodic::minimumImage(ry, box.height);
            }
            const double sigma = a.r + b.r;
            const double d2 = rx * rx + ry * ry;
            if (!(d2 < sigma * sigma)) return;
            const double d = std::sqrt(d2);
            contacts_[pairKey(order[i], order[q])] = {d, sigma - d};
            bodies[i].flags |= kPlacedOverlapping;
            b.flags |= kPlacedOverlapping;
        });
    }
}

double PlacedContacts::deepest() const {
    double deepest = 0.0;
    for (const auto& [key, contact] : contacts_)
        deepest = std::max(deepest, contact.depth);
    return deepest;
}

std::size_t PlacedContacts::memoryBytes() const {
    // An unordered_map node holds the key, the value and the next pointer; the table one
    // pointer per bucket.
    return contacts_.size() * (sizeof(std::uint64_t) + sizeof(Contact) + sizeof(void*)) +
           contacts_.bucket_count() * sizeof(void*);
}

}  // namespace psb::exact
