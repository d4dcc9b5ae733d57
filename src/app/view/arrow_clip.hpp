#pragma once
// An arrow kept inside the box: a velocity or momentum arrow drawn to scale may reach past a
// wall (a fast ball near the top wall under the HUD, the lesson's ball by the left wall). Its
// scale stays honest: no single arrow is shortened to fit. It is drawn up to the wall and ends
// there in a bar across it, without a head, so that it reads as cut, not as a shorter arrow.

#include <algorithm>

#include <particle_sandbox/math.hpp>

#include "session/camera.hpp"

namespace psb::app {

/// An arrow after clipping, pixels.
struct ClippedArrow {
    Vec2 tip = Vec2::Zero();  ///< where it ends: its tip, or where it meets the box's edge
    bool cut = false;         ///< it met the edge: drawn with a bar there, no head
};

/// The arrow from `from` to `tip` (pixels) inside `box` (the box's inside on screen,
/// Camera::boxOnScreen): unchanged when its tip is inside, or when `from` is not (a periodic
/// box's image, a particle dragged out); else cut where it leaves the box.
[[nodiscard]] ClippedArrow clipArrow(const Vec2& from, const Vec2& tip,
                                     const Camera::ScreenBox& box);

/// Half the length of the bar across a cut arrow's end, pixels, for an arrow whose shaft is
/// `halfWidth` pixels either side of its line and whose head would be `head` pixels long.
[[nodiscard]] inline double cutBarHalf(double head, double halfWidth) {
    return std::max(0.4 * head, 3.0 * halfWidth);
}

}  // namespace psb::app
