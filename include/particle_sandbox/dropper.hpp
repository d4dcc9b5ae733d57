#pragma once
/// \file
/// Ball droppers: a spout that releases balls one at a time, like the funnel of a teaching
/// Galton board. A world steps its droppers in the "drop" stage, first in every step.

#include <cstdint>
#include <vector>

#include <particle_sandbox/color.hpp>
#include <particle_sandbox/math.hpp>

namespace psb {

/// A spout that drops `balls` balls, one every `interval` seconds, each a new particle.
///
/// A ball is released at the start of the step nearest to the time it is due, at `position`
/// moved along x by an offset in [-spread, +spread] (seeded: the same dropper always gives the
/// same offsets, ball by ball), with `velocity`. If that spot is not clear (a particle overlaps
/// the new ball) the dropper waits, trying again at every step, and the next ball is then due
/// one interval after the late one was released. A dropper releases at most one ball per step.
///
/// Both what the dropper is and where it has got to are here, so that a copy of a world (an
/// undo state, a saved scene) continues exactly where the original was.
struct Dropper {
    Vec2 position = Vec2::Zero();  ///< where a ball's centre starts, metres
    std::uint64_t balls = 0;       ///< balls still to drop
    double interval = 0.1;         ///< seconds between balls, finite and > 0
    double radius = 0.0025;        ///< each ball's radius, metres, finite and > 0
    double mass = 0.002;           ///< each ball's mass, kg, finite and > 0
    Color color{};                 ///< each ball's colour
    Vec2 velocity = Vec2::Zero();  ///< each ball's velocity when released, m/s
    double spread = 0.0;           ///< release points lie within +-spread of position.x, m, >= 0
    std::uint64_t seed = 1;        ///< picks the offsets within the spread
    std::uint64_t released = 0;    ///< balls dropped so far (which offset comes next)
    double nextIn = 0.0;           ///< seconds until the next ball is due (<= 0: due now)

    /// Where the next ball starts: position.x plus its offset within the spread.
    [[nodiscard]] Vec2 nextPosition() const;

    friend bool operator==(const Dropper&, const Dropper&) = default;
};

using Droppers = std::vector<Dropper>;

/// Largest number of droppers a world holds, and of balls one dropper may still drop.
inline constexpr std::size_t kMaxDroppers = 1'000;
inline constexpr std::uint64_t kMaxDropperBalls = 1'000'000;

}  // namespace psb
