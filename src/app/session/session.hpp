#pragma once
// The sandbox without a window: the world, the scene as it was loaded, the presets, the
// camera and view toggles, the hand (grab, fling, launch), the selection and its edit prompt,
// the spawn rules and the clock that steps the world. It knows no SDL and is tested without one.
//
// Everything that changes it is a Command handed to apply(); apply() is the one place where a
// user's intent becomes a change, so keys, the mouse, tests and on-screen controls share it.
// update() is the only other mutator: it advances the world by real time.
//
// Undo (undo_history.hpp). apply() keeps the state before each command that may edit (a
// PointerDown's lasts until its release); a handler that made an edit calls
// userAction("label"), which files that state in the history under the label. Undo and Redo
// restore a state whole (world, scene as loaded, name, selection, new-particle settings, time
// speed, unsaved flag); the clock goes back with the world.
//
// Step back (timeline.hpp). Every step and every move of the held particle goes through the
// timeline, which update() ends with record(); other edits are reported with edited(). While
// paused, StepBack / StepForward / Seek show a recorded frame: the world is then a rebuilt copy
// of that frame, and nothing is recorded. Resuming, or any edit, from there carries on from
// that frame and forgets the frames after it (the edit is undoable; the forgotten frames are
// not restored by undo).
//
// What the session has to say (a mode refused, a file saved) comes out as Notices, which the app
// shows for a few seconds and logs; the session itself keeps no clock of its own.

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include <particle_sandbox/time_series.hpp>
#include <particle_sandbox/world.hpp>

#include "session/accuracy.hpp"
#include "session/box_area.hpp"
#include "session/camera.hpp"
#include "session/command.hpp"
#include "session/edit_prompt.hpp"
#include "session/interaction.hpp"
#include "session/obstacle_tool.hpp"
#include "session/scene_io.hpp"
#include "session/selection.hpp"
#include "session/timeline.hpp"
#include "session/undo_history.hpp"
#include "session/view_options.hpp"

namespace psb::app {

/// Something the session says: shown on screen (`show`) and/or written to the log (`log`).
struct Notice {
    enum class Level { Info, Warning, Error };
    Level level = Level::Info;
    std::string text;
    bool show = true;
    bool log = true;
    /// Non-empty: a newer notice of the same topic replaces this one on screen while it is the
    /// last shown (a slider being dragged says each value without filling the message box).
    std::string topic = {};
};

/// "[I] ", "[W] ", "[E] ": the log's prefix for `level`.
[[nodiscard]] const char* logPrefix(Notice::Level level);

struct SessionOptions {
    std::filesystem::path saveTo = "particle-sandbox-save.json";  ///< where Save writes first
    std::vector<std::filesystem::path> presets;                   ///< what OpenPreset opens
    std::uint32_t seed = 1;                                       ///< random spawns
    std::string sceneDescription;          ///< the first scene's, kept when it is saved
    std::vector<std::size_t> sceneTrails;  ///< the first scene's particles with trails shown
    std::optional<Bins> sceneBins;         ///< the first scene's bins
    bool paused = false;
    bool arrows = true;
    /// The control panel open at the start (folded, a window too narrow for it and the box).
    bool controls = true;
    int viewportWidth = 800;  ///< pixels
    int viewportHeight = 800;
    /// Where the box may go in that window, as the view lays it out (a Resize brings the
    /// layout of each new size).
    WindowLayout layout;
    TimelineSettings timeline;
    UndoSettings undo;
};

/// The recorded past, for a time scrubber: simulated seconds.
struct TimelineView {
    double earliest = 0.0;  ///< the oldest recorded frame
    double latest = 0.0;    ///< the newest (the present)
    double current = 0.0;   ///< the frame shown
    bool viewingPast = false;
    /// latest - current: how far back the frame shown is.
    [[nodiscard]] double secondsBack() const { return latest - current; }
    /// Whether there is a past to go back to.
    [[nodiscard]] bool recorded() const { return latest > earliest; }
    /// The Replay slider's ends, seconds: the recorded span; with nothing recorded (a new
    /// scene, just after an undo) the second before the frame shown, so that the present is at
    /// the right end whatever was recorded, and the handle agrees with the time it is labelled.
    [[nodiscard]] std::pair<double, double> sliderRange() const {
        return recorded() ? std::pair{earliest, latest} : std::pair{current - 1.0, current};
    }
};

/// Real time the world may spend catching up in one update, ms: more, and every frame would
/// fall further behind.
inline constexpr double kStepBudgetMs = 30.0;

// The control panel's ranges.
inline constexpr double kMaxPanelGravity = 1000.0;  ///< m/s²
inline constexpr int kMaxPanelSubsteps = 64;
inline constexpr double kMinLaunchMass = 1e-3;  ///< kg
inline constexpr double kMaxLaunchMass = 1e6;   ///< kg

class Session {
  public:
    static constexpr double kMinTimeScale = 1.0 / 16.0, kMaxTimeScale = 8.0;

