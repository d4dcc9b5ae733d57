#pragma once
// The physics of one particle–particle contact: its normal, the velocity change it causes and
// the positional push that removes its overlap.
//
// Two families. collideDiscs / reboundOff* are the contacts of discs that do not turn (no
// friction, or friction on the tangential velocity alone, as before rotation existed); the
// Rough ones add rotation: the tangential impulse acts on the velocities of the contact points,
// v ± ω r, and turns the discs. A stepper picks its family once per step (rotation in use and
// friction on), so that a world without rotation runs exactly the code it ran before.
//
// Rough contact, for discs i, j with unit normal n from i to j and tangent t = (−n_y, n_x):
//
//     vt = (v_j − v_i)·t − ω_j r_j − ω_i r_i          tangential velocity of j's contact
//                                                      point relative to i's
//     W  = w_i (1 + q_i) + w_j (1 + q_j)               q = 1/k (0: fixed rotation), w = 1/m
//     J  = clamp(−(1 + β) vt / W, −μ jn, μ jn)         jn the normal impulse
//     v_i −= J w_i t,  v_j += J w_j t,  ω_i −= J w_i q_i / r_i,  ω_j −= J w_j q_j / r_j
//
// (Δω = −J r / I with I = k m r².) A sticking contact (J below the cap) changes vt into −β vt;
// a fixed surface (wall, peg, segment) is a disc of infinite mass that does not turn. Linear
// momentum and angular momentum about any point (Σ m r × v + I ω) are conserved by each pair
// contact, and kinetic energy (translational plus rotational) does not grow for β <= 1.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

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
/// The normal part of a contact between discs i and j (collideDiscs says what it does): false
/// when the pair does not collide (it separates, or both are kinematic) and nothing changed;
/// else true, with the normal velocity changes of i and j in `dvi`, `dvj`.
inline bool collideDiscsNormal(double& vxi, double& vyi, double& vxj, double& vyj, double wi,
                               double wj, double mi, double mj, Normal n, double e, double& dvi,
                               double& dvj) {
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
    dvi = ni - vni;
    dvj = nj - vnj;
    vxi += dvi * n.x;
    vyi += dvi * n.y;
    vxj += dvj * n.x;
    vyj += dvj * n.y;
    return true;
}

/// The normal impulse on j (>= 0) from the normal velocity changes collideDiscsNormal made.
inline double normalImpulse(double dvi, double dvj, double wi, double wj) {
    return wj > 0.0 ? dvj / wj : -dvi / wi;
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
    double dvi, dvj;
    if (!collideDiscsNormal(vxi, vyi, vxj, vyj, wi, wj, mi, mj, n, e, dvi, dvj)) return false;
    if constexpr (kFriction) {
        const double jn = normalImpulse(dvi, dvj, wi, wj);
        // Coulomb friction on the tangential relative velocity: the impulse that would stop the
        // sliding, capped at mu times the normal impulse. These discs do not turn, so the
        // sticking limit is equal tangential velocities.
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

/// What a rough contact reads and changes of one disc's rotation: its angular velocity (rad/s),
/// radius and spin weight q = 1/k (0 for a disc that never turns: ParticleArrays::spinWeight).
struct Spin {
    double& omega;
    double r;
    double q;
};

/// The material laws of a rough contact: restitution e, friction mu, tangential restitution
/// beta (WorldDef).
struct RoughLaws {
    double e;
    double mu;
    double beta;
};

/// The tangential impulse of a rough contact (the block comment above) given its normal impulse
/// jn >= 0, applied to both discs. `w` are inverse masses (0 = kinematic).
inline void roughTangential(double& vxi, double& vyi, Spin si, double& vxj, double& vyj, Spin sj,
                            double wi, double wj, Normal n, double jn, double mu, double beta) {
    const double tx = -n.y, ty = n.x;
    const double vt = (vxj - vxi) * tx + (vyj - vyi) * ty - sj.omega * sj.r - si.omega * si.r;
    const double weight = wi * (1.0 + si.q) + wj * (1.0 + sj.q);
    // A disc of a mass near the smallest double has no finite 1/(k m): no tangential impulse
    // then (it would be 0 times infinity in its spin).
    if (!(weight <= std::numeric_limits<double>::max())) return;
    const double limit = mu * jn;
    const double jt = std::clamp(-(1.0 + beta) * vt / weight, -limit, limit);
    const double omegaI = si.omega - jt * wi * si.q / si.r;
    const double omegaJ = sj.omega - jt * wj * sj.q / sj.r;
    // A disc so small that its spin (a rim speed over its radius) leaves the doubles gets no
    // tangential impulse, rather than an infinite spin (radii of 1e-300 m, from the fuzzers).
    if (!std::isfinite(omegaI) || !std::isfinite(omegaJ)) return;
    vxi -= jt * wi * tx;
    vyi -= jt * wi * ty;
    vxj += jt * wj * tx;
    vyj += jt * wj * ty;
    si.omega = omegaI;
    sj.omega = omegaJ;
}

/// collideDiscs for turning discs: the same normal impulse, then the rough tangential one.
inline bool collideRoughDiscs(double& vxi, double& vyi, Spin si, double& vxj, double& vyj, Spin sj,
                              double wi, double wj, double mi, double mj, Normal n,
                              const RoughLaws& laws) {
    double dvi, dvj;
    if (!collideDiscsNormal(vxi, vyi, vxj, vyj, wi, wj, mi, mj, n, laws.e, dvi, dvj)) return false;
    roughTangential(vxi, vyi, si, vxj, vyj, sj, wi, wj, n, normalImpulse(dvi, dvj, wi, wj), laws.mu,
                    laws.beta);
    return true;
}

/// The rough tangential impulse of a fixed surface (a disc of infinite mass that does not turn)
/// on a disc touching it, per unit of the disc's mass, on `along`, the disc's velocity component
/// along the surface's tangent t = (−n_y, n_x) (n the outward unit normal, from the surface to
/// the disc). `dv` is the normal velocity change the contact gave (>= 0), which caps the
/// tangential one at mu·dv. For a disc that does not turn (q = 0, ω = 0) and β = 0 it is, bit
/// for bit, the friction of reboundOffWall.
inline void roughAlongSurface(double& along, Spin s, double dv, double mu, double beta) {
    const double slip = along - s.omega * s.r;
    const double limit = mu * dv;
    const double jt = std::clamp(-(1.0 + beta) * slip / (1.0 + s.q), -limit, limit);
    const double omega = s.omega - jt * s.q / s.r;
    if (!std::isfinite(omega)) return;  // as in roughTangential: no spin past the doubles
    along += jt;
    s.omega = omega;
}

/// reboundOffSurface for a turning disc: the walls' law along n, then the rough tangential
/// impulse (roughAlongSurface), in the frame of n as reboundOffSurface works. Returns the normal
/// velocity change per unit mass, >= 0 (0: no contact, nothing changed).
inline double roughReboundOffSurface(double& vx, double& vy, Spin s, double nx, double ny,
                                     const RoughLaws& laws) {
    double into = -(vx * nx + vy * ny);
    double along = vx * -ny + vy * nx;
    const double dv = reboundOffWall<false>(into, along, laws.e, 0.0);
    if (dv == 0.0) return 0.0;
    roughAlongSurface(along, s, dv, laws.mu, laws.beta);
    vx = -into * nx + along * -ny;
    vy = -into * ny + along * nx;
    return dv;
}

}  // namespace psb
