#include "view/momentum_view.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <particle_sandbox/diagnostics.hpp>

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
    const Vec2 P = axes.vector(now.momentum);
    char buf[96];
    std::snprintf(buf, sizeof buf, "P = [%.4g, %.4g] kg m/s%s", P.x(), P.y(),
                  totalMomentumArrow(world, now, arrowSeconds).capped ? " (arrow capped)" : "");
    return {buf, "m v per particle", "centre of mass and its path"};
}

}  // namespace psb::app