    Session(World world, std::string sceneName, SessionOptions options);

    /// Applies one command: the only way anything but time changes the session.
    void apply(const Command& command);
    /// Advances the world by `realSeconds` of real time (times the time speed) in fixed steps
    /// of its dt, spending at most `budgetMs` of wall-clock time (the backlog is then dropped);
    /// `now` is the pointer clock, for the held particle's velocity. While paused only a
    /// requested single step runs.
    void update(double realSeconds, double now, double budgetMs = kStepBudgetMs);

    /// What the session said since the last call.
    [[nodiscard]] std::vector<Notice> takeNotices();
    /// True once after a Screenshot command: the app writes the next frame.
    [[nodiscard]] bool takeScreenshotRequest();

    [[nodiscard]] const World& world() const { return world_; }
    [[nodiscard]] const World& loadedWorld() const { return *loaded_; }
    [[nodiscard]] const std::string& sceneName() const { return sceneName_; }
    /// The bins of the scene as opened (a Galton board's), kept when it is saved.
    [[nodiscard]] const std::optional<Bins>& sceneBins() const { return sceneBins_; }
    /// The bins panel is drawn: the scene has bins and the view shows them.
    [[nodiscard]] bool binsShown() const { return sceneBins_.has_value() && view_.bins; }
    /// Changes whenever the world is replaced (open, preset, reset): views keyed to particles
    /// (trails) start over.
    [[nodiscard]] std::uint64_t sceneGeneration() const { return generation_; }
    [[nodiscard]] const Camera& camera() const { return camera_; }
    [[nodiscard]] const ViewOptions& view() const { return view_; }
    [[nodiscard]] bool helpShown() const { return showHelp_; }
    /// The page of the help shown (H turns the page, and closes it after the last).
    [[nodiscard]] std::size_t helpPage() const { return helpPage_; }
    [[nodiscard]] bool profileShown() const { return showProfile_; }
    /// The control panel is open (else folded to a strip).
    [[nodiscard]] bool controlsShown() const { return showControls_; }
    /// Whether a panel of the side column (plots, histograms, profile) is on.
    [[nodiscard]] bool columnAsked() const;
    /// What the left mouse button does.
    [[nodiscard]] cmd::Tool tool() const { return tool_; }
    /// The sizes of the obstacles the Peg and Wall tools make (at the scene's scale when it
    /// opens; SetObstacleSizes changes them).
    [[nodiscard]] const ObstacleSizes& obstacleSizes() const { return obstacleSizes_; }
    /// The obstacle a click selected (by index in world().obstacles()), while it exists.
    [[nodiscard]] std::optional<std::size_t> selectedObstacle() const { return selectedObstacle_; }
    /// The obstacle the Peg or Wall tool would make now (a wall being dragged, a peg under the
    /// pointer), for a preview.
    [[nodiscard]] std::optional<Obstacle> obstaclePreview() const;
    /// The presets with their names and descriptions, in OpenPreset's order.
    [[nodiscard]] const std::vector<SceneInfo>& presets() const { return presets_; }
    /// Files opened or saved lately, newest first (at most kRecentFiles).
    static constexpr std::size_t kRecentFiles = 5;
    [[nodiscard]] const std::vector<std::filesystem::path>& recentFiles() const { return recent_; }
    /// Why `mode` cannot be used for the world now (empty when it can).
    [[nodiscard]] std::string modeRefusal(StepMode mode) const;
    /// The drag of a slider (a `continues` command) is one user action: how many user actions
    /// there were so far (a counter for tests and the undo history).
    [[nodiscard]] std::uint64_t userActions() const { return userActions_; }
    /// Why the last edit of a particle's value was refused (empty after one was applied, or the
    /// selection changed).
    [[nodiscard]] const std::string& editRefusal() const { return editRefusal_; }
    /// The label of the last user action ("set restitution", "launch", ...).
    [[nodiscard]] const std::string& lastAction() const { return lastAction_; }
    [[nodiscard]] const Interaction& interaction() const { return interaction_; }
    [[nodiscard]] const Selection& selection() const { return selection_; }
    [[nodiscard]] const EditPrompt& prompt() const { return prompt_; }
    [[nodiscard]] const SpawnSettings& spawn() const { return spawn_; }
    [[nodiscard]] const AccuracyMonitor& accuracy() const { return accuracy_; }
    [[nodiscard]] const TimeSeries& series() const { return series_; }
    /// The world's observables as the last update left them (summed once a frame).
    [[nodiscard]] const ObservablesSample& observables() const { return now_; }
    [[nodiscard]] bool paused() const { return paused_; }
    /// Requested simulated seconds per real second.
    [[nodiscard]] double timeScale() const { return timeScale_; }
    /// Simulated seconds per real second the last updates reached (smoothed) while the steps
    /// cannot keep up (a backlog was dropped within the last second); otherwise timeScale(),
    /// which the accumulator then keeps to on average.
    [[nodiscard]] double reachedTimeScale() const {
        return lastNow_ < behindUntil_ ? reached_ : timeScale_;
    }
    /// Wall-clock ms of simulation in the last update.
    [[nodiscard]] double lastStepMs() const { return lastStepMs_; }
    [[nodiscard]] bool running() const { return running_; }
    /// Quit was asked with unsaved changes: the next Back or Quit quits.
    [[nodiscard]] bool quitPending() const { return quitPending_; }
    /// The user changed the world since it was opened or last saved.
    [[nodiscard]] bool unsavedChanges() const { return dirty_; }
    /// The file the last Save wrote (absolute).
    [[nodiscard]] const std::optional<std::filesystem::path>& lastSave() const { return lastSave_; }
    /// Why the last open or save failed ("Save failed: ..."); empty once one succeeds.
    [[nodiscard]] const std::string& fileError() const { return fileError_; }

