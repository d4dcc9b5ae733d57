#pragma once
/// \file
/// Bins under a board: where a Galton board's bins are, which particles have landed in them,
/// and how many each should hold. A scene may describe its bins (the `bins` field of a scene
/// file, docs/scenes.md); the runner reports their counts and the app draws them as a histogram
/// against the expected distribution.

#include <cstddef>
#include <optional>
#include <vector>

#include <particle_sandbox/chi_square.hpp>
#include <particle_sandbox/particle_arrays.hpp>

namespace psb {

/// The expected distribution of a board whose bin k collects the particles that made k
/// successes in `trials` independent trials of probability `p` (a Galton board of `trials` rows
/// of pegs, each sending a ball right with probability p, has trials + 1 bins).
struct BinomialExpectation {
    int trials = 1;  ///< n >= 1
    double p = 0.5;  ///< in [0, 1]

    friend bool operator==(const BinomialExpectation&, const BinomialExpectation&) = default;
};

/// Bins side by side along x. Bin k spans [edges[k], edges[k + 1]); a particle is in the bins
/// once its centre is below the line y = `top` (y grows downward), and in bin k when its centre's
/// x lies in bin k's span.
struct Bins {
    std::vector<double> edges;  ///< x of the bin boundaries, metres, strictly increasing, >= 2
    double top = 0.0;           ///< y of the bins' opening, metres
    /// What the counts should follow, if the scene says; with a binomial, edges.size() ==
    /// trials + 2 (one bin per number of successes).
    std::optional<BinomialExpectation> binomial;

    [[nodiscard]] std::size_t size() const { return edges.empty() ? 0 : edges.size() - 1; }
    friend bool operator==(const Bins&, const Bins&) = default;
};

/// Largest number of bins a scene may have.
inline constexpr std::size_t kMaxBins = 10'000;
/// Largest number of trials of a binomial expectation.
inline constexpr int kMaxBinomialTrials = 1'000'000;

/// The particles in each bin.
struct BinCounts {
    std::vector<std::size_t> counts;  ///< per bin, left to right
    std::size_t outside = 0;  ///< below `top` but left of the first edge or right of the last
    std::size_t above = 0;    ///< not yet below `top`

    /// Particles in the bins (the sum of `counts`).
    [[nodiscard]] std::size_t counted() const;
};

/// Counts the particles of `p` in `bins` (NaN positions count as above).
[[nodiscard]] BinCounts countBins(const Bins& bins, const ParticleArrays& p);

/// P(X = k), X ~ Binomial(n, p), for k = 0 ... n.
[[nodiscard]] std::vector<double> binomialProbabilities(const BinomialExpectation& b);

/// The counts `bins` expects when `total` particles have landed: total × P(bin k), or empty
/// when the scene says no distribution.
[[nodiscard]] std::vector<double> expectedCounts(const Bins& bins, std::size_t total);

/// What the bins hold now, against what they should.
struct BinsMeasurement {
    BinCounts counts;
    /// expectedCounts(bins, counts.counted()): empty without an expected distribution.
    std::vector<double> expected;
    /// The counts against `expected` at 1 %, when there is an expectation.
    std::optional<ChiSquareTest> test;
};

/// Counts the particles of `p` in `bins` and tests the counts against the expectation.
[[nodiscard]] BinsMeasurement measureBins(const Bins& bins, const ParticleArrays& p);

}  // namespace psb
