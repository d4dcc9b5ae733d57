#pragma once
// The sandbox without a window. It knows no SDL and is tested without one. The session is a
// set of parts, one concept each, and the dispatch between them:
//   - the document (document.hpp): the world and its laws, the scene as loaded, its SceneInfo,
//     the files, the dialogs about them and leaving;
//   - the view (scene_view.hpp): the camera, the box fitted into the window, what is shown;
//   - the tools (tools.hpp): the hand, the obstacle tools, the selection and its edit prompt,
//     what new particles are made of;
//   - the clock (sim_clock.hpp): pause, time speed, real time owed;
//   - the history (history.hpp): undo and the recorded frames;
//   - the monitor (monitor.hpp): the accuracy indicators and the plots' time series;
//   - the instruments (instruments.hpp): the recording, the collision card, the stopwatch, the
//     ruler;
//   - data out (data_out.hpp): exports, the clipboard, screenshots and video.
//
// Everything that changes it is a Command handed to apply(), the one place where a user's
// intent becomes a change, so keys, the mouse, tests and on-screen controls share it. apply()
// treats a command as its type's traits say (command.hpp) and hands it to the part that owns
// what it changes: the one part with a handle() for its type, given a Context of the other
// parts it reaches. A command is behaviour where its state lives; the session itself handles
// only Undo and Redo. update() is the only other mutator: it advances the world by real time.
//
// Undo (undo_history.hpp). apply() keeps the state before each command that may edit (a
// press's lasts until its gesture ends: command.hpp, Gesture); a handler that made a change
// reports it with its label (edit_report.hpp), and apply() files that state in the history
// under the label. Undo and Redo restore a state whole (world, scene as loaded, name,
// selection, new-particle settings, time speed, unsaved flag); the clock goes back with the
// world, and every part starts over from it (start_over.hpp).
//
// What the session has to say (a mode refused, a file saved) comes out as notices
// (notices.hpp), which the app shows for a few seconds and logs.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "session/command.hpp"
#include "session/data_out.hpp"
#include "session/document.hpp"
#include "session/edit_report.hpp"
#include "session/history.hpp"
#include "session/instruments.hpp"
#include "session/monitor.hpp"
#include "session/notices.hpp"
#include "session/scene_io.hpp"
#include "session/scene_view.hpp"
#include "session/session_options.hpp"
#include "session/sim_clock.hpp"
#include "session/tools.hpp"

namespace psb::app {

struct StartOver;

/// Real time the world may spend catching up in one update, ms: more, and every frame would
/// fall further behind.
inline constexpr double kStepBudgetMs = 30.0;

class Session {
  public:
    static constexpr double kMinTimeScale = SimClock::kMinScale,
                            kMaxTimeScale = SimClock::kMaxScale;

    Session(World world, SceneInfo meta, SessionOptions options);

    /// Applies one command: the only way anything but time changes the session.
    void apply(const Command& command);
    /// Advances the world by `realSeconds` of real time (times the time speed) in fixed steps
    /// of the scene's dt (meta().dt), spending at most `budgetMs` of wall-clock time (the
    /// backlog is then dropped); `now` is the pointer clock, for the held particle's velocity.
    /// While paused only a requested single step runs.
    void update(double realSeconds, double now, double budgetMs = kStepBudgetMs);

    // What the app takes once: notices, and what the commands asked of it.
    /// What the session said since the last call.
    [[nodiscard]] std::vector<Notice> takeNotices();
    /// True once after a Screenshot command: the app writes the next frame.
    [[nodiscard]] bool takeScreenshotRequest() { return dataOut_.takeScreenshotRequest(); }
    /// The text a CopyTable command put on the clipboard, once: the app hands it to the system.
    [[nodiscard]] std::optional<std::string> takeClipboardText() {
        return dataOut_.takeClipboardText();
    }
    /// The settings of a ToggleVideo command, once: the app starts a recording with them, or
    /// stops the one running.
    [[nodiscard]] std::optional<VideoSettings> takeVideoToggle() {
        return dataOut_.takeVideoToggle();
    }
    /// The video settings last asked for (Ctrl+R records with them).
    [[nodiscard]] const VideoSettings& videoSettings() const { return dataOut_.videoSettings(); }

