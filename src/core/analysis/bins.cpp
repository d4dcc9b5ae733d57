// Counting the particles in a board's bins, and what a binomial board expects there.

#include <particle_sandbox/bins.hpp>

#include <algorithm>
#include <numeric>

#include <boost/math/distributions/binomial.hpp>

namespace psb {

std::size_t BinCounts::counted() const {
    return std::accumulate(counts.begin(), counts.end(), std::size_t{0});
}

BinCounts countBins(const Bins& bins, const ParticleArrays& p) {
    BinCounts c;
    c.counts.assign(bins.size(), 0);
    for (std::size_t i = 0; i < p.size(); ++i) {
        if (!(p.y[i] > bins.top)) {  // NaN too
            ++c.above;
            continue;
        }
        const double x = p.x[i];
        // Bin k holds [edges[k], edges[k + 1]): the first edge above x ends x's bin.
        const auto end = std::upper_bound(bins.edges.begin(), bins.edges.end(), x);
        if (end == bins.edges.begin() || end == bins.edges.end() || !(x == x)) {
            ++c.outside;
        } else {
            ++c.counts[static_cast<std::size_t>(end - bins.edges.begin() - 1)];
        }
    }
    return c;
}

std::vector<double> binomialProbabilities(const BinomialExpectation& b) {
    const boost::math::binomial_distribution<double> d(b.trials, b.p);
    std::vector<double> out(static_cast<std::size_t>(b.trials) + 1);
    for (std::size_t k = 0; k < out.size(); ++k)
        out[k] = boost::math::pdf(d, static_cast<double>(k));
    return out;
}

std::vector<double> expectedCounts(const Bins& bins, std::size_t total) {
    if (!bins.binomial) return {};
    std::vector<double> out = binomialProbabilities(*bins.binomial);
    for (double& e : out)
        e *= static_cast<double>(total);
    return out;
}

BinsMeasurement measureBins(const Bins& bins, const ParticleArrays& p) {
    BinsMeasurement m;
    m.counts = countBins(bins, p);
    m.expected = expectedCounts(bins, m.counts.counted());
    if (bins.binomial) m.test = chiSquareTest(m.counts.counts, m.expected);
    return m;
}

}  // namespace psb