    /// The selected particle, while it exists.
    [[nodiscard]] std::optional<Particle> selected() const;
    /// The particle whose trail TrailMode::Selected shows: the selected one, else the one held.
    [[nodiscard]] ParticleId trailParticle() const;
    /// How the hand turns drags into velocities at the current zoom and scene.
    [[nodiscard]] LaunchSettings launchSettings() const;
    /// A launch in progress: the velocity releasing now would give.
    [[nodiscard]] CappedVelocity launchPreview() const;
    /// Undo and redo: whether there is one, and the label of the edit it would undo / redo.
    [[nodiscard]] bool canUndo() const { return undo_.canUndo(); }
    [[nodiscard]] bool canRedo() const { return undo_.canRedo(); }
    [[nodiscard]] std::string undoLabel() const { return undo_.undoLabel(); }
    [[nodiscard]] std::string redoLabel() const { return undo_.redoLabel(); }
    [[nodiscard]] const UndoHistory& undoHistory() const { return undo_; }
    /// The recorded past and the frame shown.
    [[nodiscard]] TimelineView timeline() const;
    [[nodiscard]] const Timeline& timelineRecord() const { return timeline_; }

    /// The overlays that are on, for the HUD ("V L:all K D"); empty when none.
    [[nodiscard]] std::string overlayFlags() const;

