#include "observables/pair_distribution.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <Eigen/Dense>

namespace psb::observables {

double rectanglePairMeasure(double a, double b, double r1, double r2) {
    const auto pow = [](double r, int k) { return std::pow(r, k); };
    return std::numbers::pi * a * b * (pow(r2, 2) - pow(r1, 2)) -
           4.0 / 3.0 * (a + b) * (pow(r2, 3) - pow(r1, 3)) + 0.5 * (pow(r2, 4) - pow(r1, 4));
}

void PairDistribution::configure(double range, double binWidth, double width, double height,
                                 bool periodic) {
    // Beyond half the box a pair would be nearer through another image.
    range_ = periodic ? std::min(range, 0.5 * std::min(width, height)) : range;
    binWidth = std::min(binWidth, range_);
    binWidth_ = binWidth;
    width_ = width;
    height_ = height;
    periodic_ = periodic;
    // Whole bins only: a last bin cut by the range would read low.
    bins_ = static_cast<std::size_t>(std::floor(range_ / binWidth + 1e-9));
    range_ = static_cast<double>(bins_) * binWidth;
}

void PairDistribution::count(const std::vector<double>& x, const std::vector<double>& y,
                             std::vector<double>& counts) {
    const std::size_t n = x.size();
    if (counts.size() < bins_) counts.resize(bins_, 0.0);
    const auto cellsAlong = [this](double extent) {
        return static_cast<std::int64_t>(std::clamp(std::floor(extent / range_), 1.0, 4096.0));
    };
    std::int64_t nx = cellsAlong(width_), ny = cellsAlong(height_);
    // Wrapped, two cells along a side would be each other's neighbour on both sides.
    if (periodic_ && (nx < 3 || ny < 3)) nx = ny = 1;
    const double cw = width_ / static_cast<double>(nx), ch = height_ / static_cast<double>(ny);
    cellOf_.resize(n);
    cellStart_.assign(static_cast<std::size_t>(nx * ny) + 1, 0);
    for (std::size_t i = 0; i < n; ++i) {
        const auto cx = std::clamp<std::int64_t>(static_cast<std::int64_t>(x[i] / cw), 0, nx - 1);
        const auto cy = std::clamp<std::int64_t>(static_cast<std::int64_t>(y[i] / ch), 0, ny - 1);
        cellOf_[i] = static_cast<std::uint32_t>(cy * nx + cx);
        ++cellStart_[cellOf_[i] + 1];
    }
    for (std::size_t c = 1; c < cellStart_.size(); ++c)
        cellStart_[c] += cellStart_[c - 1];
    order_.resize(n);
    std::vector<std::uint32_t> fill(cellStart_.begin(), cellStart_.end() - 1);
    for (std::size_t i = 0; i < n; ++i)
        order_[fill[cellOf_[i]]++] = static_cast<std::uint32_t>(i);

    const double range2 = range_ * range_, inverseWidth = 1.0 / binWidth_;
    const auto pairsBetween = [&](std::uint32_t c, std::uint32_t d) {
        for (std::uint32_t s = cellStart_[c]; s < cellStart_[c + 1]; ++s) {
            const std::uint32_t i = order_[s];
            const std::uint32_t from = c == d ? s + 1 : cellStart_[d];
            for (std::uint32_t t = from; t < cellStart_[d + 1]; ++t) {
                const std::uint32_t j = order_[t];
                double dx = x[j] - x[i], dy = y[j] - y[i];
                if (periodic_) {  // both centres in the box: at most one box away
                    if (std::abs(dx) > 0.5 * width_) dx -= std::copysign(width_, dx);
                    if (std::abs(dy) > 0.5 * height_) dy -= std::copysign(height_, dy);
                }
                const double r2 = dx * dx + dy * dy;
                if (r2 >= range2) continue;
                const auto k = static_cast<std::size_t>(std::sqrt(r2) * inverseWidth);
                if (k < bins_) counts[k] += 1.0;
            }
        }
    };
    // Each cell against itself and the four neighbours after it (right, and the row below), so
    // that every pair of neighbouring cells is visited once.
    for (std::int64_t cy = 0; cy < ny; ++cy) {
        for (std::int64_t cx = 0; cx < nx; ++cx) {
            const auto c = static_cast<std::uint32_t>(cy * nx + cx);
            pairsBetween(c, c);
            const std::int64_t next[4][2] = {{1, 0}, {-1, 1}, {0, 1}, {1, 1}};
            if (nx == 1 && ny == 1) continue;
            for (const auto& o : next) {
                std::int64_t ox = cx + o[0], oy = cy + o[1];
                if (periodic_) {
                    ox = (ox + nx) % nx;
                    oy %= ny;
                } else if (ox < 0 || ox >= nx || oy >= ny) {
                    continue;
                }
                pairsBetween(c, static_cast<std::uint32_t>(oy * nx + ox));
            }
        }
    }
}

std::vector<double> PairDistribution::g(const std::vector<double>& counts, std::uint64_t snapshots,
                                        std::size_t n, double a, double b) const {
    std::vector<double> g(bins_, std::numeric_limits<double>::quiet_NaN());
    if (snapshots == 0 || n < 2 || !(a > 0.0) || !(b > 0.0)) return g;
    const double pairs =
        0.5 * static_cast<double>(n) * static_cast<double>(n - 1) * static_cast<double>(snapshots);
    const double reach = periodic_ ? 0.5 * std::min(a, b) : std::min(a, b);
    for (std::size_t k = 0; k < bins_ && k < counts.size(); ++k) {
        const double r1 = binWidth_ * static_cast<double>(k), r2 = r1 + binWidth_;
        if (r2 > reach) break;
        const double share = periodic_ ? std::numbers::pi * (r2 * r2 - r1 * r1) / (a * b)
                                       : rectanglePairMeasure(a, b, r1, r2) / (a * a * b * b);
        const double expected = pairs * share;
        if (expected > 0.0) g[k] = counts[k] / expected;
    }
    return g;
}

double PairDistribution::contactValue(const std::vector<double>& g, double sigma) const {
    // The bins inside [σ, 1.2σ]: g falls steeply from contact at high density, so the fit
    // keeps close; a quadratic follows its curvature there.
    Eigen::Matrix3d normal = Eigen::Matrix3d::Zero();
    Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
    int used = 0;
    for (std::size_t k = 0; k < g.size(); ++k) {
        const double r1 = binWidth_ * static_cast<double>(k), r2 = r1 + binWidth_;
        if (r1 < sigma * (1.0 - 1e-9)) continue;
        if (r2 > 1.2 * sigma * (1.0 + 1e-9)) break;
        if (!std::isfinite(g[k])) return std::numeric_limits<double>::quiet_NaN();
        const double u = (0.5 * (r1 + r2) - sigma) / sigma;
        const Eigen::Vector3d row(1.0, u, u * u);
        normal += row * row.transpose();
        rhs += row * g[k];
        ++used;
    }
    if (used < 4) return std::numeric_limits<double>::quiet_NaN();
    return normal.ldlt().solve(rhs)(0);
}

}  // namespace psb::observables
