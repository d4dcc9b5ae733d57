#include "observables/time_correlation.hpp"

namespace psb::observables {

void TimeCorrelation::configure(std::size_t particles, std::uint32_t maxLag,
                                std::uint32_t originEvery) {
    n_ = particles;
    maxLag_ = maxLag;
    originEvery_ = originEvery == 0 ? 1 : originEvery;
    origins_.assign(maxLag == 0 ? 0 : maxLag / originEvery_ + 1, Origin{});
}

void TimeCorrelation::add(std::uint64_t k, const std::vector<double>& x,
                          const std::vector<double>& y, const std::vector<double>& vx,
                          const std::vector<double>& vy, Chunk& into) {
    if (maxLag_ == 0) return;
    if (into.msd.size() < maxLag_ + 1u) {
        into.msd.resize(maxLag_ + 1u, 0.0);
        into.vacf.resize(maxLag_ + 1u, 0.0);
        into.lagCount.resize(maxLag_ + 1u, 0.0);
    }
    Origin* free = nullptr;
    for (Origin& o : origins_) {
        if (o.live && k - o.k > maxLag_) o.live = false;
        if (!o.live) {
            if (free == nullptr) free = &o;
            continue;
        }
        const std::uint64_t lag = k - o.k;
        double squared = 0.0, product = 0.0;
        for (std::size_t i = 0; i < n_; ++i) {
            const double dx = x[i] - o.x[i], dy = y[i] - o.y[i];
            squared += dx * dx + dy * dy;
            product += vx[i] * o.vx[i] + vy[i] * o.vy[i];
        }
        into.msd[lag] += squared;
        into.vacf[lag] += product;
        into.lagCount[lag] += static_cast<double>(n_);
    }
    if (k % originEvery_ != 0 || free == nullptr) return;
    free->k = k;
    free->live = true;
    free->x = x;
    free->y = y;
    free->vx = vx;
    free->vy = vy;
    // Lag 0: v(0)·v(0) (the MSD's is 0).
    double product = 0.0;
    for (std::size_t i = 0; i < n_; ++i)
        product += vx[i] * vx[i] + vy[i] * vy[i];
    into.vacf[0] += product;
    into.lagCount[0] += static_cast<double>(n_);
}

}  // namespace psb::observables
