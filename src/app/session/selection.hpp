#pragma once
// The particle the user clicked, to inspect and edit. It is held by stable id (ParticleId), so
// it survives the storage reordering of large worlds; a particle that is removed is forgotten
// at the next forgetIfGone, and the app clears the selection whenever the world is replaced.

#include <optional>
#include <string>

#include <particle_sandbox/axes.hpp>
#include <particle_sandbox/particle.hpp>
#include <particle_sandbox/world.hpp>

namespace psb::app {

class Selection {
  public:
    void select(ParticleId id) { id_ = id; }
    void clear() { id_.reset(); }
    /// The selected particle's id; nullopt when nothing is selected.
    [[nodiscard]] std::optional<ParticleId> id() const { return id_; }
    /// Forgets the selection when `world` no longer contains it; true when it did so.
    bool forgetIfGone(const World& world);

  private:
    std::optional<ParticleId> id_;
};

/// "[I] Selected particle 3 at [x, y] m with velocity [vx, vy] m/s, mass m kg, radius r m":
/// the line the app logs when a click selects `p` (the number is the id's slot), in `axes`,
/// those the window shows.
[[nodiscard]] std::string selectionLogLine(const Particle& p, const Axes& axes);

}  // namespace psb::app
