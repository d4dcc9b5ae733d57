// Pearson's χ² goodness-of-fit test, with the χ² distribution's tail and quantile from
// Boost.Math.

#include <particle_sandbox/chi_square.hpp>

#include <cmath>

#include <boost/math/distributions/chi_squared.hpp>
#include <particle_sandbox/error.hpp>

namespace psb {

double chiSquareCritical(int dof, double alpha) {
    if (dof < 1 || !(alpha > 0.0 && alpha < 1.0)) {
        throw InvalidArgument("chiSquareCritical: needs dof >= 1 and alpha in (0, 1)");
    }
    const boost::math::chi_squared_distribution<double> d(dof);
    return boost::math::quantile(boost::math::complement(d, alpha));
}

double chiSquareUpperTail(int dof, double statistic) {
    if (dof < 1) throw InvalidArgument("chiSquareUpperTail: needs dof >= 1");
    if (!(statistic > 0.0)) return 1.0;
    if (std::isinf(statistic)) return 0.0;
    const boost::math::chi_squared_distribution<double> d(dof);
    return boost::math::cdf(boost::math::complement(d, statistic));
}

ChiSquareTest chiSquareTest(const std::vector<std::size_t>& observed,
                            const std::vector<double>& expected, double alpha, double minExpected) {
    if (observed.size() != expected.size()) {
        throw InvalidArgument("chiSquareTest: observed and expected differ in length");
    }
    ChiSquareTest t;
    t.alpha = alpha;
    double o = 0.0, e = 0.0;
    bool open = false;
    for (std::size_t k = 0; k < observed.size(); ++k) {
        o += static_cast<double>(observed[k]);
        e += expected[k];
        open = true;
        if (e >= minExpected) {
            t.observed.push_back(o);
            t.expected.push_back(e);
            o = e = 0.0;
            open = false;
        }
    }
    if (open) {  // a thin remainder at the right joins the last class
        if (t.expected.empty()) {
            t.observed.push_back(o);
            t.expected.push_back(e);
        } else {
            t.observed.back() += o;
            t.expected.back() += e;
        }
    }
    t.dof = static_cast<int>(t.expected.size()) - 1;
    if (!t.valid()) return t;
    for (std::size_t k = 0; k < t.expected.size(); ++k) {
        const double d = t.observed[k] - t.expected[k];
        // A class that expects nothing (p = 0 or 1) and holds nothing adds nothing.
        if (t.expected[k] > 0.0) {
            t.statistic += d * d / t.expected[k];
        } else if (d != 0.0) {
            t.statistic = INFINITY;
        }
    }
    t.critical = chiSquareCritical(t.dof, alpha);
    t.pValue = chiSquareUpperTail(t.dof, t.statistic);
    return t;
}

}  // namespace psb
