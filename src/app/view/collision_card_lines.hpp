#pragma once
// The last collision card (session/last_collision.hpp) as a person reads it: a title, rows of
// a quantity before and after (signed components with units), and what the collision kept and
// lost. The panel's Last collision section shows it; the text F12 writes beside a screenshot
// lists it.

#include <string>
#include <vector>

#include <particle_sandbox/axes.hpp>

#include "session/last_collision.hpp"

namespace psb::app {

struct CollisionCardText {
    struct Row {
        std::string name;    ///< "v 1", "p 2", "total p", "kinetic energy"
        std::string unit;    ///< "m/s", "kg m/s"; empty when the values carry theirs ("3.50 J")
        std::string before;  ///< "(2.00, 0)"
        std::string after;
        std::string help;  ///< what it is, for a tooltip
    };
    /// "Particles 1 and 2 at t = 1.33 s", "Particle 1 and the right wall at t = 0.40 s".
    std::string title;
    std::vector<Row> rows;
    /// The impulse, the momentum kept, the share of kinetic energy lost.
    std::vector<std::string> notes;
};

/// In `axes` (the y up option).
[[nodiscard]] CollisionCardText collisionCardText(const CollisionCard& card, const Axes& axes = {});

/// Where the frame shown (the world's clock at `shownTime`, s) is before the card's collision
/// (stepped back through the recorded frames to read the moment of impact, where the card
/// stays): "The frame shown is 0.10 s before it"; empty at or after it.
[[nodiscard]] std::string cardAhead(const CollisionCard& card, double shownTime);

/// The card as lines of text ("v 1: (2.00, 0) m/s -> (-2.50, 0) m/s"), for the screenshot's
/// text file.
[[nodiscard]] std::vector<std::string> collisionCardLines(const CollisionCardText& text);

}  // namespace psb::app
