#include "view/bin_histogram.hpp"
#include "session/units.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace psb::app {
namespace {

/// Three figures, and every digit before the point from 100 up ("4.21", "1234").
std::string number(double v) {
    return v >= 100.0 ? plainNumber(std::round(v), 17) : plainNumber(v, 3);
}

std::string verdict(const std::optional<ChiSquareTest>& t) {
    if (!t || !t->valid()) return "too few balls yet to compare with the curve";
    const std::string stat = "chi-squared " + number(t->statistic);
    if (t->passes())
        return "close to the curve: " + stat + " < " + number(t->critical) + ", chance";
    return "far from the curve: " + stat + " > " + number(t->critical) + ", more than chance";
}

}  // namespace

std::string probabilityText(double p) {
    if (p == 0.5) return "1/2";
    return plainNumber(p, 3);
}

double normalCount(double k, const BinomialExpectation& b, double total) {
    const double n = b.trials, mean = n * b.p, sigma = std::sqrt(n * b.p * (1.0 - b.p));
    if (!(sigma > 0.0)) return 0.0;
    const double z = (k - mean) / sigma;
    return total * std::exp(-0.5 * z * z) / (sigma * std::sqrt(2.0 * std::numbers::pi));
}

BinHistogram binHistogram(const Bins& bins, const ParticleArrays& p, std::uint64_t stillToDrop) {
    BinHistogram h;
    h.bins = bins;
    h.now = measureBins(bins, p);
    const BinCounts& c = h.now.counts;
    // The board has more channels than bins: which ones count is marked on it (bin_marks.hpp).
    std::string bars = "bars: balls in bins 0 to " + std::to_string(bins.size() - 1) +
                       ", marked on the board (" + std::to_string(c.counted()) + " landed";
    if (c.above > 0) bars += ", " + std::to_string(c.above) + " not yet in the bins";
    if (c.outside > 0) bars += ", " + std::to_string(c.outside) + " outside the bins";
    if (stillToDrop > 0) bars += ", " + std::to_string(stillToDrop) + " still to drop";
    h.legend.push_back(bars + ")");
    if (const auto& b = bins.binomial) {
        h.legend.push_back("dots: binomial, " + std::to_string(b->trials) +
                           " rows, p = " + probabilityText(b->p));
        const double sigma = std::sqrt(b->trials * b->p * (1.0 - b->p));
        h.legend.push_back("line: normal curve (mean " + number(b->trials * b->p) + ", spread " +
                           number(sigma) + " bins)");
        h.legend.push_back(verdict(h.now.test));
    }
    return h;
}

}  // namespace psb::app
