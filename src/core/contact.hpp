#pragma once
// The physics of one particle–particle contact: its normal, the velocity change it causes and
// the positional push that removes its overlap.

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

}  // namespace psb