    // What the parts hold, read-only, for the view, the control panel and the tests.

    // The instruments (instruments.hpp).
    /// The run's series, the recorded trajectories and collisions.
    [[nodiscard]] const DataRecorder& data() const { return instruments_.data; }
    /// The stopwatch on simulated time (lab_stopwatch.hpp).
    [[nodiscard]] const LabStopwatch& stopwatch() const { return instruments_.stopwatch; }
    /// The ruler (lab_ruler.hpp), drawn while view().ruler.
    [[nodiscard]] const LabRuler& ruler() const { return instruments_.ruler; }
    [[nodiscard]] const std::optional<CollisionCard>& lastCollision() const {
        return instruments_.lastCollision.card();
    }

    // Data out (data_out.hpp).
    /// `table` as text with `separator` (what ExportTable writes and CopyTable copies).
    [[nodiscard]] std::string tableText(cmd::DataTable table, csv::Separator separator) const {
        return psb::app::tableText(table, separator, doc_.world, instruments_.data, axes(),
                                   rateWindow());
    }
    /// The folder ExportTable writes a relative name into (absolute).
    [[nodiscard]] std::filesystem::path exportDir() const { return dataOut_.exportDir(); }
    /// The app runs in a web page (SessionOptions::inPage).
    [[nodiscard]] bool inPage() const { return options_.inPage; }
    /// A touch screen is the user's hands (SessionOptions::touch): hints name buttons.
    [[nodiscard]] bool touch() const { return options_.touch; }
    /// The file the last ExportTable wrote (absolute).
    [[nodiscard]] const std::optional<std::filesystem::path>& lastExport() const {
        return dataOut_.lastExport();
    }
    /// Why the last export failed; empty once one succeeds.
    [[nodiscard]] const std::string& exportError() const { return dataOut_.exportError(); }

    // The document (document.hpp).
    [[nodiscard]] const World& world() const { return doc_.world; }
    [[nodiscard]] const World& loadedWorld() const { return *doc_.loaded; }
    /// The scene's name, description and bins.
    [[nodiscard]] const SceneInfo& meta() const { return doc_.meta; }
    /// The bins panel is drawn: the scene has bins and the view shows them.
    [[nodiscard]] bool binsShown() const { return view_.binsShown(doc_.meta); }
    /// Changes whenever the world is replaced (open, preset, reset): views keyed to particles
    /// (trails) start over.
    [[nodiscard]] std::uint64_t sceneGeneration() const { return doc_.generation; }
    /// The presets with their names and descriptions, in OpenPreset's order.
    [[nodiscard]] const std::vector<SceneListing>& presets() const { return presets_; }
    /// Files opened or saved lately, newest first (at most Document::kRecentFiles).
    [[nodiscard]] const std::vector<std::filesystem::path>& recentFiles() const {
        return doc_.recent;
    }
    /// The user changed the world since it was opened or last saved.
    [[nodiscard]] bool unsavedChanges() const { return doc_.dirty; }
    /// The file the scene belongs to, and whether Save writes it without asking.
    [[nodiscard]] const SceneFile& sceneFile() const { return doc_.file; }
    /// Restart's target: the world when Play was last pressed after an edit.
    [[nodiscard]] const World& setupWorld() const { return *doc_.setup; }
    /// What Save As proposes: --save-to, else a free name after the scene's in the save folder.
    [[nodiscard]] std::filesystem::path saveProposal() const { return doc_.saveProposal(options_); }
    /// What the New scene dialog starts from: the box of the scene shown.
    [[nodiscard]] NewSceneSpec newSceneDefaults() const { return doc_.newSceneDefaults(); }
    /// The file the last Save wrote (absolute).
    [[nodiscard]] const std::optional<std::filesystem::path>& lastSave() const {
        return doc_.lastSave;
    }
    /// Why the last open or save failed ("Save failed: ..."); empty once one succeeds.
    [[nodiscard]] const std::string& fileError() const { return doc_.fileError; }