    /// Replaces the world (a scene opened elsewhere, the benchmark); it becomes the scene as
    /// loaded.
    void setWorld(World world, std::string name);

  private:
    // One function per command family; apply() dispatches.
    void pointerDown(const cmd::PointerDown& c);
    void pointerMove(const cmd::PointerMove& c);
    void pointerUp(const cmd::PointerUp& c);
    void click(const ReleaseResult& r);
    void deleteHeld();
    void deleteParticle(ParticleId id);
    // The obstacle tools (session_obstacles.cpp).
    [[nodiscard]] bool obstacleToolOn() const;
    void obstaclePress();
    void obstacleRelease();
    /// The Select tool's press: on an obstacle (no particle there), starts moving it.
    void obstaclePressToMove();
    /// The Select tool's release: true when it moved an obstacle or refused the move, false for
    /// a click (which then selects).
    bool obstacleMoveRelease();
    /// A click on empty space: selects the obstacle under the pointer; true if there was one.
    bool selectObstacleAt();
    void removeObstacle(std::size_t index);
    void setObstacleSizes(const cmd::SetObstacleSizes& c);
    /// The obstacles changed (added, removed, undone): what depends on them follows.
    void obstaclesChanged();
    void spawnRandom();
    /// A scene that marks particles' trails opens with the first of them selected and its trail
    /// shown; `trails` are indices in the scene's order (the world's before any step).
    void showSceneTrails(const std::vector<std::size_t>& trails);
    void changeSpawnMass(int direction);
    void nextMode();
    void toggleGravity();
    void changeRestitution(int direction);
    void reset();
    void openPreset(int index);
    void openFile(const std::optional<std::filesystem::path>& file);
    void openEdit();
    void applyEdit();
    void closeEdit();
    void save();
    void undoOrRedo(bool redo);
    void stepBack();
    void stepForward();
    /// To the frame at or before `seconds`, or (oneFrameBack) the frame before the one shown.
    void seek(double seconds, bool oneFrameBack = false);
    void toggleHelp();
    void back();
    void quit();
    void fit();
    void resize(const cmd::Resize& c);
    void togglePanel(bool& flag, const char* on, const char* off);
    // The control panel's value commands (session_values.cpp).
    void setRestitution(const cmd::SetRestitution& c);
    void setFriction(const cmd::SetFriction& c);
    void setGravity(const cmd::SetGravity& c);
    void setWalls(const cmd::SetWalls& c);
    void setMode(const cmd::SetMode& c);
    void setTimeScale(double value);
    void setLaunchBody(const cmd::SetLaunchBody& c);
    void editParticle(const cmd::EditParticle& c);
    void select(ParticleId id);
    void setShow(const cmd::SetShow& c);
    void saveAs(const cmd::SaveAs& c);
    void saveTo(const std::filesystem::path& path);
    void rememberFile(const std::filesystem::path& file);

