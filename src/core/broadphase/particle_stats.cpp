#include "broadphase/particle_stats.hpp"

#include <algorithm>
#include <cmath>

#include "support/parallel.hpp"

namespace psb {

void measureBlock(const ParticleArrays& p, std::size_t begin, std::size_t end, ParticleStats& out) {
    const double* x = p.x.data();
    const double* y = p.y.data();
    const double* r = p.radius.data();
    double minX = x[begin], maxX = x[begin], minY = y[begin], maxY = y[begin];
    double sumR = 0.0, maxR = 0.0, minR = r[begin];
    for (std::size_t i = begin; i < end; ++i) {
        minX = std::min(minX, x[i]);
        maxX = std::max(maxX, x[i]);
        minY = std::min(minY, y[i]);
        maxY = std::max(maxY, y[i]);
        sumR += r[i];
        maxR = std::max(maxR, r[i]);
        minR = std::min(minR, r[i]);
    }
    out.count = end - begin;
    out.minX = minX;
    out.maxX = maxX;
    out.minY = minY;
    out.maxY = maxY;
    out.meanRadius = sumR;  // a sum until combined
    out.maxRadius = maxR;
    out.minRadius = minR;
}

ParticleStats combineBlocks(const std::vector<ParticleStats>& blocks, std::size_t n) {
    ParticleStats s;
    if (n == 0) return s;
    // Blocks in order: the radius sum rounds the same way for any thread count (rule 2 of
    // parallel.hpp).
    const std::size_t count = parallel::blockCount(n);
    s = blocks[0];
    double sumR = blocks[0].meanRadius;
    for (std::size_t b = 1; b < count; ++b) {
        const ParticleStats& o = blocks[b];
        s.minX = std::min(s.minX, o.minX);
        s.maxX = std::max(s.maxX, o.maxX);
        s.minY = std::min(s.minY, o.minY);
        s.maxY = std::max(s.maxY, o.maxY);
        s.maxRadius = std::max(s.maxRadius, o.maxRadius);
        s.minRadius = std::min(s.minRadius, o.minRadius);
        sumR += o.meanRadius;
    }
    s.count = n;
    s.meanRadius = sumR / static_cast<double>(n);
    s.maxAbsCoordinate =
        std::max({std::abs(s.minX), std::abs(s.maxX), std::abs(s.minY), std::abs(s.maxY)});
    return s;
}

ParticleStats measureParticles(const ParticleArrays& p, int threads,
                               std::vector<ParticleStats>& blockScratch) {
    const std::size_t n = p.size();
    if (n == 0) return {};
    blockScratch.resize(parallel::blockCount(n));
    parallel::forBlocks(threads, n, [&](std::size_t b, std::size_t begin, std::size_t end) {
        measureBlock(p, begin, end, blockScratch[b]);
    });
    return combineBlocks(blockScratch, n);
}

}  // namespace psb
