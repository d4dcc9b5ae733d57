#pragma once
/// \file
/// A record of a world's collisions: with whom, when, the velocities before and after, the
/// impulse. Opt-in (World::recordCollisions): a world that records nothing pays nothing.

#include <cstdint>
#include <vector>

#include <particle_sandbox/math.hpp>
#include <particle_sandbox/particle_id.hpp>

namespace psb {

/// The walls of the box, as a wall collision names them (x to the right, y downward).
enum class WallSide : std::uint8_t { Left, Right, Top, Bottom };

/// One resolved collision of particle `a` with another particle, a wall or a fixed obstacle.
///
/// Velocities are signed components in m/s; `impulse` is the impulse the contact gave `a`,
/// N·s: m_a (aAfter − aBefore) for a free particle (for a held particle, which has no finite
/// mass to the contact, minus what it gave `b`). `b`, a particle, received −impulse, so the
/// pair's momentum is conserved.
///
/// When: the exact mode records the instant of contact; the discrete and substep modes the
/// end of the (sub)step in which the contact was resolved (its positions are those after the
/// move). In the discrete and substep modes, what the obstacles stage does to a particle in a
/// step (possibly several contacts, a slide along a face) is one record, naming the last
/// obstacle it rebounded off.
struct Collision {
    enum class With : std::uint8_t { Particle, Wall, Obstacle };
    double time = 0.0;  ///< simulated seconds, on World::time()'s clock
    With with = With::Particle;
    ParticleId a;
    /// The other particle (With::Particle); kNullParticle for a wall or an obstacle.
    ParticleId b;
    /// With::Wall: the WallSide, as a number; With::Obstacle: the obstacle's index in
    /// World::obstacles() at the time; 0 for a pair.
    std::uint32_t where = 0;
    Vec2 aBefore = Vec2::Zero(), aAfter = Vec2::Zero();  ///< m/s
    Vec2 bBefore = Vec2::Zero(), bAfter = Vec2::Zero();  ///< m/s; zero unless With::Particle
    Vec2 impulse = Vec2::Zero();                         ///< N·s, on a

    [[nodiscard]] WallSide wall() const { return static_cast<WallSide>(where); }
    /// Whether `id` took part (as a or b).
    [[nodiscard]] bool involves(ParticleId id) const { return a == id || (!b.isNull() && b == id); }
};

/// The collisions a world records, in the order the steps resolved them, and which particles'
/// collisions it keeps: all, or only those involving one of a chosen set of ids.
class CollisionLog {
  public:
    /// Keeps every collision.
    CollisionLog() = default;
    /// Keeps only the collisions that involve at least one of `ids` (none when empty).
    explicit CollisionLog(std::vector<ParticleId> ids);

    [[nodiscard]] bool keepsAll() const { return all_; }
    /// The chosen ids (sorted), empty when keepsAll().
    [[nodiscard]] const std::vector<ParticleId>& chosen() const { return ids_; }
    /// Whether a collision of `id` is kept.
    [[nodiscard]] bool chosen(ParticleId id) const;

    /// Appends `c` if it involves a chosen particle (the steppers call this).
    void add(const Collision& c);
    /// Appends every record of `more` (already chosen), in order.
    void append(const std::vector<Collision>& more);

    [[nodiscard]] const std::vector<Collision>& records() const { return records_; }
    /// The records kept so far, leaving the log empty (and still choosing the same ids).
    [[nodiscard]] std::vector<Collision> take();
    void clear() { records_.clear(); }

  private:
    bool all_ = true;
    std::vector<ParticleId> ids_;  ///< sorted by (slot, generation)
    std::vector<Collision> records_;
};

}  // namespace psb
