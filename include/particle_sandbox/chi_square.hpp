#pragma once
/// \file
/// Pearson's χ² goodness-of-fit test: how far counts are from the counts a distribution
/// expects, and whether the difference is more than chance would make.

#include <cstddef>
#include <vector>

namespace psb {

/// The outcome of a χ² test.
struct ChiSquareTest {
    /// The classes compared, after merging: adjacent classes are merged, left to right, until
    /// each merged class expects at least the minimum (5 by default), so that the χ²
    /// approximation holds; a remainder at the right end joins the last class. For a binomial
    /// this merges each thin tail into its neighbours.
    std::vector<double> observed, expected;
    double statistic = 0.0;  ///< Σ (observed − expected)² / expected over the merged classes
    int dof = 0;             ///< degrees of freedom: merged classes − 1 (0: no test possible)
    double critical = 0.0;   ///< the statistic that chance exceeds with probability `alpha`
    double alpha = 0.01;     ///< the significance level
    double pValue = 1.0;     ///< the probability that chance gives a statistic at least this large

    /// A test was possible (at least two classes).
    [[nodiscard]] bool valid() const { return dof >= 1; }
    /// The counts are consistent with the distribution at level alpha (statistic <= critical).
    [[nodiscard]] bool passes() const { return valid() && statistic <= critical; }
};

/// The value that a χ² variable of `dof` degrees of freedom exceeds with probability `alpha`
/// (the upper critical value: 16.81 for dof 6 at 1 %). dof >= 1, alpha in (0, 1).
[[nodiscard]] double chiSquareCritical(int dof, double alpha);

/// The probability that a χ² variable of `dof` degrees of freedom is at least `statistic`.
[[nodiscard]] double chiSquareUpperTail(int dof, double statistic);

/// Tests `observed` against `expected` (same length, expected >= 0) at level `alpha`, merging
/// classes that expect fewer than `minExpected`.
[[nodiscard]] ChiSquareTest chiSquareTest(const std::vector<std::size_t>& observed,
                                          const std::vector<double>& expected, double alpha = 0.01,
                                          double minExpected = 5.0);

}  // namespace psb
