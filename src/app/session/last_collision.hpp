#pragma once
// The last collision card's content: the last collision of the selected particle, or with none
// selected the last collision between two particles anywhere, kept until the next one. Fed the
// world's collision records (collision_log.hpp) after each step, so it is the same in every
// mode: the exact mode's instant of contact, the discrete and substep modes' resolved pair.
// What the card shows of it (velocities, momenta, totals, the energy lost) is
// view/collision_card_lines.hpp.

#include <cstdint>
#include <optional>
#include <vector>

#include <particle_sandbox/collision_log.hpp>
#include <particle_sandbox/world.hpp>

namespace psb::app {

/// One collision as the card keeps it: the record, with the masses and numbers the particles
/// had then (a particle may be reweighed or deleted afterwards).
struct CollisionCard {
    Collision collision;
    double massA = 0.0;  ///< kg
    double massB = 0.0;  ///< kg; 0 unless with a particle
    std::uint64_t numberA = 0;
    std::uint64_t numberB = 0;  ///< 0 unless with a particle
    /// With an obstacle: whether it was a peg (else a wall segment).
    bool peg = false;
    /// What it was chosen by: the selected particle's number, 0 for "any pair".
    std::uint64_t follows = 0;

    [[nodiscard]] bool pair() const { return collision.with == Collision::With::Particle; }
    /// Total momentum of the two (or of the one, against a wall or an obstacle), kg m/s.
    [[nodiscard]] Vec2 momentumBefore() const;
    [[nodiscard]] Vec2 momentumAfter() const;
    /// Total kinetic energy, J.
    [[nodiscard]] double energyBefore() const;
    [[nodiscard]] double energyAfter() const;
};

class LastCollision {
  public:
    /// Up to this many particles the card follows the collisions while hidden too, so that J
    /// pressed after a collision shows it (a lesson's few balls); beyond, it listens only while
    /// shown, and a large scene records nothing for a card nobody looks at.
    static constexpr std::size_t kListensHiddenUpTo = 60;
    /// Whether the card follows the collisions: shown, or a world of few particles.
    [[nodiscard]] static bool listening(bool shown, std::size_t particles) {
        return shown || particles <= kListensHiddenUpTo;
    }
    /// Which collisions the world should record for the card (none when not `listening`),
    /// following `selected` (none: every collision, of which the card keeps the pairs).
    [[nodiscard]] static std::optional<CollisionLog> wanted(bool listening,
                                                            std::optional<ParticleId> selected);

    /// The records of a step (any particles'; those the card does not follow are passed over):
    /// the last one it follows becomes the card. `world` is the world after the step.
    void heard(const std::vector<Collision>& records, const World& world,
               std::optional<ParticleId> selected);
    /// The selection changed to `selected`: a card of another particle's collision (or, with
    /// none selected, of a wall's) is cleared; the selected particle is put first.
    void follow(std::optional<ParticleId> selected);
    /// The world's clock is at `time`, a recorded frame shown when `viewing`. Stepping back
    /// through the recorded frames (viewing) keeps the card: its collision is still in the
    /// history shown, a step or two after the frame (the lesson steps to the moment of impact;
    /// the card went, and the panel's layout jumped under the pointer). Gone back before it
    /// otherwise (an undo, carrying on from a past frame), the card never happened yet: it is
    /// put aside, and comes back when the clock passes it again through the same history. A
    /// step of the world (heard) makes a new history and forgets it.
    void dropAfter(double time, bool viewing = false);
    void clear() {
        card_.reset();
        ahead_.reset();
    }

    [[nodiscard]] const std::optional<CollisionCard>& card() const { return card_; }

  private:
    std::optional<CollisionCard> card_;
    std::optional<CollisionCard> ahead_;  ///< the card put aside by a step back
};

}  // namespace psb::app
