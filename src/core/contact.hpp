#pragma once
// The physics of one particle–particle contact: its normal, the velocity change it causes and
// the positional push that removes its overlap.

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <particle_sandbox/particle_id.hpp>

namespace psb {

/// Unit normal from particle a to particle b.
struct Normal {
    double x;
    double y;
};

/// The normal for two coincident centres, where geometry defines none. It is a fixed
/// pseudo-random direction derived from the two ids, so that (a) it is reproducible, (b) the
/// normal for (b, a) is exactly the opposite of that for (a, b), and (c) a thousand particles
/// spawned on one point fan out in all directions instead of lining up along one axis.
[[nodiscard]] Normal coincidentNormal(ParticleId a, ParticleId b);

/// Normal components after an impact of restitution e between masses m1, m2 with normal
/// velocity components v1n, v2n (both finite, masses > 0). Written in the original program's
/// form so that with e = 1 it is, operation for operation,
///     v1n' = ((m1 − m2) v1n + 2 m2 v2n) / (m1 + m2)
/// and its mirror for body 2. Momentum is conserved exactly in exact arithmetic for any e, and
/// the normal relative kinetic energy in the centre-of-mass frame is multiplied by e².
struct NormalVelocities {
    double v1n;
    double v2n;
};
[[nodiscard]] inline NormalVelocities collideNormal(double m1, double m2, double v1n, double v2n,
                                                    double e) {
    const double total = m1 + m2;
    return {((m1 - e * m2) * v1n + (1.0 + e) * m2 * v2n) / total,
            ((m2 - e * m1) * v2n + (1.0 + e) * m1 * v1n) / total};
}

/// The limit of collideNormal when body 1 has infinite mass (a kinematic particle or a wall
/// moving at v1n): body 1 is unchanged, body 2 rebounds off it.
[[nodiscard]] inline double collideNormalWithKinematic(double v1n, double v2n, double e) {
    return -e * v2n + (1.0 + e) * v1n;
}

/// The velocity change of one contact between discs i and j along the unit normal n (from i to
/// j), shared by every stepper so that the discrete, substep and exact modes apply the same
/// physics. `w` are inverse masses (0 = kinematic, infinite mass), `m` masses, `e` the
/// restitution and, when kFriction, `mu` the Coulomb coefficient. Only an approaching pair
/// collides: returns false, changing nothing, when the pair already separates (or is at rest
/// relative to each other along n) or both are kinematic.
template <bool kFriction>
inline bool collideDiscs(double& vxi, double& vyi, double& vxj, double& vyj, double wi, double wj,
                         double mi, double mj, Normal n, double e, double mu) {
    if (wi == 0.0 && wj == 0.0) return false;  // two held particles: nothing can give
    const double vni = vxi * n.x + vyi * n.y;
    const double vnj = vxj * n.x + vyj * n.y;
    // A pair that overlaps but already separates was resolved before (or was placed
    // overlapping); swapping its velocities again is what made the original's particles stick.
    if (vnj - vni >= 0.0) return false;

    double ni, nj;  // new normal components
    if (wi == 0.0) {
        ni = vni;
        nj = collideNormalWithKinematic(vni, vnj, e);
    } else if (wj == 0.0) {
        nj = vnj;
        ni = collideNormalWithKinematic(vnj, vni, e);
    } else {
        const NormalVelocities after = collideNormal(mi, mj, vni, vnj, e);
        ni = after.v1n;
        nj = after.v2n;
    }
    const double dvi = ni - vni, dvj = nj - vnj;
    vxi += dvi * n.x;
    vyi += dvi * n.y;
    vxj += dvj * n.x;
    vyj += dvj * n.y;

    if constexpr (kFriction) {
        // Coulomb friction on the tangential relative velocity: the impulse that would stop the
        // sliding, capped at mu times the normal impulse. The discs do not spin, so the sticking
        // limit is equal tangential velocities.
        const double jn = wj > 0.0 ? dvj / wj : -dvi / wi;  // normal impulse on j, >= 0
        const double tx = -n.y, ty = n.x;
        const double vt = (vxj - vxi) * tx + (vyj - vyi) * ty;
        const double limit = mu * jn;
        const double jt = std::clamp(-vt / (wi + wj), -limit, limit);
        vxi -= jt * wi * tx;
        vyi -= jt * wi * ty;
        vxj += jt * wj * tx;
        vyj += jt * wj * ty;
    }
    return true;
}

/// A rebound off a fixed wall: `v` is the velocity component along the wall's outward normal
/// (> 0 means moving into the wall), `vt` the component along the wall. Turns v inward with
/// speed e·|v| and, when kFriction, reduces |vt| by at most mu times the normal velocity change.
/// Returns the normal velocity change per unit mass, >= 0 (0 when v <= 0: nothing to do).
template <bool kFriction>
inline double reboundOffWall(double& v, double& vt, double e, double mu) {
    if (!(v > 0.0)) return 0.0;
    const double dv = (1.0 + e) * v;
    v -= dv;
    if constexpr (kFriction) {
        const double cut = std::min(std::abs(vt), mu * dv);
        vt -= std::copysign(cut, vt);
    }
    return dv;
}

/// A rebound off a fixed surface whose outward unit normal (from the surface to the particle)
/// is n: the walls' law (reboundOffWall) in the frame of n. Returns the normal velocity change
/// per unit mass, >= 0 (0 when the velocity does not point into the surface).
template <bool kFriction>
inline double reboundOffSurface(double& vx, double& vy, double nx, double ny, double e, double mu) {
    double into = -(vx * nx + vy * ny);
    double along = vx * -ny + vy * nx;
    const double dv = reboundOffWall<kFriction>(into, along, e, mu);
    if (dv == 0.0) return 0.0;
    vx = -into * nx + along * -ny;
    vy = -into * ny + along * nx;
    return dv;
}

}  // namespace psb
