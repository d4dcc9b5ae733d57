#pragma once
// Times of impact for the exact (event-driven) mode: disc–disc, disc–wall and disc–cell-face.
//
// Every function answers "how long from now", a duration >= 0, or kNever. None ever returns a
// negative time: rounding can leave a pair a hair inside contact or a disc a hair past a wall,
// and the rules below (Bannerman, Strobl, Formella & Pöschel 2014) define what happens there
// instead of letting the sign of a rounding error decide:
//   - a pair that overlaps and approaches collides now (duration 0);
//   - a pair that overlaps and separates, or is at rest relative to each other (up to a relative
//     tolerance far above rounding), is left alone;
//   - a disc past a wall and moving outward hits it now; one moving inward is left alone.

#include <algorithm>
#include <cmath>
#include <limits>

namespace psb::exact {

inline constexpr double kNever = std::numeric_limits<double>::infinity();

/// Relative approach speed (as the cosine between dr and dv) below which a pair counts as not
/// approaching: six orders of magnitude above rounding, and only ever met by a pair sliding
/// past at a right angle, whose closest approach is then its current distance.
inline constexpr double kApproachTolerance = 1e-10;

/// Time until two discs moving in straight lines touch: the smaller root of
/// |dr + t·dv| = sigma, where dr = r_j − r_i and dv = v_j − v_i (metres, m/s) and sigma is the
/// sum of the radii. Approaching pairs only (dr·dv < 0).
///
/// With a = dv·dv, b = dr·dv, c = dr·dr − sigma², the smaller root is (−b − √(b² − ac)) / a.
/// Two cancellations lurk there when the pair is far apart (|dr| >> sigma):
///   - −b − √(…) subtracts two nearly equal numbers. Multiplying by the conjugate gives the
///     same root as c / (−b + √(…)), where both terms are positive and add.
///   - b² − ac is a small difference of two huge products. In 2-D, Lagrange's identity
///     (dr·dv)² + (dr×dv)² = |dr|²|dv|² turns it into a·sigma² − (dr×dv)², which is exact up to
///     the rounding of small terms (it only cancels for a truly grazing approach).
[[nodiscard]] inline double pairImpactTime(double dx, double dy, double dvx, double dvy,
                                           double sigma) {
    const double b = dx * dvx + dy * dvy;
    if (!(b < 0.0)) return kNever;  // separating or relatively at rest: never collides
    const double a = dvx * dvx + dvy * dvy;
    const double r2 = dx * dx + dy * dy;
    // Approaching only if clearly so: b < −kApproachTolerance·|dr|·|dv|. A pair that has just
    // collided with e = 0 leaves touching, at a relative normal speed that is zero up to
    // rounding; its sign is noise, and the collision code (which computes it another way) may
    // disagree with ours. Without the tolerance such a pair is "approaching and touching",
    // collides "now", changes nothing, and is predicted again at the same instant, forever.
    if (b * b <= kApproachTolerance * kApproachTolerance * r2 * a) return kNever;
    const double c = r2 - sigma * sigma;
    if (c <= 0.0) return 0.0;  // overlapping (or touching) and approaching: collide now
    const double cross = dx * dvy - dy * dvx;
    const double disc = a * sigma * sigma - cross * cross;
    if (disc < 0.0) return kNever;  // closest approach wider than sigma: a miss
    return c / (-b + std::sqrt(disc));
}

/// Time until a centre at coordinate x (one axis) moving at v reaches `limit`, the extreme
/// coordinate a wall allows it (the wall's position moved inward by the radius). `outward` is
/// +1 if the wall lies at larger coordinates, −1 if at smaller ones.
[[nodiscard]] inline double wallImpactTime(double x, double v, double limit, double outward) {
    const double speedOut = outward * v;
    if (!(speedOut > 0.0)) return kNever;  // moving along or away from this wall
    const double gap = outward * (limit - x);
    if (gap <= 0.0) return 0.0;  // at or past the wall and moving outward: hit it now
    return gap / speedOut;
}

/// Time until a centre at x with velocity v leaves the slab [lo, hi) through one of its faces.
/// Writes which face (+1 = hi, −1 = lo, 0 = never) to `face`.
[[nodiscard]] inline double slabExitTime(double x, double v, double lo, double hi, int& face) {
    if (v > 0.0) {
        face = 1;
        return std::max(0.0, (hi - x) / v);
    }
    if (v < 0.0) {
        face = -1;
        return std::max(0.0, (lo - x) / v);
    }
    face = 0;
    return kNever;
}

}  // namespace psb::exact
