#include "particle_stats.hpp"

#include <algorithm>
#include <cmath>

#include "parallel.hpp"

namespace psb {

ParticleStats measureParticles(const ParticleArrays& p, int threads,
                               std::vector<ParticleStats>& blockScratch) {
    const std::size_t n = p.size();
    ParticleStats s;
    if (n == 0) return s;
    const double* x = p.x.data();
    const double* y = p.y.data();
    const double* r = p.radius.data();
    blockScratch.resize(parallel::blockCount(n));
    // The radius sum is the only order-sensitive term: one sequential sum per fixed block,
    // blocks added in order (rule 2 of parallel.hpp).
    parallel::forBlocks(threads, n, [&](std::size_t b, std::size_t begin, std::size_t end) {
        double minX = x[begin], maxX = x[begin], minY = y[begin], maxY = y[begin];
        double sumR = 0.0, maxR = 0.0;
        for (std::size_t i = begin; i < end; ++i) {
            minX = std::min(minX, x[i]);
            maxX = std::max(maxX, x[i]);
            minY = std::min(minY, y[i]);
            maxY = std::max(maxY, y[i]);
            sumR += r[i];
            maxR = std::max(maxR, r[i]);
        }
        ParticleStats& o = blockScratch[b];
        o.minX = minX;
        o.maxX = maxX;
        o.minY = minY;
        o.maxY = maxY;
        o.meanRadius = sumR;  // a sum until combined below
        o.maxRadius = maxR;
    });
    s = blockScratch[0];
    double sumR = blockScratch[0].meanRadius;
    for (std::size_t b = 1; b < blockScratch.size(); ++b) {
        const ParticleStats& o = blockScratch[b];
        s.minX = std::min(s.minX, o.minX);
        s.maxX = std::max(s.maxX, o.maxX);
        s.minY = std::min(s.minY, o.minY);
        s.maxY = std::max(s.maxY, o.maxY);
        s.maxRadius = std::max(s.maxRadius, o.maxRadius);
        sumR += o.meanRadius;
    }
    s.count = n;
    s.meanRadius = sumR / static_cast<double>(n);
    s.maxAbsCoordinate =
        std::max({std::abs(s.minX), std::abs(s.maxX), std::abs(s.minY), std::abs(s.maxY)});
    return s;
}

}  // namespace psb
