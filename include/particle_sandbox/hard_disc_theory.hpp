#pragma once
/// \file
/// What theory predicts for a gas of equal hard discs (diameter σ, mass m, number density ρ,
/// packing fraction φ = ρ π σ² / 4, temperature kT): the equation of state and contact value of
/// Henderson, and Enskog's collision rate, mean free path and self-diffusion coefficient. The
/// observables (observables.hpp) report these beside what they measure.
///
///   Henderson (1975)   Z = P A / (N kT) = (1 + φ²/8) / (1 − φ)²
///                      g(σ) = (1 − 7φ/16) / (1 − φ)²   (the contact value Z = 1 + 2 φ g(σ)
///                      gives for it; within about 1 % of simulations up to φ ≈ 0.6)
///   Liu (2021)         Z = (1 + φ²/8 + φ³/18 − 4φ⁴/21) / (1 − φ)²
///                      fitted to simulations of the stable fluid (to φ ≈ 0.70): the reference
///                      the exact mode's periodic gas is held to (within 0.3 % from φ 0.1 to
///                      0.6, docs/observables.md); Henderson's is 1.2 % above it at 0.6
///   Enskog, 2-D        collision rate per particle  ω = 2 σ ρ g(σ) √(π kT / m)
///                      mean free path               ℓ = ⟨|v|⟩ / ω = 1 / (2√2 σ ρ g(σ))
///                      self-diffusion               D = (1 / (2 σ ρ g(σ))) √(kT / (π m))
///
/// ω and ℓ follow from a Maxwell distribution and uncorrelated collisions at contact density
/// ρ g(σ); the simulated hard-disc gas reaches them within about 1 % at moderate density. D is
/// the first Chapman–Enskog approximation (Gass 1971); simulations find D / D_E above 1 at
/// moderate density (correlated motion, the 2-D long-time tail) — it is a reference, not a
/// target.

#include <cmath>
#include <numbers>

namespace psb::hard_discs {

/// Henderson's compressibility factor Z(φ), for 0 ≤ φ < 1.
[[nodiscard]] inline double hendersonZ(double phi) {
    return (1.0 + phi * phi / 8.0) / ((1.0 - phi) * (1.0 - phi));
}

/// Liu's compressibility factor Z(φ) for the stable hard-disc fluid, 0 ≤ φ ≤ kLiuFluidLimit
/// (H. Liu, "Global equation of state and phase transitions of the hard disc systems", Mol.
/// Phys. 119, e1886364 (2021), eq. 1; arXiv:2010.10624).
[[nodiscard]] inline double liuZ(double phi) {
    const double p2 = phi * phi;
    return (1.0 + p2 / 8.0 + p2 * phi / 18.0 - 4.0 * p2 * p2 / 21.0) / ((1.0 - phi) * (1.0 - phi));
}

/// The densest packing fraction of the stable fluid Liu's equation describes (the liquid
/// meets the hexatic phase at about 0.70 to 0.72).
inline constexpr double kLiuFluidLimit = 0.70;

/// Henderson's contact value g(σ) at packing fraction φ, for 0 ≤ φ < 1.
[[nodiscard]] inline double hendersonContact(double phi) {
    return (1.0 - 7.0 * phi / 16.0) / ((1.0 - phi) * (1.0 - phi));
}

/// Enskog's collisions per particle per second: density ρ (1/m²), diameter σ (m), contact
/// value g, kT (J), mass m (kg).
[[nodiscard]] inline double enskogCollisionRate(double rho, double sigma, double g, double kT,
                                                double m) {
    return 2.0 * sigma * rho * g * std::sqrt(std::numbers::pi * kT / m);
}

/// Enskog's mean free path, metres.
[[nodiscard]] inline double enskogMeanFreePath(double rho, double sigma, double g) {
    return 1.0 / (2.0 * std::numbers::sqrt2 * sigma * rho * g);
}

/// Enskog's self-diffusion coefficient, m²/s.
[[nodiscard]] inline double enskogDiffusion(double rho, double sigma, double g, double kT,
                                            double m) {
    return std::sqrt(kT / (std::numbers::pi * m)) / (2.0 * sigma * rho * g);
}

/// Densest packing of equal discs (hexagonal): π / (2√3) = 0.9069.
inline constexpr double kClosePacking = std::numbers::pi / (2.0 * std::numbers::sqrt3);

}  // namespace psb::hard_discs
