#pragma once
// The bins panel: a Galton board's bin counts as bars, against the binomial distribution its
// scene expects (a dot per bin) and the normal curve that approximates it (mean n p, standard
// deviation sqrt(n p (1 - p)), scaled to the balls counted), with a legend in plain words and a
// line saying how far the counts are from the curve (Pearson's chi-squared test at 1 %).
//
// What it says is computed here (binHistogram), from the same counts the chart draws
// (render/bin_chart.hpp), so the words and the bars never disagree; the screen-text dump (F12)
// lists the same lines.

#include <cstdint>
#include <string>
#include <vector>

#include <particle_sandbox/bins.hpp>

namespace psb::app {

/// The panel's content for one frame.
struct BinHistogram {
    Bins bins;
    BinsMeasurement now;
    /// The legend, one line each: the bars, the binomial, the normal curve, the verdict.
    std::vector<std::string> legend;
};

/// The bins of `p` now, and the legend that describes them; `stillToDrop` balls are still in
/// the scene's droppers (counted in the legend, not yet anywhere on the board).
[[nodiscard]] BinHistogram binHistogram(const Bins& bins, const ParticleArrays& p,
                                        std::uint64_t stillToDrop = 0);

/// The normal approximation to Binomial(n, p) over `total` balls, as a count per bin at bin
/// position `k` (bins one unit wide): total · φ((k − n p) / σ) / σ, σ = sqrt(n p (1 − p)).
/// 0 when σ is 0.
[[nodiscard]] double normalCount(double k, const BinomialExpectation& b, double total);

/// "1/2" for 0.5, else the probability with up to three significant digits.
[[nodiscard]] std::string probabilityText(double p);

}  // namespace psb::app
