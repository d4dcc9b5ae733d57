#include "broad_phase_all_pairs.hpp"

namespace psb {

void findPairsAllPairs(const ParticleArrays& p, std::vector<ContactPair>& out) {
    const std::size_t n = p.size();
    const double* x = p.x.data();
    const double* y = p.y.data();
    const double* r = p.radius.data();
    for (std::size_t i = 0; i < n; ++i) {
        const double xi = x[i], yi = y[i], ri = r[i];
        for (std::size_t j = i + 1; j < n; ++j) {
            const double dx = x[j] - xi;
            const double dy = y[j] - yi;
            const double rs = ri + r[j];
            if (dx * dx + dy * dy < rs * rs) {
                out.push_back({static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j)});
            }
        }
    }
}

}  // namespace psb