    void stepOnce(double now);
    /// The held particle to the hand, through the timeline's setters.
    void holdParticle(double now);
    /// The selected particle is gone: forget it (and close its edit prompt), saying so.
    void checkSelection();
    /// The user made the edit `what` ("delete particle", "set restitution"): it becomes an
    /// undo entry (the state apply() kept before the command), the energy drift is measured
    /// from here on, and there are unsaved changes. A command that continues the previous one
    /// (a slider still being dragged) passes `continues`: it is part of that action (and of its
    /// undo entry), not a new one.
    void userAction(const char* what, bool continues = false);
    /// Files the state kept before the command under `what` in the undo history (userAction
    /// without the unsaved flag: an opened scene or a reset is what is on disk).
    void remember(const char* what);
    /// Whether `command` may edit the session (then apply() keeps the state before it).
    [[nodiscard]] static bool mayEdit(const Command& command);
    /// The session's state with `world` (world_, or world_ moved out) as its world.
    [[nodiscard]] UndoState snapshot(World world) const;
    /// Puts `state` back (undo / redo).
    void restore(UndoState state);
    /// Viewing a past frame and about to change the world: carry on from that frame.
    void leavePast();
    /// Shows recorded frame `frame` (paused); the latest frame ends the viewing.
    void show(std::int64_t frame);
    /// The hand did not move but the world under it did: the held particle follows the cursor.
    void afterCameraMove();
    void say(std::string text, Notice::Level level = Notice::Level::Info);
    void log(std::string text, Notice::Level level = Notice::Level::Info);
    [[nodiscard]] Vec2 pointerWorld() const { return camera_.screenToWorld(pointer_); }

    SessionOptions options_;
    World world_;
    std::shared_ptr<const World> loaded_;  ///< world_ as it was loaded, for Reset
    std::string sceneName_;
    std::string sceneDescription_;   ///< the scene's as loaded, written back by save()
    std::optional<Bins> sceneBins_;  ///< likewise
    std::uint64_t generation_ = 0;
    std::size_t nextPreset_ = 0;

    Camera camera_;
    bool fitted_ = true;  ///< the view is as Fit left it (a resize fits again)
    /// Where the box may go: the window's layout the app sent last.
    WindowLayout layout_;
    ViewOptions view_;
    bool showHelp_ = false;
    std::size_t helpPage_ = 0;
    bool showProfile_ = false;
    bool showControls_ = true;
    cmd::Tool tool_ = cmd::Tool::Fling;
    std::optional<Vec2> panFrom_;  ///< the Pan tool's drag, screen pixels
    ObstacleTool obstacleTool_;
    ObstacleSizes obstacleSizes_;
    std::optional<std::size_t> selectedObstacle_;
    std::vector<SceneInfo> presets_;
    std::vector<std::filesystem::path> recent_;
    std::string exactRefusal_;  ///< why the exact mode is refused for the world, if it is
    std::uint64_t userActions_ = 0;
    std::string lastAction_;
    std::string editRefusal_;

    Interaction interaction_;
    Selection selection_;
    EditPrompt prompt_;
    SpawnSettings spawn_;
    std::mt19937 rng_;
    Vec2 pointer_ = Vec2::Zero();  ///< screen pixels
    double pointerTime_ = 0.0;     ///< seconds, of the last pointer command

    bool paused_ = false;
    bool stepRequested_ = false;
    double timeScale_ = 1.0;
    double reached_ = 1.0;
    double behindUntil_ = -1.0;  ///< `now` until which the steps count as falling behind
    double lastNow_ = 0.0;       ///< `now` of the last update
    double accumulator_ = 0.0;
    double lastStepMs_ = 0.0;

    bool running_ = true;
    bool quitPending_ = false;
    bool dirty_ = false;
    bool changedSinceMeasure_ = true;  ///< the world changed other than by stepping
    bool screenshotRequested_ = false;
    std::optional<std::filesystem::path> lastSave_;
    std::string fileError_;

    AccuracyMonitor accuracy_;
    /// About 68 s of frames at 60 fps for the plots and the centre of mass path.
    static constexpr std::size_t kSeriesSamples = 4096;
    TimeSeries series_{kSeriesSamples};
    std::uint64_t collisions_ = 0;  ///< since the scene opened, for series_
    ObservablesSample now_;

    UndoHistory undo_;
    std::optional<UndoState> before_;       ///< the state before the command being applied
    std::optional<UndoState> pressBefore_;  ///< before the pointer's press, until its release
    Timeline timeline_;
    std::optional<std::int64_t> viewing_;  ///< the past frame shown, while paused

    std::vector<Notice> notices_;
};

}  // namespace psb::app
