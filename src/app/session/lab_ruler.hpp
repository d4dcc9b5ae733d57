#pragma once
// The ruler a student measures the box with (the Show section's Ruler, key Q): a straight edge
// between two ends in the world's metres, each end dragged with the left button, the whole
// ruler dragged by its edge. It reads its length, its run and rise (Δx, Δy) and its angle from
// the horizontal, so it also measures a ramp's slope. It is an instrument, not part of the
// scene: it is not saved and not undone; a scene opened puts it back across the middle of the
// new box, at that box's scale. A restart, a revert or an undo keeps its reading (a student
// measures, then runs the experiment again), unless the box they bring back is of another size.

#include <optional>

#include <particle_sandbox/math.hpp>

namespace psb::app {

class Camera;

/// Degrees from the horizontal of a line along `d`, 0 to 90 whichever way it points: a ramp's
/// slope (0 for a zero vector).
[[nodiscard]] double slopeDegrees(const Vec2& d);

class LabRuler {
  public:
    /// How near the pointer must be, pixels, to take an end (or the edge) of the ruler.
    static constexpr double kGrabPixels = 10.0;
    enum class Part { EndA, EndB, Edge };

    /// Across the middle of a `width` × `height` box (metres), half its width long.
    void place(double width, double height);
    /// Where it is, when the box is still the `width` × `height` one it was placed in; across
    /// the middle of the box (place) when the box is of another size.
    void keepIn(double width, double height);

    /// The part of the ruler under screen point `screen`, ends first, or none.
    [[nodiscard]] std::optional<Part> partAt(const Vec2& screen, const Camera& camera) const;
    /// Takes `part` at world point `at`; moveTo moves it there, keeping the grab's offset.
    void take(Part part, const Vec2& at);
    void moveTo(const Vec2& at);
    void letGo() { held_.reset(); }
    [[nodiscard]] bool held() const { return held_.has_value(); }

    [[nodiscard]] const Vec2& a() const { return a_; }
    [[nodiscard]] const Vec2& b() const { return b_; }
    /// Metres from a to b.
    [[nodiscard]] double length() const { return (b_ - a_).norm(); }
    /// Degrees from the horizontal, 0 to 90: the slope of a ramp it is laid along, whichever
    /// way it points.
    [[nodiscard]] double slopeDegrees() const { return psb::app::slopeDegrees(b_ - a_); }

  private:
    Vec2 a_{0.0, 0.0}, b_{1.0, 0.0};
    Vec2 box_{0.0, 0.0};  ///< the box it was placed in, m (none yet: zero)
    std::optional<Part> held_;
    Vec2 grabOffset_{0.0, 0.0};  ///< the held point minus the pointer (the edge: minus a_)
};

}  // namespace psb::app
