#pragma once
// The `generate` block of a scene: many particles from a few numbers.
//
// Design. Particles are placed on a square lattice whose spacing is the larger of the
// diameter (plus a part in a million) and the spacing that gives about two sites per particle;
// `count` sites are chosen at random without replacement, and each particle is displaced from
// its site by a random jitter smaller than the lattice's slack. Every particle is therefore
// inside the region and no two overlap, by construction rather than by trial and error, so
// generation never stalls, even near the densest packing a square lattice allows (π/4).
// All randomness comes from one SplitMix64 stream seeded by `seed` and mapped to doubles by
// bit operations, so the same block gives the same particles on every platform (up to the
// libm functions used for the Gaussian and the direction: log, sqrt, cos, sin).

#include <cmath>
#include <cstdint>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <particle_sandbox/color.hpp>
#include <particle_sandbox/particle.hpp>

namespace psb::detail {

/// SplitMix64 (Steele, Lea & Flood 2014): tiny, fast, fully specified, good enough here.
class SplitMix64 {
  public:
    explicit SplitMix64(std::uint64_t seed) : state_(seed) {}
    std::uint64_t next() {
        std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ULL);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
        return z ^ (z >> 31);
    }
    /// Uniform in [0, 1), 53 random bits.
    double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
    /// Uniform integer in [0, n), n > 0 (Lemire's multiply-shift; the bias is below 2^-64·n).
    std::uint64_t below(std::uint64_t n) {
        __extension__ using U128 = unsigned __int128;
        return static_cast<std::uint64_t>((static_cast<U128>(next()) * n) >> 64);
    }
    /// Standard normal by Box–Muller (one of the pair; simplicity over speed).
    double normal() {
        const double u1 = 1.0 - uniform();  // (0, 1]: log stays finite
        const double u2 = uniform();
        return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
    }

  private:
    std::uint64_t state_;
};

/// A validated generate block (see docs/scenes.md for the fields).
struct GenerateSpec {
    std::uint64_t count = 0;    ///< particles to make (already derived from `packing` if given)
    double radius = 1.0;        ///< metres
    double mass = 1.0;          ///< kilograms
    double x0 = 0.0, y0 = 0.0;  ///< region's top-left corner, metres
    double x1 = 1.0, y1 = 1.0;  ///< region's bottom-right corner, metres
    std::optional<double> temperature;  ///< kT, joules: each velocity component ~ N(0, kT/m)
    std::optional<double> speed;        ///< m/s, every particle, random direction
    std::optional<Color> color;         ///< else random channels in 100..255, like the original
    std::uint64_t seed = 1;
};

/// How many particles of `radius` the region's lattice holds at most.
[[nodiscard]] std::uint64_t latticeCapacity(const GenerateSpec& spec);

/// The particles of a block whose count fits (count <= latticeCapacity(spec)).
[[nodiscard]] std::vector<ParticleDef> generateParticles(const GenerateSpec& spec);

}  // namespace psb::detail
