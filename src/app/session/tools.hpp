#pragma once
// What the user works with on the world: the left button's tool, the hand (grab, fling,
// launch; interaction.hpp), the obstacle tools (obstacle_tool.hpp), the selection and its edit
// prompt (edit_prompt.hpp), what new particles are made of, and where the pointer is. Its
// commands are the pointer's and the keys that add, delete, select and edit; the rules of a
// gesture are the hand's and the obstacle tool's, which only read the world and say what the
// user meant, and the handlers here have the document, the world's owner, make the change.

#include <cstddef>
#include <optional>
#include <random>
#include <string>

#include <particle_sandbox/math.hpp>
#include <particle_sandbox/obstacle.hpp>
#include <particle_sandbox/particle.hpp>
#include <particle_sandbox/world.hpp>

#include "session/camera.hpp"
#include "session/command.hpp"
#include "session/edit_prompt.hpp"
#include "session/interaction.hpp"
#include "session/obstacle_tool.hpp"
#include "session/selection.hpp"

namespace psb::app {

struct Document;
class EditReport;
class LabRuler;
class Monitor;
class Notices;
class SceneView;
class SimClock;
class Timeline;
struct UndoState;

/// What launched particles may weigh, kg (the control panel's range).
inline constexpr double kMinLaunchMass = 1e-3;
inline constexpr double kMaxLaunchMass = 1e6;

struct Tools {
    /// What the tools' commands reach beyond them: the world they change (through the
    /// document), the camera and what is shown (the view: where the pointer is in the world,
    /// the Pan tool's drag, the arrows' scale a launch follows, the axes an edit is typed in,
    /// the ruler shown), the ruler under the hand, whether time runs (the clock), the energy
    /// measured from a grab (the monitor).
    struct Context {
        Document& doc;
        SceneView& view;
        LabRuler& ruler;
        const SimClock& clock;
        Monitor& monitor;
        Notices& notices;
        EditReport& edit;
    };
    // The hand and what new particles are made of (tools_hand.cpp).
    void handle(const cmd::PointerDown& c, Context& x);
    void handle(const cmd::PointerMove& c, Context& x);
    void handle(const cmd::PointerUp& c, Context& x);
    void handle(const cmd::PointerLeave& c, Context& x);
    void handle(const cmd::DeleteHeld& c, Context& x);
    void handle(const cmd::DeleteParticle& c, Context& x);
    void handle(const cmd::SetTool& c, Context& x);
    void handle(const cmd::SpawnRandom& c, Context& x);
    void handle(const cmd::ChangeSpawnMass& c, Context& x);
    void handle(const cmd::SetLaunchBody& c, Context& x);
    void handle(const cmd::SetDiscsTurn& c, Context& x);
    // The obstacle tools (tools_obstacles.cpp).
    void handle(const cmd::SetObstacleSizes& c, Context& x);
    void handle(const cmd::RemoveObstacle& c, Context& x);
    // The selection and its edit prompt (tools_edit.cpp).
    void handle(const cmd::Select& c, Context& x);
    void handle(const cmd::OpenEdit& c, Context& x);
    void handle(const cmd::EditType& c, Context& x);
    void handle(const cmd::EditField& c, Context& x);
    void handle(const cmd::EditBackspace& c, Context& x);
    void handle(const cmd::EditApply& c, Context& x);
    void handle(const cmd::EditParticle& c, Context& x);

    /// A new world is in place (a scene opened, an undo): nothing is held, drawn, edited or
    /// selected.
    void startOver() {
        letGo();
        selection.clear();
    }
    /// A scene opened, `world`: new particles and obstacles are made at its scale.
    void followScene(const World& world);
    /// What undo restored of the tools (`state`), as far as `world` still has it.
    void restore(const UndoState& state, const World& world);
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
    /// The hand holds a particle.
    [[nodiscard]] bool holding() const { return hand.mode() == Interaction::Mode::Holding; }
    /// The hand or an obstacle tool took the last press: its gesture is under way.
    [[nodiscard]] bool gestureUnderWay() const {
        return hand.mode() != Interaction::Mode::Idle || obstacle.active();
    }
    /// How the hand turns drags into velocities at `camera`'s zoom in the box `box`.
    [[nodiscard]] static LaunchSettings launchSettings(const Camera& camera, const WorldDef& box);
    /// A launch in progress: the velocity releasing now would give.
    [[nodiscard]] CappedVelocity launchPreview(const Camera& camera, const WorldDef& box,
                                               double arrowSeconds) const;
    /// The obstacle the Peg or Wall tool would make now (a wall being dragged, a peg under the
    /// pointer), for a preview.
    [[nodiscard]] std::optional<Obstacle> obstaclePreview(const Camera& camera,
                                                          const WorldDef& box) const;
    /// The selected particle of `world`, while it exists.
    [[nodiscard]] std::optional<Particle> selected(const World& world) const;
    /// The particle whose trail TrailMode::Selected shows: the selected one, else the one held.
    [[nodiscard]] ParticleId trailParticle(const World& world) const;
    /// Shows the held particle at the hand, through the timeline's setters, so that a past
    /// frame replays the hand's moves.
    void hold(World& world, Timeline& timeline, double now, const Camera& camera) const;
    /// The selected particle is gone from `world`: forget it (and close its edit prompt),
    /// saying so.
    void checkSelection(const World& world, Notices& notices);

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
    /// The pointer is over the window: moved or pressed since it last left (cmd::PointerLeave).
    bool pointerIn = false;

  private:
    /// A click that selects what is under it (a particle, else an obstacle), or clears.
    void click(const ReleaseResult& r, Context& x);
    [[nodiscard]] bool obstacleToolOn() const {
        return tool == cmd::Tool::Peg || tool == cmd::Tool::Wall;
    }
    /// The Peg or Wall tool's press and release: a peg placed, a wall drawn.
    void obstaclePress(Context& x);
    void obstacleRelease(Context& x);
    /// The Select tool's press: on an obstacle (no particle there), starts moving it.
    void obstaclePressToMove(Context& x);
    /// The Select tool's release: true when it moved an obstacle or refused the move, false for
    /// a click (which then selects).
    bool obstacleMoveRelease(Context& x);
    /// A click on empty space: selects the obstacle under the pointer; true if there was one.
    bool selectObstacleAt(Context& x);
    void removeObstacle(std::size_t index, Context& x);
};

}  // namespace psb::app
