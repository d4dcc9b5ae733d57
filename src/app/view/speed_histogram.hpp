#pragma once
// The speed distribution (the D key): a histogram of particle speeds against the 2-D
// Maxwell–Boltzmann speed density at the gas's current temperature.
//
// In two dimensions a particle of mass m in equilibrium at temperature T has the speed density
// (Rayleigh)  f(v) = (m v / kT) · exp(−m v² / 2kT),  and its mean kinetic energy is kT
// (two quadratic degrees of freedom), so kT is measured as the mean kinetic energy per
// particle. Unequal masses share T, not the speed scale: the expected histogram is then the
// mixture Σ_m (N_m / N) f_m(v) over the distinct masses, which is what is drawn (for equal
// masses it is the single Rayleigh curve).

#include <cstddef>
#include <utility>
#include <vector>

#include <particle_sandbox/particle_arrays.hpp>

namespace psb::app {

/// The 2-D Maxwell–Boltzmann (Rayleigh) speed density for mass `m` (kg) at `kT` (J), s/m.
/// 0 for v < 0 or kT <= 0.
[[nodiscard]] double rayleighDensity(double v, double kT, double m);

/// Speeds binned for display.
struct SpeedHistogram {
    std::vector<std::size_t> counts;  ///< particles per bin
    std::size_t overflow = 0;         ///< particles faster than vmax (not in any bin)
    double vmax = 1.0;                ///< upper end of the last bin, m/s
    double kT = 0.0;                  ///< mean kinetic energy per particle, J
    std::vector<std::pair<double, std::size_t>> masses;  ///< (mass kg, particles), ascending
    std::size_t particles = 0;

    [[nodiscard]] double binWidth() const { return vmax / static_cast<double>(counts.size()); }
    /// The expected density at `v` (s/m): the mixture over `masses` at kT.
    [[nodiscard]] double expectedDensity(double v) const;
};

/// Bins the speeds of `p` into `bins` bins over [0, vmax]: vmax is the fastest particle, but at
/// most twice the 99th percentile speed (one bullet must not squash the gas into the first
/// bin); faster ones count as overflow.
[[nodiscard]] SpeedHistogram speedHistogram(const ParticleArrays& p, std::size_t bins);

}  // namespace psb::app
