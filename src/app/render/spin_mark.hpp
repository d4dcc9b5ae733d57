#pragma once
// A turning disc's rotation on screen: one quarter of the disc, from its centre to its rim, in
// a colour that stands out from the disc's own (dark on a light disc, light on a dark one), so
// that a student sees a disc roll rather than slide, at any size (a spoke a pixel wide vanishes
// on a small disc; a quarter does not). It turns with the disc: positive angles turn +x toward
// +y, clockwise on the screen (y down), as the world's.
//
// The quarter is two triangles over the same quarter of the circle texture, whose alpha draws
// its arc, added to the discs' own batch right after its disc: the discs and their marks stay
// one draw call, and a disc drawn later covers an earlier disc's mark as it covers the disc.

#include <particle_sandbox/color.hpp>

#include "render/geometry_batch.hpp"

namespace psb::app {

/// Discs smaller than this on screen (radius, pixels) get no mark: it would be a dot.
inline constexpr double kSpinMarkPixels = 3.5;

/// The mark's colour on a disc of colour `disc`: the disc's hue darkened to a third on a light
/// disc, lightened two thirds of the way to white on a dark one.
[[nodiscard]] SDL_Color spinMarkColor(const Color& disc);

/// Adds the mark of a disc centred at (`x`, `y`) pixels, of radius `r` pixels (at least
/// kSpinMarkPixels), turned `angle` radians, to `discs` (drawn over the circle texture): the
/// quarter between the disc's own +x and +y axes turned by `angle` (at angle 0, the quarter
/// right of the centre and below it on screen).
void addSpinMark(GeometryBatch& discs, float x, float y, float r, double angle, const Color& disc);

}  // namespace psb::app
