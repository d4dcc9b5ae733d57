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

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <particle_sandbox/color.hpp>
#include <particle_sandbox/particle.hpp>

namespace psb::detail {

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