    // The view (scene_view.hpp).
    [[nodiscard]] const Camera& camera() const { return view_.camera(); }
    [[nodiscard]] const ViewOptions& view() const { return view_.options(); }
    /// The axes numbers are shown and typed in (the y up option, the box's height).
    [[nodiscard]] Axes axes() const { return view_.axes(world().def()); }
    [[nodiscard]] bool helpShown() const { return view_.helpShown(); }
    /// The page of the help shown (H turns the page, and closes it after the last).
    [[nodiscard]] std::size_t helpPage() const { return view_.helpPage(); }
    [[nodiscard]] bool profileShown() const { return view_.options().profile; }
    /// The control panel is open (else folded to a strip).
    [[nodiscard]] bool controlsShown() const { return view_.controlsShown(); }
    /// Where the box may go in the window, as the app sent it last.
    [[nodiscard]] const WindowLayout& layout() const { return view_.layout(); }
    /// Whether a panel of the side column (plots, histograms, profile) is on.
    [[nodiscard]] bool columnAsked() const { return view_.columnAsked(doc_.meta); }
    /// The side column's charts are folded so that the box keeps its share (SceneView::fit).
    [[nodiscard]] bool columnFolded() const { return view_.columnFolded(); }
    /// The side column's charts are in a band under the box instead (SceneView::fit).
    [[nodiscard]] bool chartsBelow() const { return view_.chartsBelow(); }
    /// Where the values table docks (I): where it left the box largest when the box was last
    /// fitted (BoxArea).
    [[nodiscard]] const ValuesDock& valuesDock() const { return view_.valuesDock(); }
    /// The overlays that are on, for the HUD ("V L:all K D"); empty when none.
    [[nodiscard]] std::string overlayFlags() const { return view_.overlayFlags(); }

    // The tools (tools.hpp).
    /// What the left mouse button does.
    [[nodiscard]] cmd::Tool tool() const { return tools_.tool; }
    /// The sizes of the obstacles the Peg and Wall tools make (at the scene's scale when it
    /// opens; SetObstacleSizes changes them).
    [[nodiscard]] const ObstacleSizes& obstacleSizes() const { return tools_.obstacleSizes; }
    /// The obstacle a click selected (by index in world().obstacles()), while it exists.
    [[nodiscard]] std::optional<std::size_t> selectedObstacle() const {
        return tools_.selectedObstacle;
    }
    /// The obstacle the Peg or Wall tool would make now (a wall being dragged, a peg under the
    /// pointer), for a preview.
    [[nodiscard]] std::optional<Obstacle> obstaclePreview() const {
        return tools_.obstaclePreview(view_.camera(), doc_.world.def());
    }
    [[nodiscard]] const Interaction& interaction() const { return tools_.hand; }
    [[nodiscard]] const Selection& selection() const { return tools_.selection; }
    [[nodiscard]] const EditPrompt& prompt() const { return tools_.prompt; }
    [[nodiscard]] const SpawnSettings& spawn() const { return tools_.spawn; }
    /// Why the last edit of a particle's value was refused (empty after one was applied, or the
    /// selection changed).
    [[nodiscard]] const std::string& editRefusal() const { return tools_.editRefusal; }
    /// The selected particle, while it exists.
    [[nodiscard]] std::optional<Particle> selected() const { return tools_.selected(doc_.world); }
    /// The particle whose trail TrailMode::Selected shows: the selected one, else the one held.
    [[nodiscard]] ParticleId trailParticle() const { return tools_.trailParticle(doc_.world); }
    /// How the hand turns drags into velocities at the current zoom and scene.
    [[nodiscard]] LaunchSettings launchSettings() const {
        return Tools::launchSettings(view_.camera(), doc_.world.def());
    }
    /// A launch in progress: the velocity releasing now would give.
    [[nodiscard]] CappedVelocity launchPreview() const {
        return tools_.launchPreview(view_.camera(), doc_.world.def(), view_.options().arrowSeconds);
    }

