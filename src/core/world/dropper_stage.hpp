#pragma once
// The drop stage of a step (dropper.hpp) and the checks World makes on droppers.

#include <optional>

#include <particle_sandbox/dropper.hpp>
#include <particle_sandbox/particle.hpp>
#include <particle_sandbox/particle_arrays.hpp>

#include "support/periodic_box.hpp"

namespace psb::detail {

/// Whether the dropper's next ball is due in a step of `dt` seconds starting now (its time is
/// nearer this step's start than the next one's) and it still has one.
[[nodiscard]] bool ballDue(const Dropper& d, double dt);

/// The dropper's next ball, where and as it would be released.
[[nodiscard]] ParticleDef nextBall(const Dropper& d);

/// Whether no particle of `p` overlaps `ball`; in a periodic box (`box` given) measured between
/// nearest images.
[[nodiscard]] bool spotClear(const ParticleArrays& p, const ParticleDef& ball,
                             const periodic::Box* box = nullptr);

/// Advances the dropper's clock over a step of `dt` seconds; `releasedBall` says whether it
/// released a ball at the step's start, `waiting` whether one was due and had no room.
void advanceDropper(Dropper& d, double dt, bool releasedBall, bool waiting);

/// Throws InvalidArgument naming `where`, the dropper by index and the problem for a dropper
/// World cannot run in a box of width × height (walls on or off): non-finite or non-positive
/// values where they must be positive, more than kMaxDropperBalls balls, a ball that does not
/// fit in the box, or release points outside it.
void validateDropper(const Dropper& d, std::size_t index, double width, double height, bool walls,
                     const char* where);
void validateDroppers(const Droppers& droppers, double width, double height, bool walls,
                      const char* where);

}  // namespace psb::detail
