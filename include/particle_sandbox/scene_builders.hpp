#pragma once
/// \file
/// Scenes built in code from a few numbers: the gases, lattices and rows that the app's
/// benchmark, the benchmarks, the tests and the presets are made of. Each builder returns a
/// Scene (box, laws, default solver, particles), so the caller chooses the step mode and dt and
/// makes the world with makeWorld(). The same arguments always give the same scene.

#include <cstddef>
#include <cstdint>

#include <particle_sandbox/scene.hpp>

namespace psb::scenes {

/// A gas in a square box with walls, e = 1, no gravity, no friction.
struct GasSpec {
    std::size_t count = 1000;
    double radius = 1.0;       ///< metres: every disc's, or the smallest when maxRadius > radius
    double maxRadius = 0.0;    ///< > radius: radii log-uniform in [radius, maxRadius]
    double packing = 0.1;      ///< fraction of the box the discs cover, in (0, π/4]
    double mass = 1.0;         ///< kilograms, of a disc of `radius`; others scale with their area
    double temperature = 1.0;  ///< kT, joules: each velocity component ~ N(0, kT / m)
    std::uint64_t seed = 42;
    Color color{140, 200, 255};
    /// One radius only: centres uniform at random in the box, overlaps allowed (the discrete
    /// mode's first steps push them apart), drawn with std::mt19937_64 — the discrete gas
    /// benchmark's start. Otherwise discs never overlap.
    bool overlapping = false;
};

/// Discs of one radius sit on a jittered square lattice (never overlapping), as a scene's
/// `generate` block places them; mixed radii are placed at random, largest first, without
/// overlaps. Throws InvalidArgument for a count of 0, a non-positive radius or mass, a packing
/// outside (0, kMaxPackingFraction], or discs that cannot be placed: more than the lattice in
/// the box holds (which says how many it holds), or mixed radii that jam (random placement
/// stops near 0.55 for nearly equal radii, and reaches π/4 only for widely spread ones; the
/// error says how far it got, after at most 100000 tries per disc).
[[nodiscard]] Scene gas(const GasSpec& spec);

/// Brownian motion: a gas of `count` light discs at packing `packing` around one heavy disc at
/// the centre, at rest; the same temperature for all. The heavy disc is particle 0 (its trail
/// is the scene's point).
struct BrownianSpec {
    std::size_t count = 2000;
    double lightRadius = 1.0;  ///< metres
    double lightMass = 1.0;    ///< kilograms
    double bigRadius = 10.0;   ///< metres
    double bigMass = 100.0;    ///< kilograms
    double packing = 0.2;      ///< fraction of the area the heavy disc leaves, in (0, π/4]
    double temperature = 1.0;  ///< kT, joules: each velocity component ~ N(0, kT / m)
    std::uint64_t seed = 7;
};

/// Throws InvalidArgument for a count of 0, a non-positive radius, mass or temperature, a
/// packing outside (0, kMaxPackingFraction], or more light discs than the lattice around the
/// heavy one holds.
[[nodiscard]] Scene brownian(const BrownianSpec& spec);

/// A hexagonal lattice of `cols` × `rows` discs of radius `radius` at packing `fraction`, in
/// a box of exactly its size, velocity components N(0, 1) m/s drawn with std::mt19937_64 (a
/// dense, jammed scene: staggered rows need more width than the box has, so the walls clamp
/// the row ends into overlaps).
[[nodiscard]] Scene hexagonalLattice(int cols, int rows, double radius, double fraction,
                                     std::uint64_t seed = 5);

/// Newton's cradle: `balls` discs of radius 1 m touching in a row along y = 0 from x = 0, and
/// a striker `gap` metres before the first moving at `speed` m/s along +x; walls off.
[[nodiscard]] Scene cradle(int balls = 5, double gap = 8.0, double speed = 1.0);

}  // namespace psb::scenes
