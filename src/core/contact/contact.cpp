#include "contact/contact.hpp"

#include <cmath>
#include <numbers>

namespace psb {

Normal coincidentNormal(ParticleId a, ParticleId b) {
    const bool swapped = a.slot > b.slot;
    const std::uint64_t lo = swapped ? b.slot : a.slot;
    const std::uint64_t hi = swapped ? a.slot : b.slot;
    // SplitMix64 finaliser over the ordered pair of slots: cheap, well mixed, reproducible.
    std::uint64_t h = lo * 0x9E3779B97F4A7C15ull ^ (hi + 0x632BE59BD9B4E019ull);
    h ^= h >> 30;
    h *= 0xBF58476D1CE4E5B9ull;
    h ^= h >> 27;
    h *= 0x94D049BB133111EBull;
    h ^= h >> 31;
    const double angle = static_cast<double>(h >> 11) * 0x1.0p-53 * 2.0 * std::numbers::pi;
    const double s = swapped ? -1.0 : 1.0;
    return {s * std::cos(angle), s * std::sin(angle)};
}

}  // namespace psb
