// suggestedObservablesSettings (observables.hpp): sampling chosen from Enskog's predictions.

#include <algorithm>
#include <cmath>
#include <numbers>

#include <particle_sandbox/diagnostics.hpp>
#include <particle_sandbox/hard_disc_theory.hpp>
#include <particle_sandbox/observables.hpp>
#include <particle_sandbox/world.hpp>

namespace psb {

ObservablesSettings suggestedObservablesSettings(const World& world, double sampleInterval,
                                                 bool correlations, bool pairs) {
    ObservablesSettings s;
    const ParticleArrays& p = world.particles();
    const std::size_t n = p.size();
    if (correlations) s.maxLag = 64;
    if (pairs) s.pairEvery = 1;
    if (n < 2 || !(sampleInterval > 0.0)) return s;
    bool equal = true;
    for (std::size_t i = 0; i < n; ++i)
        equal = equal && p.radius[i] == p.radius[0] && p.mass[i] == p.mass[0];
    const double r = p.radius[0], sigma = 2.0 * r, m = p.mass[0];
    const double w = world.def().width - sigma, h = world.def().height - sigma;
    const double kT = kineticEnergy(world) / static_cast<double>(n);
    if (!equal || !(w > 0.0) || !(h > 0.0) || !(kT > 0.0)) return s;
    const double rho = static_cast<double>(n) / (w * h);
    const double phi = rho * std::numbers::pi * sigma * sigma / 4.0;
    if (!(phi < hard_discs::kClosePacking)) return s;
    const double g = hard_discs::hendersonContact(phi);
    const double freeTime = 1.0 / hard_discs::enskogCollisionRate(rho, sigma, g, kT, m);
    const double interval = std::max(sampleInterval, 0.25 * freeTime);
    s.stateEvery = static_cast<std::uint32_t>(
        std::clamp(std::floor(interval / sampleInterval + 1e-9), 1.0, 1e9));
    const double stateInterval = s.stateEvery * sampleInterval;
    if (correlations) {
        // Long enough for the MSD's slope (many free times), short enough that the walls do
        // not bend it: a particle diffuses an eighth of the box in L²/(64 · 4 D).
        const double d = hard_discs::enskogDiffusion(rho, sigma, g, kT, m);
        const double side = std::min(w, h);
        const double longest = std::min(20.0 * freeTime, side * side / (256.0 * d));
        s.maxLag = static_cast<std::uint32_t>(std::clamp(longest / stateInterval, 4.0, 4096.0));
    }
    if (pairs) {
        // An exact step costs about 1.5 µs per particle per free time (a collision and a cell
        // crossing or two); a snapshot about 2 ns per pair, n²/2 pairs: for the snapshots to
        // cost 3 % of that, one every n / 45 free times.
        const double every = static_cast<double>(n) / 45.0 * freeTime / stateInterval;
        s.pairEvery = static_cast<std::uint32_t>(std::clamp(std::round(every), 1.0, 1e9));
    }
    return s;
}

}  // namespace psb
