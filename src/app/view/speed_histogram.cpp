#include "view/speed_histogram.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>

namespace psb::app {

double rayleighDensity(double v, double kT, double m) {
    if (!(v >= 0.0) || !(kT > 0.0) || !(m > 0.0)) return 0.0;
    const double a = m / kT;
    return a * v * std::exp(-0.5 * a * v * v);
}

double SpeedHistogram::expectedDensity(double v) const {
    if (particles == 0) return 0.0;
    double f = 0.0;
    for (const auto& [m, n] : masses)
        f += static_cast<double>(n) * rayleighDensity(v, kT, m);
    return f / static_cast<double>(particles);
}

SpeedHistogram speedHistogram(const ParticleArrays& p, std::size_t bins) {
    std::vector<double> speeds;
    SpeedHistogram h;
    h.counts.assign(std::max<std::size_t>(bins, 1), 0);
    h.particles = p.size();
    if (p.size() == 0) return h;
    double energy = 0.0, fastest = 0.0;
    std::map<double, std::size_t> masses;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const double v2 = p.vx[i] * p.vx[i] + p.vy[i] * p.vy[i];
        energy += 0.5 * p.mass[i] * v2;
        fastest = std::max(fastest, std::sqrt(v2));
        ++masses[p.mass[i]];
    }
    h.masses.assign(masses.begin(), masses.end());
    h.kT = energy / static_cast<double>(p.size());
    // Twice the 99th percentile speed: a gas keeps its tail, a bullet goes off scale.
    speeds.resize(p.size());
    for (std::size_t i = 0; i < p.size(); ++i)
        speeds[i] = std::hypot(p.vx[i], p.vy[i]);
    const auto q = speeds.begin() + static_cast<std::ptrdiff_t>(p.size() * 99 / 100);
    std::nth_element(speeds.begin(), q, speeds.end());
    h.vmax = std::min(fastest, 2.0 * *q);
    if (!(h.vmax > 0.0) || !std::isfinite(h.vmax)) h.vmax = 1.0;
    const double width = h.binWidth();
    for (std::size_t i = 0; i < p.size(); ++i) {
        const double v = std::hypot(p.vx[i], p.vy[i]);
        if (v > h.vmax) {
            ++h.overflow;
            continue;
        }
        // The fastest particle sits exactly at vmax: it belongs to the last bin.
        const auto b = std::min(h.counts.size() - 1, static_cast<std::size_t>(v / width));
        ++h.counts[b];
    }
    return h;
}

}  // namespace psb::app
