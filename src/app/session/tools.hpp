#pragma once
// What the user works with on the world: the left button's tool, the hand (grab, fling,
// launch; interaction.hpp), the obstacle tools, the selection and its edit prompt, what new
// particles are made of, and where the pointer is. The session's handlers use them; they
// change the world only through the session.

#include <cstddef>
#include <optional>
#include <random>
#include <string>

#include <particle_sandbox/math.hpp>

#include "session/camera.hpp"
#include "session/command.hpp"
#include "session/edit_prompt.hpp"
#include "session/interaction.hpp"
#include "session/obstacle_tool.hpp"
#include "session/selection.hpp"

namespace psb::app {

struct Tools {
    /// A new world is in place (a scene opened, an undo): nothing is held, drawn or edited.
    void letGo() {
        hand.reset();
        obstacle.reset();
        selectedObstacle.reset();
        closePrompt();
    }
    void closePrompt() {
        if (prompt.active()) prompt.close();
    }
    /// Where the pointer is in the world seen through `camera`.
    [[nodiscard]] Vec2 pointerWorld(const Camera& camera) const {
        return camera.screenToWorld(pointer);
    }

    cmd::Tool tool = cmd::Tool::Fling;  ///< what the left mouse button does
    Interaction hand;
    /// This drag of a held particle while paused has been told that a fling keeps its speed.
    bool pausedFlingTold = false;
    std::optional<Vec2> panFrom;  ///< the Pan tool's drag, screen pixels
    ObstacleTool obstacle;
    ObstacleSizes obstacleSizes;
    std::optional<std::size_t> selectedObstacle;  ///< by index in the world's obstacles
    Selection selection;
    EditPrompt prompt;
    std::string editRefusal;  ///< why the last EditParticle was refused
    SpawnSettings spawn;
    std::mt19937 rng;             ///< random spawns
    Vec2 pointer = Vec2::Zero();  ///< screen pixels
    double pointerTime = 0.0;     ///< seconds, of the last pointer command
};

}  // namespace psb::app
