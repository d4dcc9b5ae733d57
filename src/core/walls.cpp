// The wall stage of the discrete step (see discrete_step.hpp).

#include <algorithm>
#include <cmath>

#include "contact.hpp"
#include "discrete_step.hpp"

namespace psb::stages {
namespace {

/// One axis of one particle against the walls at 0 and `extent`. The wall sets the sign of the
/// velocity: a particle past a wall and moving outward is turned inward with speed e·|v|; one
/// already moving inward keeps its velocity (the original negated it, throwing it back out).
/// Returns the normal impulse per unit mass delivered (>= 0). `vt` is the other velocity
/// component, reduced by wall friction when kFriction.
template <bool kFriction>
inline double wallAxis(double& x, double& v, double& vt, double r, double extent, double e,
                       double mu) {
    const double lo = r, hi = extent - r;
    if (lo >= hi) {
        // As wide as the box or wider: it touches both walls at once, so the only place it can
        // be is the centre and the only velocity it can have along this axis is zero.
        x = 0.5 * extent;
        const double dv = std::abs(v);
        v = 0.0;
        if constexpr (kFriction) vt -= std::copysign(std::min(std::abs(vt), mu * dv), vt);
        return dv;
    }
    if (x < lo) {
        x = lo;
        double out = -v;  // the left/top wall's outward normal points to -x
        const double dv = reboundOffWall<kFriction>(out, vt, e, mu);
        v = -out;
        return dv;
    }
    if (x > hi) {
        x = hi;
        return reboundOffWall<kFriction>(v, vt, e, mu);
    }
    return 0.0;
}

template <bool kFriction>
void wallsImpl(ParticleArrays& p, const WorldDef& def, StepCounters& counters) {
    const double e = def.restitution, mu = def.friction;
    const std::size_t n = p.size();
    std::uint64_t hits = 0;
    double impulse = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        const double r = p.radius[i];
        if (p.invMass[i] == 0.0) {
            // A held particle is clamped into the box but its velocity is its owner's.
            double vx = 0.0, vy = 0.0, vt = 0.0;
            wallAxis<false>(p.x[i], vx, vt, r, def.width, e, mu);
            wallAxis<false>(p.y[i], vy, vt, r, def.height, e, mu);
            continue;
        }
        const double jx = wallAxis<kFriction>(p.x[i], p.vx[i], p.vy[i], r, def.width, e, mu);
        const double jy = wallAxis<kFriction>(p.y[i], p.vy[i], p.vx[i], r, def.height, e, mu);
        if (jx > 0.0 || jy > 0.0) {
            hits += (jx > 0.0) + (jy > 0.0);
            impulse += p.mass[i] * (jx + jy);
        }
    }
    counters.wallCollisions += hits;
    counters.wallImpulse += impulse;
}

}  // namespace

void walls(ParticleArrays& p, const WorldDef& def, StepCounters& counters) {
    if (def.friction > 0.0) {
        wallsImpl<true>(p, def, counters);
    } else {
        wallsImpl<false>(p, def, counters);
    }
}

}  // namespace psb::stages
