#pragma once
// Times of impact under a constant acceleration (gravity), for the exact mode: a centre crossing
// a wall's limit or a cell face on a parabola, and a disc on a parabola meeting a disc that does
// not fall (a held particle, a particle at rest; later fixed obstacles).
//
// The rules are those of time_of_impact.hpp (durations >= 0 or kNever; an overlapping
// pair that approaches collides now; a centre past a limit and moving outward crosses now),
// with one addition that gravity forces: a pair or a centre that is "left alone" because it
// separates may be turned back by the acceleration, so the search goes on past the separation
// instead of answering never.
//
// Two free particles under the same gravity move on a straight line relative to each other:
// their time of impact is time_of_impact.hpp's quadratic, not something from here.

#include <algorithm>
#include <cmath>
#include <limits>

#include "exact/time_of_impact.hpp"

namespace psb::exact {

/// Time until a coordinate moving as x + v·t + ½·a·t² first crosses `limit` going outward
/// (`outward` = +1 if the limit is at larger coordinates, −1 if at smaller ones).
///
/// In outward terms (gap = distance still to go, u = outward speed, g = outward acceleration)
/// the crossing solves ½·g·t² + u·t − gap = 0. Each root is taken in the form that adds terms of
/// one sign (2·gap / (u + √D) or (√D − u) / g, D = u² + 2·g·gap), so that neither loses digits
/// when g is small or the apex is near. The apex: a centre moving out against the acceleration
/// (g < 0) reaches the limit only if D >= 0; if rounding decides D's sign the centre stops a
/// hair short or a hair past, both of which the callers tolerate (a wall's rule for a centre
/// past it; a cell's skin).
[[nodiscard]] inline double crossingTime(double x, double v, double a, double limit,
                                         double outward) {
    const double gap = outward * (limit - x);
    const double u = outward * v;
    const double g = outward * a;
    if (g == 0.0) {
        if (!(u > 0.0)) return kNever;
        return gap <= 0.0 ? 0.0 : gap / u;
    }
    if (gap <= 0.0) {
        // At or past the limit: moving (or pushed) outward, it crosses now.
        if (u > 0.0 || (u == 0.0 && g > 0.0)) return 0.0;
        if (!(g > 0.0)) return kNever;  // moving inward and never turned back
        // Moving inward, turned back by g: back inside first and out again (the larger root),
        // or, if it never gets back inside, outward again at its turning point.
        const double d = u * u + 2.0 * g * gap;
        if (!(d > 0.0)) return -u / g;
        return (std::sqrt(d) - u) / g;
    }
    const double d = u * u + 2.0 * g * gap;
    if (g > 0.0) {
        // Always gets there: the one positive root.
        const double s = std::sqrt(d);
        return u >= 0.0 ? 2.0 * gap / (u + s) : (s - u) / g;
    }
    // Decelerated: only if it is moving outward fast enough to get there (the smaller root).
    if (!(u > 0.0) || d < 0.0) return kNever;
    return 2.0 * gap / (u + std::sqrt(d));
}

/// Time until a coordinate at x with velocity v and acceleration a leaves the slab [lo, hi)
/// through either face (a particle thrown upwards may fall back through the face it came in
/// by). Writes the face to `face` (+1 = hi, −1 = lo, 0 = never).
[[nodiscard]] inline double slabExitTimeAccelerated(double x, double v, double a, double lo,
                                                    double hi, int& face) {
    const double up = crossingTime(x, v, a, hi, 1.0);
    const double down = crossingTime(x, v, a, lo, -1.0);
    if (up == kNever && down == kNever) {
        face = 0;
        return kNever;
    }
    face = up <= down ? 1 : -1;
    return std::min(up, down);
}

/// Relative acceleration along the contact normal (as the cosine between it and the relative
/// position) below which a touching pair counts as not pressed together: a disc that hovers a
/// few ulps beside another and falls past it is not pushed into it.
inline constexpr double kPressTolerance = 1e-6;

namespace detail {

/// Root of a monotone function on [lo, hi] where f(lo) and f(hi) differ in sign (or one is 0):
/// Newton steps kept inside the bracket, bisection when a step would leave it or stop
/// shrinking it. Returns the end of the final bracket on the side of the sign f has before the
/// root (for a falling f: the last time still outside contact).
template <typename F, typename D>
double bracketedRoot(F f, D df, double lo, double hi) {
    double flo = f(lo);
    if (flo == 0.0) return lo;
    const bool rising = flo < 0.0;
    double t = 0.5 * (lo + hi);
    for (int iter = 0; iter < 200; ++iter) {
        const double ft = f(t);
        if (ft == 0.0) return t;
        if ((ft < 0.0) == rising) {
            lo = t;
        } else {
            hi = t;
        }
        if (!(hi - lo > 4.0 * std::numeric_limits<double>::epsilon() * hi)) break;
        const double slope = df(t);
        double next = slope != 0.0 ? t - ft / slope : lo - 1.0;
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        if (next == t) break;
        t = next;
    }
    return lo;
}

/// The real roots of c0 + c1·t + c2·t² in (lo, hi), ascending; returns how many (0–2).
inline int quadraticRootsIn(double c0, double c1, double c2, double lo, double hi, double out[2]) {
    int n = 0;
    const auto keep = [&](double r) {
        if (r > lo && r < hi) out[n++] = r;
    };
    if (c2 == 0.0) {
        if (c1 != 0.0) keep(-c0 / c1);
        return n;
    }
    const double d = c1 * c1 - 4.0 * c2 * c0;
    if (d < 0.0) return 0;
    const double q = -0.5 * (c1 + std::copysign(std::sqrt(d), c1));
    double r1 = q / c2, r2 = q != 0.0 ? c0 / q : r1;
    if (r1 > r2) std::swap(r1, r2);
    keep(r1);
    if (r2 != r1) keep(r2);
    return n;
}

}  // namespace detail

/// Time until two discs whose relative position moves as p + q·t + ½·a·t² (a != 0: one falls,
/// the other does not) come within `sigma`: the first time f(t) = |p + q·t + ½·a·t²|² − σ²
/// reaches 0 while decreasing, searched in [0, horizon] (kNever beyond).
///
/// f is a quartic. Its first root is found without a closed formula: the roots of f'' (a
/// quadratic) split the interval into pieces where f' is monotone, a bracketed Newton iteration
/// finds f' = 0 in each (f's turning points), and a second one the first crossing of f on the
/// first piece where f falls through 0. Each step works on a bracket, so no root is skipped and
/// none is found twice; the result is the last time still outside contact, to within a few ulps.
///
/// On a piece where f falls: if the pair is already within sigma at its start, the pair is
/// overlapping and approaching there, so that start is the time (0 for "now", as
/// pairImpactTime). A pair touching now (f(0) ≈ 0) that leaves does not collide at 0: its first
/// piece rises.
[[nodiscard]] inline double parabolicPairImpactTime(double px, double py, double qx, double qy,
                                                    double ax, double ay, double sigma,
                                                    double horizon) {
    // f(t) = c0 + c1 t + c2 t² + c3 t³ + c4 t⁴.
    const double c0 = px * px + py * py - sigma * sigma;
    const double c1 = 2.0 * (px * qx + py * qy);
    const double c2 = qx * qx + qy * qy + px * ax + py * ay;
    const double c3 = qx * ax + qy * ay;
    const double c4 = 0.25 * (ax * ax + ay * ay);
    const auto f = [&](double t) { return c0 + t * (c1 + t * (c2 + t * (c3 + t * c4))); };
    const auto df = [&](double t) { return c1 + t * (2.0 * c2 + t * (3.0 * c3 + t * 4.0 * c4)); };
    const auto ddf = [&](double t) { return 2.0 * c2 + t * (6.0 * c3 + t * 12.0 * c4); };

    // A pair touching now and clearly approaching collides now (the rounding of a just-made
    // contact leaves |f'(0)| tiny; the tolerance is pairImpactTime's). One touching now whose
    // relative velocity and acceleration are both, up to tolerances, along the contact (a disc
    // sliding down the side of another) is not pressed into it: left alone while that lasts.
    const double p2 = px * px + py * py, q2 = qx * qx + qy * qy, a2 = ax * ax + ay * ay;
    const bool approaching =
        c1 < 0.0 && c1 * c1 > 4.0 * kApproachTolerance * kApproachTolerance * p2 * q2;
    if (c0 <= 0.0 && approaching) return 0.0;
    // Pressed together by the acceleration at time t (the relative position then against it).
    const auto pressedAt = [&](double t) {
        const double x = px + t * (qx + 0.5 * ax * t), y = py + t * (qy + 0.5 * ay * t);
        const double pa = x * ax + y * ay;
        return pa < 0.0 && pa * pa > kPressTolerance * kPressTolerance * (x * x + y * y) * a2;
    };

    // An acceleration too small to square (below ~1e-154 m/s²) changes nothing a double can
    // see: the straight-line answer.
    if (!(c4 > 0.0)) return pairImpactTime(px, py, qx, qy, sigma);

    // No root beyond a bound of the quartic's roots (Cauchy's, on the monic form).
    double hi = horizon;
    if (!(hi < kNever)) {
        const double m = std::max({std::abs(c0), std::abs(c1), std::abs(c2), std::abs(c3)});
        hi = 1.0 + m / c4;
        if (!std::isfinite(hi)) return kNever;
    }
    if (!(hi > 0.0)) return kNever;

    // Turning points of f' (roots of f''), then of f (roots of f').
    double bends[2];
    const int nb = detail::quadraticRootsIn(2.0 * c2, 6.0 * c3, 12.0 * c4, 0.0, hi, bends);
    double knots[4] = {0.0};
    int nk = 1;
    for (int k = 0; k <= nb; ++k)
        knots[nk++] = k < nb ? bends[k] : hi;
    double turns[5];
    int nt = 0;
    turns[nt++] = 0.0;
    for (int k = 0; k + 1 < nk; ++k) {
        const double a = knots[k], b = knots[k + 1];
        const double fa = df(a), fb = df(b);
        if ((fa < 0.0 && fb > 0.0) || (fa > 0.0 && fb < 0.0)) {
            turns[nt++] = detail::bracketedRoot(df, ddf, a, b);
        }
    }
    turns[nt++] = hi;

    // Touching to rounding: |f| within a few ulps of σ². A pair that starts so, neither clearly
    // approaching nor pressed together, grazes: left alone until it is clearly apart (f above
    // the band) or clearly inside (f below it).
    const double band = 64.0 * std::numeric_limits<double>::epsilon() * sigma * sigma;
    bool touching = c0 <= band;
    for (int k = 0; k + 1 < nt; ++k) {
        const double a = turns[k], b = turns[k + 1];
        if (!(b > a)) continue;
        const double fa = f(a), fb = f(b);
        if (!(df(0.5 * (a + b)) < 0.0)) {  // rising on this piece
            if (fb > band) touching = false;
            continue;
        }
        if (touching && fa <= band) {
            // Starts to approach while touching: a collision if the acceleration presses the
            // pair together there; otherwise a graze, unless it goes clearly inside.
            if (pressedAt(a)) return a;
            if (!(fb < -band)) continue;
            return detail::bracketedRoot([&](double t) { return f(t) + band; }, df, a, b);
        }
        touching = false;
        if (fa <= 0.0) return a;  // overlapping and approaching there
        if (fb > 0.0) continue;
        return detail::bracketedRoot(f, df, a, b);
    }
    return kNever;
}

}  // namespace psb::exact
