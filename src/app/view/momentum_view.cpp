#include "view/momentum_view.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <particle_sandbox/diagnostics.hpp>

#include "session/units.hpp"

namespace psb::app {
double meanMass(const ParticleArrays& p) {
    double m = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i)
        m += p.mass[i];
    return p.size() > 0 ? m / static_cast<double>(p.size()) : 1.0;
}

TotalMomentumArrow totalMomentumArrow(const World& world, const ObservablesSample& now,
                                      double arrowSeconds) {
    TotalMomentumArrow a;
    a.from = now.centreOfMass;
    const Vec2 total = now.momentum;
    Vec2 d = arrowSeconds * total / meanMass(world.particles());
    const double cap = 0.4 * std::min(world.def().width, world.def().height);
    if (d.norm() > cap) {
        d *= cap / d.norm();
        a.capped = true;
    }
    a.to = a.from + d;
    return a;
}

std::vector<std::string> momentumLegend(const World& world, const ObservablesSample& now,
                                        double arrowSeconds, const Axes& axes) {
    // Signed components as every other reading writes them: "P = (14.3, -35.7) kg m/s".
    std::string total = "P = " + components(axes.vector(now.momentum)) + " kg m/s";
    if (totalMomentumArrow(world, now, arrowSeconds).capped) total += " (arrow capped)";
    return {total, "m v per particle", "centre of mass and its path"};
}

}  // namespace psb::app
