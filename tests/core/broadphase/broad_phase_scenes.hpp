#pragma once
// Random particle layouts that broadphases find hard, shared by the broadphase tests.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include <particle_sandbox/particle_arrays.hpp>

namespace psb::test {

enum class Layout {
    Uniform,        ///< equal radii, uniform in a box, some overlapping
    RadiiSpan1000,  ///< radii log-uniform over three decades
    FewLarge,       ///< many small discs and a handful 50–500 times larger
    Clustered,      ///< tight Gaussian clusters with empty space between
    OneCorner,      ///< everything piled into one corner of a large box
    Outside,        ///< spread well beyond the box on every side (walls off)
    Coincident,     ///< groups of particles sharing one centre exactly
    FarFromOrigin,  ///< a small gas a million metres from the origin
};

inline const char* name(Layout l) {
    switch (l) {
        case Layout::Uniform:
            return "uniform";
        case Layout::RadiiSpan1000:
            return "radii-span-1000";
        case Layout::FewLarge:
            return "few-large";
        case Layout::Clustered:
            return "clustered";
        case Layout::OneCorner:
            return "one-corner";
        case Layout::Outside:
            return "outside";
        case Layout::Coincident:
            return "coincident";
        case Layout::FarFromOrigin:
            return "far-from-origin";
    }
    return "?";
}

inline constexpr Layout kAllLayouts[] = {
    Layout::Uniform,   Layout::RadiiSpan1000, Layout::FewLarge,   Layout::Clustered,
    Layout::OneCorner, Layout::Outside,       Layout::Coincident, Layout::FarFromOrigin};

inline void push(ParticleArrays& p, double x, double y, double r) {
    p.x.push_back(x);
    p.y.push_back(y);
    p.vx.push_back(0.0);
    p.vy.push_back(0.0);
    p.invMass.push_back(1.0);
    p.radius.push_back(r);
    p.mass.push_back(1.0);
    p.color.push_back({});
    p.id.push_back({static_cast<std::uint32_t>(p.id.size()), 0});
}

/// `n` particles in a layout; the box is 100 m × 100 m unless the layout says otherwise.
inline ParticleArrays makeLayout(Layout layout, std::size_t n, std::uint32_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::normal_distribution<double> g(0.0, 1.0);
    ParticleArrays p;
    const double side = 100.0;
    // Radius giving packing fraction ~0.3 for equal discs, so that many pairs overlap.
    const double r0 = std::sqrt(0.3 * side * side / (3.141592653589793 * n));
    for (std::size_t k = 0; k < n; ++k) {
        switch (layout) {
            case Layout::Uniform:
                push(p, side * u(rng), side * u(rng), r0);
                break;
            case Layout::RadiiSpan1000:
                push(p, side * u(rng), side * u(rng), 0.01 * std::pow(1000.0, u(rng)));
                break;
            case Layout::FewLarge:
                push(p, side * u(rng), side * u(rng),
                     k % 200 == 7 ? r0 * (50.0 + 450.0 * u(rng)) / 10.0 : r0);
                break;
            case Layout::Clustered: {
                const std::size_t c = k % 5;
                const double cx = 10.0 + 20.0 * c, cy = 90.0 - 17.0 * c;
                push(p, cx + 2.0 * g(rng), cy + 2.0 * g(rng), r0 * (0.5 + u(rng)));
                break;
            }
            case Layout::OneCorner:
                push(p, 5.0 * u(rng), 5.0 * u(rng), r0 * (0.5 + u(rng)));
                break;
            case Layout::Outside:
                push(p, -2.0 * side + 5.0 * side * u(rng), -2.0 * side + 5.0 * side * u(rng),
                     5.0 * r0 * (0.5 + u(rng)));
                break;
            case Layout::Coincident: {
                const double cx = side * std::floor(10.0 * u(rng)) / 10.0;
                const double cy = side * std::floor(10.0 * u(rng)) / 10.0;
                push(p, cx, cy, r0 * (0.5 + u(rng)));
                break;
            }
            case Layout::FarFromOrigin:
                push(p, 1e6 + side * u(rng), -1e6 + side * u(rng), r0);
                break;
        }
    }
    return p;
}

}  // namespace psb::test
