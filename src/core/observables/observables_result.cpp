// The observables window's result (observables.hpp): every value a function of a chunk, taken of
// the window's total; its error the standard error of the same function over the full chunks.

#include <algorithm>
#include <cmath>
#include <numbers>

#include <particle_sandbox/hard_disc_theory.hpp>
#include <particle_sandbox/observables.hpp>

#include "observables/window_state.hpp"

namespace psb {

namespace {

using observables::Chunk;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// The value of `f` over the whole window, and the standard error of its block values.
template <typename F>
Measured measure(const Chunk& total, const std::vector<const Chunk*>& blocks, int minBlocks,
                 F&& f) {
    Measured m;
    m.value = f(total);
    if (!std::isfinite(m.value)) {
        m.value = kNaN;
        return m;
    }
    std::vector<double> values;
    for (const Chunk* c : blocks) {
        const double v = f(*c);
        if (std::isfinite(v)) values.push_back(v);
    }
    if (static_cast<int>(values.size()) < minBlocks) return m;
    double mean = 0.0;
    for (const double v : values)
        mean += v;
    mean /= static_cast<double>(values.size());
    double spread = 0.0;
    for (const double v : values)
        spread += (v - mean) * (v - mean);
    const auto b = static_cast<double>(values.size());
    m.error = std::sqrt(spread / (b * (b - 1.0)));
    return m;
}

/// Einstein's D: the least-squares slope of the MSD over lags [maxLag/2, maxLag], over 4.
double diffusionFromMsd(const Chunk& c, double dt, std::uint32_t maxLag) {
    if (c.msd.size() < maxLag + 1u || maxLag < 2) return kNaN;
    double st = 0, sm = 0, stt = 0, stm = 0, count = 0;
    for (std::uint32_t k = maxLag / 2; k <= maxLag; ++k) {
        if (!(c.lagCount[k] > 0.0)) return kNaN;
        const double t = k * dt, m = c.msd[k] / c.lagCount[k];
        st += t;
        sm += m;
        stt += t * t;
        stm += t * m;
        count += 1.0;
    }
    const double slope = (count * stm - st * sm) / (count * stt - st * st);
    return slope / 4.0;
}

/// Green–Kubo's D(t) = ½ ∫₀ᵗ C, averaged over t in [maxLag/2, maxLag] like the MSD's slope.
double diffusionFromVacf(const Chunk& c, double dt, std::uint32_t maxLag) {
    if (c.vacf.size() < maxLag + 1u || maxLag < 2) return kNaN;
    double integral = 0.0, sum = 0.0, count = 0.0;
    for (std::uint32_t k = 0; k <= maxLag; ++k) {
        if (!(c.lagCount[k] > 0.0)) return kNaN;
        const double v = c.vacf[k] / c.lagCount[k];
        if (k > 0) integral += 0.5 * dt * (v + c.vacf[k - 1] / c.lagCount[k - 1]);
        if (k >= maxLag / 2) {
            sum += 0.5 * integral;
            count += 1.0;
        }
    }
    return sum / count;
}

}  // namespace

ObservablesResult ObservablesWindow::result() const {
    ObservablesResult r;
    if (!state_) return r;
    const State& s = *state_;
    r.notes = s.notes;
    const Chunk total = s.chunks.total();
    const auto n = static_cast<double>(s.n);
    r.particles = s.n;
    r.duration = total.time;
    r.samples = s.samples;
    r.stateSamples = s.stateSamples;
    // The centres' box: a radius in from each wall, or all of a periodic box (no walls).
    const double inset = s.periodic ? 0.0 : 2.0 * s.meanRadius;
    const double a = std::max(0.0, s.width - inset);
    const double b = std::max(0.0, s.height - inset);
    r.area = a * b;
    r.perimeter = s.periodic ? 0.0 : 2.0 * (a + b);
    r.density = r.area > 0.0 ? n / r.area : kNaN;
    r.packingFraction = s.coveredArea / (s.width * s.height);
    if (s.equalDiscs) {
        r.sigma = s.sigma;
        r.mass = s.mass;
    }

    // The full chunks are the blocks.
    std::vector<const Chunk*> blocks;
    for (const Chunk& c : s.chunks.all()) {
        if (c.intervals == s.chunks.span()) blocks.push_back(&c);
    }
    r.blocks = static_cast<int>(blocks.size());
    r.blockDuration = blocks.empty() ? 0.0 : blocks.front()->time;
    if (r.blocks < kMinBlocks) {
        r.notes.push_back("the window is too short for errors: " + std::to_string(r.blocks) +
                          " full blocks of samples, errors need " + std::to_string(kMinBlocks) +
                          " (" + std::to_string(2 * kMinBlocks) + " samples at least)");
    }
    const auto measured = [&](auto&& f) { return measure(total, blocks, kMinBlocks, f); };

    // The mean kinetic energy (in the centre of mass's frame where momentum is conserved) and
    // kT, its share per pair of degrees of freedom.
    const auto kinetic = [&](const Chunk& c) {
        return c.states > 0 ? c.kinetic / static_cast<double>(c.states) : kNaN;
    };
    const auto kT = [&](const Chunk& c) { return kinetic(c) / s.freedom; };
    r.temperature = measured(kT);
    if (s.turning > 0) {
        r.rotationalTemperature = measured([&](const Chunk& c) {
            return c.states > 0
                       ? 2.0 * c.rotational /
                             (static_cast<double>(c.states) * static_cast<double>(s.turning))
                       : kNaN;
        });
    }
    const double kTall = kT(total), kineticAll = kinetic(total);
    // A block without a state sample takes the window's temperature.
    const auto kTof = [&](const Chunk& c) { return c.states > 0 ? kT(c) : kTall; };
    const auto kineticOf = [&](const Chunk& c) { return c.states > 0 ? kinetic(c) : kineticAll; };
    const bool pressures = !s.gravity && r.area > 0.0 && total.time > 0.0;
    if (!pressures) {
        r.notes.push_back(s.gravity ? "no pressure under gravity (the walls carry the weight too)"
                                    : "no pressure: no time measured, or no room in the box");
    } else {
        // P A = K + Σ r·J / 2T: the kinetic part is the kinetic energy itself (N kT with walls;
        // (N − 1) kT in a periodic box, whose centre of mass carries no pressure).
        const auto virial = [&](const Chunk& c) {
            return c.time > 0.0 ? (kineticOf(c) + c.virial / (2.0 * c.time)) / r.area : kNaN;
        };
        if (s.obstacles) {
            r.notes.push_back(
                "no virial pressure with fixed obstacles: only pair collisions are "
                "counted in the virial");
        } else {
            r.pressureVirial = measured(virial);
            // Z = 1 + Σ r·J / (2T N kT): the ideal part 1, the excess from the collisions. With
            // walls that is P A / (N kT); in a periodic box P A / (N kT) is 1/N less, the
            // momentum constraint's share and not the fluid's, which the equations of state
            // (the thermodynamic limit's) do not have.
            r.compressibilityFactor = measured([&](const Chunk& c) {
                return c.time > 0.0 ? 1.0 + c.virial / (2.0 * c.time * n * kTof(c)) : kNaN;
            });
        }
        if (s.walls) {
            r.pressureWalls = measured([&](const Chunk& c) {
                return c.time > 0.0 ? c.wallImpulse / (c.time * r.perimeter) : kNaN;
            });
        }
    }
    const auto rate = [&](const Chunk& c) {
        return c.time > 0.0 ? 2.0 * static_cast<double>(c.collisions) / (n * c.time) : kNaN;
    };
    r.collisionRate = measured(rate);
    if (s.walls) {
        r.wallCollisionRate = measured([&](const Chunk& c) {
            return c.time > 0.0 ? static_cast<double>(c.wallCollisions) / c.time : kNaN;
        });
    }
    r.meanFreePath = measured([&](const Chunk& c) {
        return c.states > 0 && rate(c) > 0.0 ? c.speed / static_cast<double>(c.states) / rate(c)
                                             : kNaN;
    });

    if (total.snapshots > 0) {
        const std::vector<double> g = s.pairs.g(total.pairs, total.snapshots, s.n, a, b);
        for (std::size_t k = 0; k < g.size(); ++k) {
            if (!std::isfinite(g[k])) break;
            r.pairR.push_back(s.pairs.binWidth() * (static_cast<double>(k) + 0.5));
            r.pairG.push_back(g[k]);
        }
        if (s.equalDiscs) {
            r.contactValue = measured([&](const Chunk& c) {
                return c.snapshots > 0 ? s.pairs.contactValue(
                                             s.pairs.g(c.pairs, c.snapshots, s.n, a, b), s.sigma)
                                       : kNaN;
            });
        } else {
            r.notes.push_back("no contact value: the discs are not all alike");
        }
    }

    const std::uint32_t lags = s.correlation.maxLag();
    if (lags > 0 && s.stateInterval > 0.0 && total.msd.size() > lags) {
        const double dt = s.stateInterval;
        for (std::uint32_t k = 0; k <= lags; ++k) {
            if (!(total.lagCount[k] > 0.0)) break;
            r.lagTime.push_back(k * dt);
            r.msd.push_back(total.msd[k] / total.lagCount[k]);
            r.vacf.push_back(total.vacf[k] / total.lagCount[k]);
        }
        r.diffusionMsd = measured([&](const Chunk& c) { return diffusionFromMsd(c, dt, lags); });
        r.diffusionVacf = measured([&](const Chunk& c) { return diffusionFromVacf(c, dt, lags); });
        if (r.vacf.size() > 1 && r.vacf[0] > 0.0 && r.vacf[1] / r.vacf[0] < 0.8) {
            r.notes.push_back("the VACF falls by more than 20 % in one lag step (C(Δ)/C(0) = " +
                              std::to_string(r.vacf[1] / r.vacf[0]) +
                              "): D from the VACF's trapezoids is coarse; sample more often");
        }
        if ((r.diffusionMsd.valid() && !r.diffusionMsd.hasError()) ||
            (r.diffusionVacf.valid() && !r.diffusionVacf.hasError())) {
            r.notes.push_back(
                "D has no error: too few blocks span every lag (a block must be "
                "longer than the time between origins); run longer");
        }
        if (total.time < 5.0 * lags * dt) {
            r.notes.push_back(
                "the window is shorter than five times the longest lag: few "
                "independent origins for the MSD and VACF");
        }
    }

    if (s.equalDiscs && std::isfinite(r.temperature.value)) {
        const double phi = r.packingFraction, kTv = r.temperature.value;
        const double rho = n / (s.width * s.height);
        if (phi < 1.0) {
            r.hendersonZ = hard_discs::hendersonZ(phi);
            if (phi <= hard_discs::kLiuFluidLimit) r.liuZ = hard_discs::liuZ(phi);
            r.hendersonContact = hard_discs::hendersonContact(phi);
            r.enskogCollisionRate =
                hard_discs::enskogCollisionRate(rho, s.sigma, r.hendersonContact, kTv, s.mass);
            r.enskogMeanFreePath = hard_discs::enskogMeanFreePath(rho, s.sigma, r.hendersonContact);
            r.enskogDiffusion =
                hard_discs::enskogDiffusion(rho, s.sigma, r.hendersonContact, kTv, s.mass);
        }
    }
    return r;
}

}  // namespace psb
