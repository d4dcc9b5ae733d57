#include "accuracy_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <vector>

namespace psb::cli {

MoveCheck checkMove(const ParticleArrays& p, double h, const Vec2& gravity) {
    const std::size_t n = p.size();
    std::vector<double> vx(n), vy(n), lo(n), hi(n);
    for (std::size_t i = 0; i < n; ++i) {
        vx[i] = p.vx[i] + (p.isKinematic(i) ? 0.0 : gravity.x() * h);
        vy[i] = p.vy[i] + (p.isKinematic(i) ? 0.0 : gravity.y() * h);
        const double x1 = p.x[i] + vx[i] * h;
        lo[i] = std::min(p.x[i], x1) - p.radius[i];
        hi[i] = std::max(p.x[i], x1) + p.radius[i];
    }
    std::vector<std::size_t> order(n);
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return lo[a] < lo[b] || (lo[a] == lo[b] && a < b);
    });

    MoveCheck out;
    for (std::size_t oi = 0; oi < n; ++oi) {
        const std::size_t i = order[oi];
        const double yi1 = p.y[i] + vy[i] * h;
        const double iyLo = std::min(p.y[i], yi1) - p.radius[i];
        const double iyHi = std::max(p.y[i], yi1) + p.radius[i];
        for (std::size_t oj = oi + 1; oj < n && lo[order[oj]] <= hi[i]; ++oj) {
            const std::size_t j = order[oj];
            const double yj1 = p.y[j] + vy[j] * h;
            if (std::max(p.y[j], yj1) + p.radius[j] < iyLo ||
                std::min(p.y[j], yj1) - p.radius[j] > iyHi)
                continue;
            const double sigma = p.radius[i] + p.radius[j];
            const double dx = p.x[j] - p.x[i], dy = p.y[j] - p.y[i];
            const double mx = (vx[j] - vx[i]) * h, my = (vy[j] - vy[i]) * h;
            const double ex = dx + mx, ey = dy + my;
            const double end2 = ex * ex + ey * ey;
            if (end2 < sigma * sigma) {
                ++out.detected;
                const double depth = sigma - std::sqrt(end2);
                out.maxOverlapOverRadius =
                    std::max(out.maxOverlapOverRadius, depth / std::min(p.radius[i], p.radius[j]));
                continue;
            }
            if (dx * dx + dy * dy < sigma * sigma) continue;  // in contact at the start
            const double a = mx * mx + my * my;
            const double b = dx * mx + dy * my;
            if (a == 0.0 || b >= 0.0 || -b >= a) continue;  // closest approach at an end
            // Squared distance of closest approach as (d0 × D)² / |D|²: no cancellation.
            const double cross = dx * my - dy * mx;
            if (cross * cross < sigma * sigma * a) ++out.missed;
        }
    }
    return out;
}

double wallPressure(const RunTotals& r) {
    if (r.wallLength <= 0.0 || r.simTime <= 0.0) return std::numeric_limits<double>::quiet_NaN();
    return r.wallImpulse / (r.simTime * r.wallLength);
}

ErrorMeasures compareToExact(const RunTotals& run, const RunTotals& exact) {
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    ErrorMeasures e;
    e.collisionRatio = exact.collisions > 0 ? static_cast<double>(run.collisions) /
                                                  static_cast<double>(exact.collisions)
                                            : nan;
    e.missed = run.missed;
    e.maxOverlapOverRadius = run.maxOverlapOverRadius;
    e.kineticEnergyError =
        run.kineticEnergyInitial > 0.0
            ? std::abs(run.kineticEnergyFinal - exact.kineticEnergyFinal) / run.kineticEnergyInitial
            : nan;
    e.positionErrorOverRadius = nan;
    if (run.finalPositions.size() == exact.finalPositions.size() && exact.smallestRadius > 0.0) {
        double worst = 0.0;
        for (std::size_t i = 0; i < run.finalPositions.size(); ++i)
            worst = std::max(worst, (run.finalPositions[i] - exact.finalPositions[i]).norm());
        e.positionErrorOverRadius = worst / exact.smallestRadius;
    }
    const double pe = wallPressure(exact);
    e.pressureRatio = pe > 0.0 ? wallPressure(run) / pe : nan;
    e.wallSecondsPerSimSecond = run.simTime > 0.0 ? run.wallSeconds / run.simTime : nan;
    e.cpuSecondsPerSimSecond = run.simTime > 0.0 ? run.cpuSeconds / run.simTime : nan;
    const double work = static_cast<double>(run.particles) * static_cast<double>(run.steps);
    e.nsPerParticleStep = work > 0.0 ? run.wallSeconds * 1e9 / work : nan;
    return e;
}

}  // namespace psb::cli
