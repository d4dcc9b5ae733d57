#pragma once
// The radial distribution function g(r): pair distances counted into bins, normalised by what
// as many uniformly placed centres in the same rectangle (or periodic box) would give, and its
// contact value.

#include <cstddef>
#include <cstdint>
#include <vector>

namespace psb::observables {

class PairDistribution {
  public:
    /// Distances below `range` (m, > 0) in bins of `binWidth` (m, > 0); positions are in the box
    /// [0, width] × [0, height] (a centre outside counts in the nearest cell). In a `periodic`
    /// box a pair's distance is its nearest images' (the range at most half the box's shorter
    /// side, so that no pair is counted twice).
    void configure(double range, double binWidth, double width, double height,
                   bool periodic = false);
    [[nodiscard]] std::size_t bins() const { return bins_; }
    [[nodiscard]] double binWidth() const { return binWidth_; }
    [[nodiscard]] double range() const { return range_; }

    /// Adds every unordered pair closer than the range to `counts` (bins() entries): a cell grid
    /// of cells at least `range` wide, each cell against itself and four neighbours (in a
    /// periodic box the cells wrap; fewer than three along a side, one cell holds all).
    void count(const std::vector<double>& x, const std::vector<double>& y,
               std::vector<double>& counts);

    /// g in each bin from `counts` over `snapshots` snapshots of n centres that move in the
    /// rectangle a × b (the centres' box): counts over n(n − 1)/2 times the probability that two
    /// uniform points of the rectangle lie that far apart. Bins beyond min(a, b) are NaN (the
    /// formula holds up to there). In a periodic box a × b is the box, and that probability is
    /// the ring's area over the box's: 2π r dr / (ab).
    [[nodiscard]] std::vector<double> g(const std::vector<double>& counts, std::uint64_t snapshots,
                                        std::size_t n, double a, double b) const;

    /// g(σ): the quadratic least-squares fit to the bins that lie in [σ, 1.2 σ], evaluated at σ;
    /// NaN with fewer than four such bins or any of them NaN.
    [[nodiscard]] double contactValue(const std::vector<double>& g, double sigma) const;

  private:
    double range_ = 0.0, binWidth_ = 0.0, width_ = 0.0, height_ = 0.0;
    bool periodic_ = false;
    std::size_t bins_ = 0;
    std::vector<std::uint32_t> cellStart_, order_, cellOf_;
};

/// ∫ from r1 to r2 of 2π r γ̄(r) dr for the rectangle a × b, where γ̄(r) = ab − 2r(a + b)/π +
/// r²/π is its isotropic set covariance (the area it shares with itself shifted by r, averaged
/// over directions; valid for r ≤ min(a, b)). Divided by (ab)², the probability that two
/// uniform points of the rectangle are between r1 and r2 apart.
[[nodiscard]] double rectanglePairMeasure(double a, double b, double r1, double r2);

}  // namespace psb::observables
