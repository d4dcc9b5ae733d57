#pragma once
/// \file
/// Fixed obstacles: pegs (discs) and segments (walls at any angle, with rounded ends).

#include <vector>

#include <particle_sandbox/math.hpp>

namespace psb {

/// A fixed obstacle of infinite mass that never moves. Particles rebound off it with the
/// world's restitution and friction, as off the box walls.
///
/// Both kinds are the set of points within `radius` of a core: a peg's core is the point `a`,
/// a segment's is the line from `a` to `b`, so a segment is a wall of thickness 2·radius with
/// rounded ends (a capsule). World validates every obstacle (see World::setObstacles).
struct Obstacle {
    enum class Kind { Peg, Segment };

    Kind kind = Kind::Peg;
    Vec2 a = Vec2::Zero();  ///< a peg's centre, or a segment's first endpoint, metres
    Vec2 b = Vec2::Zero();  ///< a segment's second endpoint (equal to `a` for a peg), metres
    double radius = 0.0;    ///< a peg's radius, or half a segment's thickness, metres, > 0

    /// A fixed disc of `radius` metres centred at `centre`.
    [[nodiscard]] static Obstacle peg(const Vec2& centre, double radius) {
        return {Kind::Peg, centre, centre, radius};
    }
    /// A wall from `from` to `to`, `thickness` metres thick, with rounded ends.
    [[nodiscard]] static Obstacle segment(const Vec2& from, const Vec2& to, double thickness) {
        return {Kind::Segment, from, to, 0.5 * thickness};
    }
    [[nodiscard]] bool isPeg() const { return kind == Kind::Peg; }
    /// A segment's full thickness, 2·radius.
    [[nodiscard]] double thickness() const { return 2.0 * radius; }
    /// Whether a disc of `discRadius` metres centred at `p` keeps clear of the obstacle
    /// (touching counts as clear).
    [[nodiscard]] bool clears(const Vec2& p, double discRadius) const {
        const Vec2 along = b - a;
        const double length2 = along.squaredNorm();
        double t = length2 > 0.0 ? (p - a).dot(along) / length2 : 0.0;
        t = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
        const double reach = discRadius + radius;
        return (p - (a + t * along)).squaredNorm() >= reach * reach;
    }

    bool operator==(const Obstacle&) const = default;
};

/// The fixed obstacles of a world, in the order they were added (an obstacle's index is its
/// position here).
using Obstacles = std::vector<Obstacle>;

}  // namespace psb
