#include "broadphase/broad_phase_all_pairs.hpp"

#include "broadphase/disc_overlap.hpp"

namespace psb {

void findPairsAllPairs(const ParticleArrays& p, std::vector<ContactPair>& out) {
    const std::size_t n = p.size();
    const double* x = p.x.data();
    const double* y = p.y.data();
    const double* r = p.radius.data();
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t j = i + 1; j < n; ++j) {
            const auto a = static_cast<std::uint32_t>(i), b = static_cast<std::uint32_t>(j);
            if (discsOverlap(x, y, r, a, b)) out.push_back({a, b});
        }
    }
}

void findPairsAllPairs(const ParticleArrays& p, const periodic::Box& box,
                       std::vector<ContactPair>& out) {
    const std::size_t n = p.size();
    const double* x = p.x.data();
    const double* y = p.y.data();
    const double* r = p.radius.data();
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t j = i + 1; j < n; ++j) {
            const auto a = static_cast<std::uint32_t>(i), b = static_cast<std::uint32_t>(j);
            if (discsOverlapPeriodic(x, y, r, a, b, box)) out.push_back({a, b});
        }
    }
}

}  // namespace psb
