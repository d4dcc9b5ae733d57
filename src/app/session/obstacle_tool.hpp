#pragma once
// The tools that build obstacles with the mouse: Peg (a click places a fixed disc at the
// cursor), Wall (a drag draws a segment from the press to the release) and Move (the Select
// tool's drag of an obstacle moves it), and picking an obstacle under the cursor to select it. No
// SDL: points are world metres, the session converts them from the pointer's pixels.
//
// Rules. A peg's centre and a wall's first end (the press) must lie inside the box, or the
// gesture is refused with a notice; a wall's second end is kept to the box (a drag past the
// edge ends the wall on the edge, and the preview shows it there). A wall shorter than
// `minLength` (a click, or a drag of a few pixels) is refused. An obstacle may be drawn over
// particles: the next step pushes them out, as it separates particles placed overlapping. A move
// is a translation by the drag; one that would take any end or centre out of the box is refused,
// and a drag shorter than `minLength` is a click (nothing made, nothing said).

#include <optional>
#include <string>

#include <particle_sandbox/obstacle.hpp>
#include <particle_sandbox/world_def.hpp>

namespace psb::app {

/// The sizes of obstacles the tools make, metres.
struct ObstacleSizes {
    double pegRadius = 1.0;
    double wallThickness = 0.5;  ///< full thickness (twice the segment's radius)
};

/// Sizes at the scale of a scene whose typical particle has radius `typicalRadius`: a peg as
/// big as that particle, a wall half as thick as the particle is wide.
[[nodiscard]] ObstacleSizes obstacleSizesFor(double typicalRadius);

/// What a released gesture made: an obstacle, or why none (a sentence for the notice).
struct ObstaclePlacement {
    std::optional<Obstacle> obstacle;
    std::string refusal;
};

class ObstacleTool {
  public:
    enum class Kind { Peg, Wall, Move };

    /// The left button went down at `point` with tool `kind` (Peg or Wall).
    void press(Kind kind, const Vec2& point);
    /// The left button went down at `point` on `obstacle` (index `index`), to move it.
    void pressOn(std::size_t index, const Obstacle& obstacle, const Vec2& point);
    void moveTo(const Vec2& point);
    /// The button went up at `point`: the obstacle the gesture made in a `box`-sized box, or
    /// why none. Ends the gesture.
    ObstaclePlacement release(const Vec2& point, const ObstacleSizes& sizes, const WorldDef& box,
                              double minLength);
    /// The obstacle releasing now would make (drawn as a preview while dragging a wall), if any.
    [[nodiscard]] std::optional<Obstacle> preview(const ObstacleSizes& sizes,
                                                  const WorldDef& box) const;
    [[nodiscard]] bool active() const { return press_.has_value(); }
    [[nodiscard]] Kind kind() const { return kind_; }
    /// The obstacle being moved, by index (Kind::Move).
    [[nodiscard]] std::size_t movedIndex() const { return movedIndex_; }
    void reset() { press_.reset(); }

  private:
    Kind kind_ = Kind::Peg;
    std::optional<Vec2> press_;
    Vec2 pointer_ = Vec2::Zero();
    std::size_t movedIndex_ = 0;
    Obstacle moved_;  ///< as it was at the press
};

/// Why `sizes` cannot be used in `box` (empty when they can): each size finite, > 0 and at most
/// half the box's smaller side.
[[nodiscard]] std::string obstacleSizesRefusal(const ObstacleSizes& sizes, const WorldDef& box);

/// The distance from `point` to the obstacle's surface (negative inside it), metres.
[[nodiscard]] double distanceToObstacle(const Obstacle& obstacle, const Vec2& point);

/// The obstacle under `point` (within `slop` metres of its surface; the nearest of several), by
/// index in `obstacles`.
[[nodiscard]] std::optional<std::size_t> pickObstacle(const Obstacles& obstacles, const Vec2& point,
                                                      double slop);

/// "peg" or "wall", for messages.
[[nodiscard]] const char* obstacleNoun(const Obstacle& obstacle);

}  // namespace psb::app