    // The monitor (monitor.hpp).
    [[nodiscard]] const AccuracyMonitor& accuracy() const { return monitor_.accuracy(); }
    [[nodiscard]] const TimeSeries& series() const { return monitor_.series(); }
    /// The window the series' collision rate counts over, s of simulated time (monitor.hpp).
    [[nodiscard]] double rateWindow() const { return Monitor::rateWindow(doc_.meta.dt); }
    /// The world's observables as the last update left them (summed once a frame).
    [[nodiscard]] const ObservablesSample& observables() const { return monitor_.observables(); }
    /// The gas instruments' reading (gas_gauges.hpp), when they apply to the world shown.
    [[nodiscard]] std::optional<GasReading> gasReading() const {
        if (!gasGaugesApply(doc_.world)) return std::nullopt;
        return monitor_.gas().reading(doc_.world);
    }
    /// The pressure plot's points (gas_gauges.hpp), oldest first.
    [[nodiscard]] const std::deque<GasHistoryPoint>& gasHistory() const {
        return monitor_.gas().history();
    }

    // The clock (sim_clock.hpp).
    [[nodiscard]] bool paused() const { return clock_.paused; }
    /// Requested simulated seconds per real second.
    [[nodiscard]] double timeScale() const { return clock_.scale(); }
    /// What the last updates reached (SimClock::reachedScale).
    [[nodiscard]] double reachedTimeScale() const { return clock_.reachedScale(); }
    /// Wall-clock ms of simulation in the last update.
    [[nodiscard]] double lastStepMs() const { return clock_.lastStepMs(); }

    // The history (history.hpp).
    /// The drag of a slider (a `continues` command) is one user action: how many user actions
    /// there were so far (a counter for tests and the undo history).
    [[nodiscard]] std::uint64_t userActions() const { return userActions_; }
    /// The label of the last user action ("set restitution", "launch", ...).
    [[nodiscard]] const std::string& lastAction() const { return lastAction_; }
    /// Undo and redo: whether there is one, and the label of the edit it would undo / redo.
    [[nodiscard]] bool canUndo() const { return history_.undo.canUndo(); }
    [[nodiscard]] bool canRedo() const { return history_.undo.canRedo(); }
    [[nodiscard]] std::string undoLabel() const { return history_.undo.undoLabel(); }
    [[nodiscard]] std::string redoLabel() const { return history_.undo.redoLabel(); }
    [[nodiscard]] const UndoHistory& undoHistory() const { return history_.undo; }
    /// The recorded past and the frame shown.
    [[nodiscard]] TimelineView timeline() const { return history_.view(doc_.world); }
    [[nodiscard]] const Timeline& timelineRecord() const { return history_.timeline; }

    // Dialogs and leaving.
    /// The dialog open (Save As, New scene, the quit question), if any.
    [[nodiscard]] const Dialog& dialog() const { return doc_.dialog; }
    [[nodiscard]] bool running() const { return doc_.running; }

    /// Replaces the world (a scene opened elsewhere, the benchmark); it becomes the scene as
    /// loaded, from `file`.
    void setWorld(World world, SceneInfo meta, SceneFile file = {});

  private:
    /// Hands `c` to the part that owns what it changes (its handle() for the command's type),
    /// with what that part reaches beyond itself.
    template <class C>
    void route(const C& c);
    /// Undo and redo are the session's own: they put back every part's state.
    void handle(const cmd::Undo& c);
    void handle(const cmd::Redo& c);
    void handle(const cmd::SetTouch& c);
    void undoOrRedo(bool redo);
    /// Files what the command's handler reported (edit_report.hpp) in the undo history: the
    /// state apply() kept before the command, under the edit's label. A user action also ends
    /// the viewing of a past frame, counts, measures the energy drift from here and leaves
    /// unsaved changes.
    void file(const EditReport& edit);
    /// The session's state with `world` (the world, or the world moved out) as its world.
    [[nodiscard]] UndoState snapshot(World world) const;
    /// Puts `state` back (undo / redo).
    void restore(UndoState state);
    /// The parts that start over from a world put in place.
    [[nodiscard]] StartOver startOver();
    /// One frame's step; returns the seconds simulated (less than the frame: behind).
    double stepOnce(double now);

    SessionOptions options_;
    Document doc_;
    std::vector<SceneListing> presets_;  ///< the presets described, for the panel
    SceneView view_;
    Tools tools_;
    SimClock clock_;
    History history_;
    Monitor monitor_;
    Instruments instruments_;
    DataOut dataOut_;
    Notices notices_;

    /// What the handler of the command being applied reported, for file().
    EditReport edit_;
    std::uint64_t userActions_ = 0;
    std::string lastAction_;
};

}  // namespace psb::app
