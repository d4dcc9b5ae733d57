#include "view/plot_scale.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace psb::app {

double niceStep(double lo, double hi, int maxTicks) {
    const double span = hi - lo;
    if (!(span > 0.0) || !std::isfinite(span)) return 1.0;
    const double rough = span / std::max(1, maxTicks - 1);
    const double p = std::pow(10.0, std::floor(std::log10(rough)));
    for (const double m : {1.0, 2.0, 5.0, 10.0}) {
        if (m * p >= rough) return m * p;
    }
    return 10.0 * p;
}

std::vector<double> niceTicks(double lo, double hi, int maxTicks) {
    const double step = niceStep(lo, hi, maxTicks);
    std::vector<double> ticks;
    for (double t = std::ceil(lo / step - 1e-9) * step; t <= hi + 1e-9 * step; t += step) {
        ticks.push_back(std::abs(t) < 1e-12 * step ? 0.0 : t);
        if (ticks.size() > static_cast<std::size_t>(maxTicks) + 1) break;
    }
    return ticks;
}

AxisTicks axisTicks(double lo, double hi, int most) {
    most = std::max(1, most);
    AxisTicks t{niceTicks(lo, hi, most), niceStep(lo, hi, most)};
    const std::size_t least = static_cast<std::size_t>(std::min(3, most));
    if (t.values.size() >= least || !(hi > lo) || !std::isfinite(hi - lo)) return t;
    // Finer round steps, as long as their labels still have room.
    for (int finer = most + 1; finer <= most + 6; ++finer) {
        std::vector<double> values = niceTicks(lo, hi, finer);
        if (values.size() > static_cast<std::size_t>(most)) break;
        if (values.size() >= least) return {std::move(values), niceStep(lo, hi, finer)};
    }
    // No round step fits (a range of 4 steps of 1 offset by one: 2 and 4 at a step of 2, five
    // ticks at 1): the ends and the middle.
    const double step = (hi - lo) / 2.0;
    return {{lo, lo + step, hi}, step};
}

PlotRange plotRange(double dataMin, double dataMax, double minSpan) {
    if (!std::isfinite(dataMin) || !std::isfinite(dataMax)) return {};
    if (!(minSpan > 0.0) || !std::isfinite(minSpan)) minSpan = 1.0;
    double lo = dataMin, hi = dataMax;
    if (hi - lo < minSpan) {
        const double mid = 0.5 * (lo + hi);
        lo = mid - 0.5 * minSpan;
        hi = mid + 0.5 * minSpan;
    }
    const double step = niceStep(lo, hi, 4);
    return {std::floor(lo / step) * step, std::ceil(hi / step) * step};
}

std::string tickLabel(double v, double step) {
    if (v == 0.0) return "0";
    char buf[32];
    const double mag = std::max(std::abs(v), step);
    // Outside [1e-3, 1e5) the number takes an SI prefix ("4.04M", "2.5µ"), never an exponent;
    // digits down to the step's decade.
    int power = 0;
    if (mag >= 1e5 || mag < 1e-3) {
        power = std::clamp(3 * static_cast<int>(std::floor(std::log10(mag) / 3.0)), -9, 12);
    }
    const double unit = std::pow(10.0, power);
    const int decimals = std::max(0, -static_cast<int>(std::floor(std::log10(step / unit))));
    static const char* const kPrefix[] = {"n", "\u00b5", "m", "", "k", "M", "G", "T"};
    std::snprintf(buf, sizeof buf, "%.*f%s", decimals, v / unit, kPrefix[power / 3 + 3]);
    return buf;
}

std::string collisionRateTitle(double windowSeconds) {
    // Two figures: 0.5 s, 0.52 s, 1 s; never a row of digits from a dt that does not divide it.
    char buf[64];
    std::snprintf(buf, sizeof buf, "collisions/s, last %.2g s", windowSeconds);
    return buf;
}

std::string plotTitle(int plot, double windowSeconds, bool brief) {
    switch (plot) {
        case 0:
            return brief ? "energy (J)" : "kinetic energy (J)";
        case 1:
            return brief ? "px (kg m/s)" : "momentum px (kg m/s)";
        case 2:
            return brief ? "py (kg m/s)" : "momentum py (kg m/s)";
        default: {
            if (!brief) return collisionRateTitle(windowSeconds);
            char buf[64];
            std::snprintf(buf, sizeof buf, "coll./s, %.2g s", windowSeconds);
            return buf;
        }
    }
}

}  // namespace psb::app
