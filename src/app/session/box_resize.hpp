#pragma once
// The box resized with the particles in it (the Physics section's Squeeze and Expand): each
// centre's coordinates scaled by the box's, kept inside the walls, the velocities unchanged, so
// a gas keeps its temperature while its pressure follows the area. Squeezed, discs that come to
// overlap are pushed apart along the line of their centres (each pair half each way, a few
// passes over a grid of cells) until none overlaps more than it did before; where that does
// not settle (the discs fill too much of the box) the resize is refused.

#include <string>
#include <variant>

#include <particle_sandbox/world.hpp>

namespace psb::app {

/// Passes of pushing overlapping discs apart before a squeeze is refused.
inline constexpr int kSqueezePasses = 50;

/// `world` with its box `width` × `height` metres and its particles moved with it, or why not
/// (a message naming the particle that does not fit, or the overlap left). The box's sides are
/// checked by the caller; a world with obstacles or droppers is the caller's to refuse.
[[nodiscard]] std::variant<World, std::string> resizedBox(const World& world, double width,
                                                          double height);

}  // namespace psb::app
