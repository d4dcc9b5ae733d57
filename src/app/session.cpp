#include "session.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <type_traits>

#include <particle_sandbox/diagnostics.hpp>
#include <particle_sandbox/scene.hpp>

#include "clock.hpp"
#include "physics_controls.hpp"
#include "scene_io.hpp"
#include "units.hpp"

namespace psb::app {

namespace {

std::string fmt(const char* format, double a, double b) {
    char buf[128];
    std::snprintf(buf, sizeof buf, format, a, b);
    return buf;
}

/// The control panel's commands: the mouse sends them, so the edit prompt (which takes the
/// keyboard) does not hold them back.
template <class T>
constexpr bool isPanelCommand() {
    return std::is_same_v<T, cmd::SetRestitution> || std::is_same_v<T, cmd::SetFriction> ||
           std::is_same_v<T, cmd::SetGravity> || std::is_same_v<T, cmd::SetWalls> ||
           std::is_same_v<T, cmd::SetMode> || std::is_same_v<T, cmd::SetTimeScale> ||
           std::is_same_v<T, cmd::SetTool> || std::is_same_v<T, cmd::SetLaunchBody> ||
           std::is_same_v<T, cmd::EditParticle> || std::is_same_v<T, cmd::DeleteParticle> ||
           std::is_same_v<T, cmd::Select> || std::is_same_v<T, cmd::SetShow> ||
           std::is_same_v<T, cmd::SetTrails> || std::is_same_v<T, cmd::ToggleControls> ||
           std::is_same_v<T, cmd::SaveAs> || std::is_same_v<T, cmd::SetObstacleSizes> ||
           std::is_same_v<T, cmd::RemoveObstacle>;
}

/// A stepping speed (simulated per real second) for the HUD and messages: "x2", "x0.25".
std::string speedText(double s) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "x%g", s);
    return buf;
}

}  // namespace

const char* logPrefix(Notice::Level level) {
    switch (level) {
        case Notice::Level::Warning:
            return "[W] ";
        case Notice::Level::Error:
            return "[E] ";
        case Notice::Level::Info:
            break;
    }
    return "[I] ";
}

Session::Session(World world, std::string sceneName, SessionOptions options)
    : options_(std::move(options)),
      paused_(options_.paused),
      undo_(options_.undo),
      timeline_(options_.timeline) {
    rng_.seed(options_.seed);
    view_.arrows = options_.arrows;
    showControls_ = options_.controls;
    camera_.setViewport(options_.viewportWidth, options_.viewportHeight);
    sceneDescription_ = options_.sceneDescription;
    sceneBins_ = options_.sceneBins;
    for (const auto& file : options_.presets)
        presets_.push_back(describeScene(file));
    setWorld(std::move(world), std::move(sceneName));
    showSceneTrails(options_.sceneTrails);
    if (!showControls_) say("The control panel is folded in this narrow window: C or >> opens it");
}

void Session::setWorld(World world, std::string name) {
    interaction_.reset();
    selection_.clear();
    closeEdit();
    loaded_ = std::make_shared<const World>(world);
    world_ = std::move(world);
    viewing_.reset();
    pressBefore_.reset();
    timeline_ = Timeline(options_.timeline);  // a new scene starts a new record
    sceneName_ = std::move(name);
    ++generation_;
    view_.arrowSeconds = arrowSecondsFor(world_);
    followScene(spawn_, world_);
    obstacleTool_.reset();
    selectedObstacle_.reset();
    obstacleSizes_ = obstacleSizesFor(spawn_.typicalRadius);
    accumulator_ = 0.0;
    series_.clear();
    collisions_ = 0;
    now_ = sampleObservables(world_);
    dirty_ = false;
    quitPending_ = false;
    changedSinceMeasure_ = true;
    fit();
    // The last scene's figures (its deepest overlap) say nothing about this one.
    accuracy_ = AccuracyMonitor{};
    accuracy_.resetReference(monitoredEnergy(world_));
    exactRefusal_ = exactModeRefusal(world_);
}

std::vector<Notice> Session::takeNotices() {
    std::vector<Notice> out;
    out.swap(notices_);
    return out;
}

bool Session::takeScreenshotRequest() {
    const bool r = screenshotRequested_;
    screenshotRequested_ = false;
    return r;
}

void Session::say(std::string text, Notice::Level level) {
    notices_.push_back({level, std::move(text), true, true});
}

void Session::log(std::string text, Notice::Level level) {
    notices_.push_back({level, std::move(text), false, true});
}

void Session::userAction(const char* what, bool continues) {
    leavePast();
    if (!continues || lastAction_ != what) {
        ++userActions_;
        lastAction_ = what;
    }
    remember(what);
    accuracy_.resetReference(monitoredEnergy(world_));
    dirty_ = true;
    changedSinceMeasure_ = true;
    timeline_.edited();
}

void Session::remember(const char* what) {
    if (!before_) return;  // already filed (one command, one entry)
    undo_.record(what, lastNow_, std::move(*before_));
    before_.reset();
}

bool Session::mayEdit(const Command& command) {
    return std::visit(
        [](const auto& c) {
            using T = std::decay_t<decltype(c)>;
            // A slider still being dragged continues the edit its first command began (and
            // filed): nothing new to keep.
            if constexpr (std::is_same_v<T, cmd::SetRestitution> ||
                          std::is_same_v<T, cmd::SetFriction> ||
                          std::is_same_v<T, cmd::SetGravity>) {
                return !c.continues;
            }
            // Commands that look, move the view, steer the prompt, step or leave: never an
            // edit. Anything else may be (a new command is, until listed here).
            return !(std::is_same_v<T, cmd::PointerMove> || std::is_same_v<T, cmd::PointerUp> ||
                     std::is_same_v<T, cmd::Pan> || std::is_same_v<T, cmd::Zoom> ||
                     std::is_same_v<T, cmd::Fit> || std::is_same_v<T, cmd::Resize> ||
                     std::is_same_v<T, cmd::ToggleArrows> || std::is_same_v<T, cmd::ToggleLabels> ||
                     std::is_same_v<T, cmd::ToggleHelp> || std::is_same_v<T, cmd::ToggleProfile> ||
                     std::is_same_v<T, cmd::ToggleMomentum> ||
                     std::is_same_v<T, cmd::CycleTrails> || std::is_same_v<T, cmd::TogglePlots> ||
                     std::is_same_v<T, cmd::ToggleSpeeds> || std::is_same_v<T, cmd::TogglePause> ||
                     std::is_same_v<T, cmd::SingleStep> || std::is_same_v<T, cmd::StepBack> ||
                     std::is_same_v<T, cmd::StepForward> || std::is_same_v<T, cmd::Seek> ||
                     std::is_same_v<T, cmd::SeekBy> || std::is_same_v<T, cmd::Undo> ||
                     std::is_same_v<T, cmd::Redo> || std::is_same_v<T, cmd::OpenEdit> ||
                     std::is_same_v<T, cmd::EditType> || std::is_same_v<T, cmd::EditField> ||
                     std::is_same_v<T, cmd::EditBackspace> || std::is_same_v<T, cmd::Save> ||
                     std::is_same_v<T, cmd::Screenshot> || std::is_same_v<T, cmd::Back> ||
                     std::is_same_v<T, cmd::Quit> || std::is_same_v<T, cmd::SetTool> ||
                     std::is_same_v<T, cmd::Select> || std::is_same_v<T, cmd::SetShow> ||
                     std::is_same_v<T, cmd::SetTrails> || std::is_same_v<T, cmd::ToggleControls> ||
                     std::is_same_v<T, cmd::SaveAs> || std::is_same_v<T, cmd::SetObstacleSizes>);
        },
        command);
}

UndoState Session::snapshot(World world) const {
    UndoState s{std::move(world),  loaded_,
                sceneName_,        sceneDescription_,
                sceneBins_,        selection_.id().value_or(kNullParticle),
                selectedObstacle_, spawn_,
                timeScale_,        dirty_};
    // A particle in the hand is kinematic only while held: restored, it is free again.
    if (interaction_.mode() == Interaction::Mode::Holding &&
        s.world.contains(interaction_.held())) {
        s.world.setKinematic(interaction_.held(), false);
    }
    return s;
}

void Session::restore(UndoState state) {
    interaction_.reset();
    obstacleTool_.reset();
    selectedObstacle_.reset();
    pressBefore_.reset();
    closeEdit();
    const bool otherScene = state.loaded != loaded_;
    world_ = std::move(state.world);
    loaded_ = std::move(state.loaded);
    sceneName_ = std::move(state.sceneName);
    sceneDescription_ = std::move(state.sceneDescription);
    sceneBins_ = std::move(state.sceneBins);
    spawn_ = state.spawn;
    timeScale_ = reached_ = state.timeScale;
    dirty_ = state.dirty;
    selection_.clear();
    if (!state.selection.isNull() && world_.contains(state.selection)) {
        selection_.select(state.selection);
    }
    if (state.selectedObstacle && *state.selectedObstacle < world_.obstacles().size()) {
        selectedObstacle_ = state.selectedObstacle;
    }
    ++generation_;  // views keyed to particles (trails) start over
    // The recorded frames belong to the state undone: the record starts again from here.
    viewing_.reset();
    timeline_ = Timeline(options_.timeline);
    accumulator_ = 0.0;
    quitPending_ = false;
    changedSinceMeasure_ = true;
    now_ = sampleObservables(world_);
    accuracy_ = AccuracyMonitor{};
    accuracy_.resetReference(monitoredEnergy(world_));
    exactRefusal_ = exactModeRefusal(world_);  // the obstacles may differ
    if (otherScene) {
        view_.arrowSeconds = arrowSecondsFor(world_);
        series_.clear();
        collisions_ = 0;
        if (fitted_) fit();
    }
}

void Session::afterCameraMove() {
    fitted_ = false;
    if (interaction_.mode() != Interaction::Mode::Idle) {
        interaction_.moveTo(pointerWorld(), pointerTime_);
    }
}

LaunchSettings Session::launchSettings() const {
    LaunchSettings s;
    s.window = 0.1;
    // A hand that moved less than 4 pixels in the last 100 ms was holding still.
    s.minDistance = camera_.toWorld(4.0);
    s.maxSpeed = maxLaunchSpeed(world_.def());
    return s;
}

CappedVelocity Session::launchPreview() const {
    if (interaction_.mode() != Interaction::Mode::Launching) return {};
    return interaction_.launchVelocityNow(launchSettings(), view_.arrowSeconds);
}

std::optional<Particle> Session::selected() const {
    if (const auto id = selection_.id(); id && world_.contains(*id)) return world_.get(*id);
    return std::nullopt;
}

ParticleId Session::trailParticle() const {
    if (const auto id = selection_.id(); id && world_.contains(*id)) return *id;
    return interaction_.mode() == Interaction::Mode::Holding ? interaction_.held() : kNullParticle;
}

std::string Session::overlayFlags() const {
    std::string f;
    const auto add = [&f](const std::string& s) { f += (f.empty() ? "" : " ") + s; };
    if (view_.momentum) add("V");
    if (view_.trails != TrailMode::Off) add(std::string("L:") + toString(view_.trails));
    if (view_.plots) add("K");
    if (view_.speeds) add("D");
    return f;
}

// ---------------------------------------------------------------------------------------------
// The one place commands are applied.

void Session::apply(const Command& command) {
    // A pending quit question is answered by the next Back or Quit; anything else cancels it.
    const bool answersQuit =
        std::holds_alternative<cmd::Back>(command) || std::holds_alternative<cmd::Quit>(command);
    const bool passive = std::holds_alternative<cmd::PointerMove>(command) ||
                         std::holds_alternative<cmd::Resize>(command);
    if (quitPending_ && !answersQuit && !passive) {
        quitPending_ = false;
        say("Quit cancelled");
    }
    // While the edit prompt is open it takes the keyboard: only its own commands, the pointer,
    // the view's geometry, a screenshot and leaving reach the session.
    if (prompt_.active()) {
        const bool allowed = std::visit(
            [](const auto& c) {
                using T = std::decay_t<decltype(c)>;
                return std::is_same_v<T, cmd::EditType> || std::is_same_v<T, cmd::EditField> ||
                       std::is_same_v<T, cmd::EditBackspace> || std::is_same_v<T, cmd::EditApply> ||
                       std::is_same_v<T, cmd::Back> || std::is_same_v<T, cmd::Quit> ||
                       std::is_same_v<T, cmd::Screenshot> || std::is_same_v<T, cmd::Resize> ||
                       std::is_same_v<T, cmd::PointerDown> || std::is_same_v<T, cmd::PointerMove> ||
                       std::is_same_v<T, cmd::PointerUp> || std::is_same_v<T, cmd::Zoom> ||
                       std::is_same_v<T, cmd::Pan> || isPanelCommand<T>();
            },
            command);
        if (!allowed) return;
    }
    // The state before an edit, for the undo history.
    const bool edits = mayEdit(command);
    before_.reset();
    // A press keeps the state before it until its release or the deletion of what it holds:
    // the gesture (grab, drag, fling or delete) is one edit.
    if (std::holds_alternative<cmd::PointerUp>(command) ||
        (std::holds_alternative<cmd::DeleteHeld>(command) &&
         interaction_.mode() == Interaction::Mode::Holding)) {
        before_ = std::move(pressBefore_);
        pressBefore_.reset();
    } else if (edits) {
        before_ = snapshot(world_);
    }
    std::visit(
        [this](const auto& c) {
            using T = std::decay_t<decltype(c)>;
            if constexpr (std::is_same_v<T, cmd::PointerDown>) {
                pointerDown(c);
            } else if constexpr (std::is_same_v<T, cmd::PointerMove>) {
                pointerMove(c);
            } else if constexpr (std::is_same_v<T, cmd::PointerUp>) {
                pointerUp(c);
            } else if constexpr (std::is_same_v<T, cmd::DeleteHeld>) {
                deleteHeld();
            } else if constexpr (std::is_same_v<T, cmd::Pan>) {
                camera_.panPixels(c.pixels);
                camera_.keepNear(world_.def().width, world_.def().height);
                afterCameraMove();
            } else if constexpr (std::is_same_v<T, cmd::Zoom>) {
                camera_.zoomAbout(c.screen, c.factor);
                char buf[96];
                std::snprintf(buf, sizeof buf, "Zoom %.4f px/m about [%.0f, %.0f]", camera_.zoom(),
                              c.screen.x(), c.screen.y());
                log(buf);
                afterCameraMove();
            } else if constexpr (std::is_same_v<T, cmd::Fit>) {
                fit();
                afterCameraMove();
                fitted_ = true;
            } else if constexpr (std::is_same_v<T, cmd::Resize>) {
                resize(c.width, c.height);
            } else if constexpr (std::is_same_v<T, cmd::ToggleArrows>) {
                view_.arrows = !view_.arrows;
                say(view_.arrows ? "Arrows on" : "Arrows off");
            } else if constexpr (std::is_same_v<T, cmd::ToggleLabels>) {
                view_.labels = !view_.labels;
                say(view_.labels ? "Labels on" : "Labels off");
            } else if constexpr (std::is_same_v<T, cmd::ToggleHelp>) {
                toggleHelp();
            } else if constexpr (std::is_same_v<T, cmd::ToggleProfile>) {
                togglePanel(showProfile_, "Profile on", "Profile off");
            } else if constexpr (std::is_same_v<T, cmd::ToggleMomentum>) {
                view_.momentum = !view_.momentum;
                say(view_.momentum ? "Momentum view on" : "Momentum view off");
            } else if constexpr (std::is_same_v<T, cmd::CycleTrails>) {
                view_.trails = nextTrailMode(view_.trails);
                say(std::string("Trails: ") + toString(view_.trails));
            } else if constexpr (std::is_same_v<T, cmd::TogglePlots>) {
                togglePanel(view_.plots, "Plots on", "Plots off");
            } else if constexpr (std::is_same_v<T, cmd::ToggleSpeeds>) {
                togglePanel(view_.speeds, "Speed distribution on", "Speed distribution off");
            } else if constexpr (std::is_same_v<T, cmd::TogglePause>) {
                if (paused_ && viewing_) {
                    const double t = world_.time();
                    leavePast();
                    say(fmt("Resumed from %.2f s: the later frames are forgotten", t, 0.0));
                } else {
                    say(!paused_ ? "Paused" : "Resumed");
                }
                paused_ = !paused_;
                accumulator_ = 0.0;
            } else if constexpr (std::is_same_v<T, cmd::SingleStep>) {
                if (viewing_) {
                    stepForward();
                } else if (paused_) {
                    stepRequested_ = true;
                }
            } else if constexpr (std::is_same_v<T, cmd::StepBack>) {
                stepBack();
            } else if constexpr (std::is_same_v<T, cmd::StepForward>) {
                stepForward();
            } else if constexpr (std::is_same_v<T, cmd::Seek>) {
                seek(c.seconds);
            } else if constexpr (std::is_same_v<T, cmd::SeekBy>) {
                seek(timeline().current + c.seconds);
            } else if constexpr (std::is_same_v<T, cmd::Undo>) {
                undoOrRedo(false);
            } else if constexpr (std::is_same_v<T, cmd::Redo>) {
                undoOrRedo(true);
            } else if constexpr (std::is_same_v<T, cmd::ScaleTime>) {
                const double before = timeScale_;
                setTimeScale(timeScale_ * c.factor);
                if (timeScale_ != before) remember("set time speed");
            } else if constexpr (std::is_same_v<T, cmd::SpawnRandom>) {
                spawnRandom();
            } else if constexpr (std::is_same_v<T, cmd::ChangeSpawnMass>) {
                changeSpawnMass(c.direction);
            } else if constexpr (std::is_same_v<T, cmd::ChangeRestitution>) {
                changeRestitution(c.direction);
            } else if constexpr (std::is_same_v<T, cmd::ToggleGravity>) {
                toggleGravity();
            } else if constexpr (std::is_same_v<T, cmd::NextMode>) {
                nextMode();
            } else if constexpr (std::is_same_v<T, cmd::Reset>) {
                reset();
            } else if constexpr (std::is_same_v<T, cmd::OpenPreset>) {
                openPreset(c.index);
            } else if constexpr (std::is_same_v<T, cmd::OpenFile>) {
                openFile(c.file);
            } else if constexpr (std::is_same_v<T, cmd::OpenEdit>) {
                openEdit();
            } else if constexpr (std::is_same_v<T, cmd::EditType>) {
                prompt_.type(c.text);
            } else if constexpr (std::is_same_v<T, cmd::EditField>) {
                if (c.back) {
                    prompt_.previousField();
                } else {
                    prompt_.nextField();
                }
            } else if constexpr (std::is_same_v<T, cmd::EditBackspace>) {
                prompt_.backspace();
            } else if constexpr (std::is_same_v<T, cmd::EditApply>) {
                applyEdit();
            } else if constexpr (std::is_same_v<T, cmd::Save>) {
                save();
            } else if constexpr (std::is_same_v<T, cmd::Screenshot>) {
                screenshotRequested_ = true;
            } else if constexpr (std::is_same_v<T, cmd::Back>) {
                back();
            } else if constexpr (std::is_same_v<T, cmd::Quit>) {
                quit();
            } else if constexpr (std::is_same_v<T, cmd::SetRestitution>) {
                setRestitution(c);
            } else if constexpr (std::is_same_v<T, cmd::SetFriction>) {
                setFriction(c);
            } else if constexpr (std::is_same_v<T, cmd::SetGravity>) {
                setGravity(c);
            } else if constexpr (std::is_same_v<T, cmd::SetWalls>) {
                setWalls(c);
            } else if constexpr (std::is_same_v<T, cmd::SetMode>) {
                setMode(c);
            } else if constexpr (std::is_same_v<T, cmd::SetTimeScale>) {
                const double before = timeScale_;
                setTimeScale(c.value);
                if (timeScale_ != before) remember("set time speed");
            } else if constexpr (std::is_same_v<T, cmd::SetTool>) {
                tool_ = c.toggle && tool_ == c.tool ? cmd::Tool::Fling : c.tool;
                panFrom_.reset();
                obstacleTool_.reset();
                static const char* const kTools[] = {
                    "Left mouse: fling particles, launch on empty space",
                    "Left mouse: launch new particles",
                    "Left mouse: select particles and obstacles",
                    "Left mouse: move the view",
                    "Left mouse: a click places a peg",
                    "Left mouse: a drag draws a wall"};
                say(kTools[static_cast<int>(tool_)]);
            } else if constexpr (std::is_same_v<T, cmd::SetLaunchBody>) {
                setLaunchBody(c);
            } else if constexpr (std::is_same_v<T, cmd::EditParticle>) {
                editParticle(c);
            } else if constexpr (std::is_same_v<T, cmd::DeleteParticle>) {
                deleteParticle(c.id);
            } else if constexpr (std::is_same_v<T, cmd::Select>) {
                select(c.id);
            } else if constexpr (std::is_same_v<T, cmd::SetShow>) {
                setShow(c);
            } else if constexpr (std::is_same_v<T, cmd::SetTrails>) {
                view_.trails = static_cast<TrailMode>(std::clamp(c.mode, 0, 2));
            } else if constexpr (std::is_same_v<T, cmd::ToggleControls>) {
                showControls_ = !showControls_;
                if (fitted_) fit();
            } else if constexpr (std::is_same_v<T, cmd::SaveAs>) {
                saveAs(c);
            } else if constexpr (std::is_same_v<T, cmd::SetObstacleSizes>) {
                setObstacleSizes(c);
            } else if constexpr (std::is_same_v<T, cmd::RemoveObstacle>) {
                removeObstacle(c.index);
            } else {
                static_assert(sizeof(T) == 0, "a command without a handler");
            }
        },
        command);
    if (std::holds_alternative<cmd::PointerDown>(command) &&
        (interaction_.mode() != Interaction::Mode::Idle || obstacleTool_.active())) {
        pressBefore_ = std::move(before_);
    }
    before_.reset();
    // Whatever changed the world other than the timeline's setters makes its frame a keyframe
    // (a press and a release set a particle kinematic and free).
    if (edits || std::holds_alternative<cmd::PointerUp>(command)) timeline_.edited();
}

// ---------------------------------------------------------------------------------------------
// The hand.

void Session::pointerDown(const cmd::PointerDown& c) {
    pointer_ = c.screen;
    pointerTime_ = c.time;
    if (tool_ == cmd::Tool::Pan) {
        panFrom_ = c.screen;
        return;
    }
    if (tool_ == cmd::Tool::Select) {
        obstaclePressToMove();  // on an obstacle: a drag moves it
        return;                 // the release selects
    }
    if (obstacleToolOn()) {
        obstaclePress();
        return;
    }
    interaction_.press(world_, pointerWorld(), c.time, tool_ == cmd::Tool::Fling);
    if (interaction_.mode() == Interaction::Mode::Holding) {
        const Particle p = world_.get(interaction_.held());
        log(fmt("Grabbed particle at [%.2f, %.2f]", p.position.x(), p.position.y()));
        // The energy is measured from the grab; a click that only selects changes nothing.
        accuracy_.resetReference(monitoredEnergy(world_));
    }
}

void Session::pointerMove(const cmd::PointerMove& c) {
    if (panFrom_) {
        camera_.panPixels(c.screen - *panFrom_);
        camera_.keepNear(world_.def().width, world_.def().height);
        panFrom_ = c.screen;
        fitted_ = false;
    }
    pointer_ = c.screen;
    pointerTime_ = c.time;
    obstacleTool_.moveTo(pointerWorld());
    interaction_.moveTo(pointerWorld(), c.time);
}

void Session::pointerUp(const cmd::PointerUp& c) {
    pointer_ = c.screen;
    pointerTime_ = c.time;
    if (tool_ == cmd::Tool::Pan) {
        panFrom_.reset();
        return;
    }
    if (tool_ == cmd::Tool::Select) {
        if (obstacleMoveRelease()) return;  // moved, or the move refused; else a click
        ReleaseResult r;
        r.kind = ReleaseResult::Kind::Clicked;
        if (const auto id = world_.pick(pointerWorld())) r.id = *id;
        click(r);
        return;
    }
    if (obstacleToolOn()) {
        obstacleRelease();
        return;
    }
    const ReleaseResult r = interaction_.release(world_, pointerWorld(), c.time, spawn_,
                                                 launchSettings(), view_.arrowSeconds);
    using K = ReleaseResult::Kind;
    const std::string at = fmt("at [%.2f, %.2f]", r.position.x(), r.position.y());
    const std::string v = fmt("with velocity [%.2f, %.2f] m/s", r.velocity.x(), r.velocity.y());
    if (r.kind == K::Flung) log("Released particle " + at + " " + v);
    if (r.kind == K::Launched) log("Launched particle " + at + " " + v);
    if ((r.kind == K::Flung || r.kind == K::Launched) && r.capped) {
        say(fmt("Speed capped at %.3g m/s (%g box widths per second)", r.velocity.norm(),
                kMaxLaunchBoxesPerSecond));
    }
    if (r.kind == K::Refused) say(r.message);
    if (r.kind == K::Clicked) click(r);
    if (r.kind == K::Flung) userAction("fling particle");
    if (r.kind == K::Launched) userAction("launch particle");
}

void Session::click(const ReleaseResult& r) {
    if (!r.id.isNull()) {
        if (prompt_.target() != r.id) closeEdit();
        selectedObstacle_.reset();
        selection_.select(r.id);
        std::string line = selectionLogLine(world_.get(r.id));
        log(line.substr(4));  // without its "[I] "
    } else if (selectObstacleAt()) {
        selection_.clear();
        closeEdit();
    } else if (selection_.id() || selectedObstacle_) {
        selection_.clear();
        selectedObstacle_.reset();
        closeEdit();
        say("Selection cleared");
    }
}

void Session::deleteHeld() {
    if (const auto p = interaction_.deleteHeld(world_)) {
        log(deletionLogLine(*p).substr(4));
        notices_.push_back({Notice::Level::Info, "Deleted a particle", true, false});
        userAction("delete particle");
        checkSelection();
    } else if (selectedObstacle_) {
        removeObstacle(*selectedObstacle_);
    }
}

void Session::deleteParticle(ParticleId id) {
    if (!world_.contains(id)) return;
    if (interaction_.mode() != Interaction::Mode::Idle && interaction_.held() == id) {
        interaction_.reset();
    }
    const Particle p = world_.get(id);
    world_.remove(id);
    log(deletionLogLine(p).substr(4));
    notices_.push_back({Notice::Level::Info, "Deleted a particle", true, false});
    userAction("delete particle");
    checkSelection();
}

void Session::checkSelection() {
    if (selection_.forgetIfGone(world_)) {
        closeEdit();
        say("Selection cleared: the particle was deleted");
    }
}

// ---------------------------------------------------------------------------------------------
// The world.

void Session::spawnRandom() {
    const WorldDef& d = world_.def();
    // The original: mass a random integer 3..20 kg with its radius, 2.5 cm per kg at its scale of
    // 1 px = 1 cm (here 0.3..2 times the scene's typical particle), somewhere in the upper part
    // of the box, colour channels 100..255, velocity components up to 5 px per frame at 60
    // frames per second (3 m/s), scaled with the box.
    std::uniform_int_distribution<int> sizeDist(3, 20), channel(100, 255);
    const double size = sizeDist(rng_) / 10.0;
    const double mass = size * spawn_.typicalMass, radius = size * spawn_.typicalRadius;
    std::uniform_real_distribution<double> x(radius, std::max(radius, d.width - radius));
    std::uniform_real_distribution<double> y(radius, std::max(radius, d.height / 2.0));
    const double vmax = 3.0 * std::min(d.width, d.height) / 7.0;
    std::uniform_real_distribution<double> v(-vmax, vmax);
    const Vec2 want(x(rng_), y(rng_));
    const auto spot = findFreeSpot(world_, want, radius);
    if (!spot) {
        say("No room for a new particle");
        return;
    }
    ParticleDef def;
    def.position = *spot;
    def.velocity = {v(rng_), v(rng_)};
    def.mass = mass;
    def.radius = radius;
    def.color = {static_cast<std::uint8_t>(channel(rng_)), static_cast<std::uint8_t>(channel(rng_)),
                 static_cast<std::uint8_t>(channel(rng_))};
    world_.add(def);
    userAction("spawn particle");
    char buf[200];
    std::snprintf(buf, sizeof buf,
                  "Spawned particle at [%.2f, %.2f] with velocity [%.2f, %.2f] m/s and mass "
                  "%.3g kg",
                  spot->x(), spot->y(), def.velocity.x(), def.velocity.y(), mass);
    log(buf);
}

void Session::changeSpawnMass(int direction) {
    const double before = spawn_.mass();
    spawn_.changeSize(direction < 0 ? -1 : 1);
    if (spawn_.mass() != before) remember("set new particle size");
    char buf[160];
    std::snprintf(buf, sizeof buf,
                  "New particles: %.3g kg, radius %.3g m (%.1f x the scene's typical)",
                  spawn_.mass(), spawn_.radius(), spawn_.size);
    notices_.push_back({Notice::Level::Info, buf, true, false});
}

void Session::nextMode() {
    const ModeSwitch r = switchToNextMode(world_);
    say(r.message, r.skipped.empty() ? Notice::Level::Info : Notice::Level::Warning);
    if (!r.detail.empty()) log(r.detail, Notice::Level::Warning);
    if (r.changed) {
        accumulator_ = 0.0;
        userAction("switch mode");
    }
}

void Session::toggleGravity() {
    const ControlChange c = psb::app::toggleGravity(world_, loaded_->def().gravity);
    say(c.message, c.changed ? Notice::Level::Info : Notice::Level::Warning);
    if (c.changed) userAction("switch gravity");
}

void Session::changeRestitution(int direction) {
    const ControlChange c = stepRestitution(world_, direction);
    say(c.message);
    if (c.changed) userAction("set restitution");
}

void Session::reset() {
    // The scene as loaded stays the one shared with the undo history's snapshots.
    std::shared_ptr<const World> loaded = loaded_;
    setWorld(World(*loaded), sceneName_);
    loaded_ = std::move(loaded);
    remember("reset");
    say("Reset to the scene as loaded: " + std::to_string(world_.size()) + " particles");
}

void Session::openPreset(int index) {
    const auto& presets = options_.presets;
    if (presets.empty()) {
        say("No preset scenes found (assets/scenes)");
        return;
    }
    std::size_t k = nextPreset_ % presets.size();
    if (index >= 0) {
        if (static_cast<std::size_t>(index) >= presets.size()) {
            say("No preset " + std::to_string(index + 1) + " (there are " +
                std::to_string(presets.size()) + ")");
            return;
        }
        k = static_cast<std::size_t>(index);
    }
    const std::uint64_t before = generation_;
    openFile(presets[k]);
    nextPreset_ = (k + 1) % presets.size();
    if (generation_ == before) return;  // not opened: the error is said
    // Presets open paused: many are over in seconds (a Galton board, a bullet), and a teacher
    // wants to show the start before it runs.
    paused_ = true;
    accumulator_ = 0.0;
    const std::string key = cmd::presetKey(static_cast<int>(k));
    say("Preset " + std::to_string(k + 1) + " of " + std::to_string(presets.size()) +
        (key.empty() ? std::string() : " (key " + key + ")") + ", paused: Space starts it");
}

void Session::openFile(const std::optional<std::filesystem::path>& file) {
    try {
        const Scene scene = psb::app::openScene(file);
        std::string name = scene.name.empty() && file ? file->stem().string() : scene.name;
        World world = makeWorld(scene);
        sceneBins_ = scene.bins;  // before setWorld, whose fit leaves room for the bins panel
        setWorld(std::move(world), name);
        remember("open scene");
        sceneDescription_ = scene.description;
        // A new scene starts at its own pace: a time speed asked for the last one would make
        // this one look wrong without saying why.
        std::string speedReset;
        if (timeScale_ != 1.0) {
            speedReset = "; time speed back to x1 (was " + speedText(timeScale_) + ")";
            timeScale_ = 1.0;
            reached_ = 1.0;
        }
        showSceneTrails(scene.trails);
        if (file) rememberFile(*file);
        say("Opened " + (file ? file->filename().string() : std::string("the built-in scene")) +
            ": " + name + " (" + std::to_string(world_.size()) + " particles)" + speedReset);
        fileError_.clear();
    } catch (const std::exception& e) {  // SceneError, or a scene the world refuses
        fileError_ = std::string("Cannot open scene: ") + e.what();
        say(fileError_, Notice::Level::Error);
    }
}

// ---------------------------------------------------------------------------------------------
// The edit prompt.

void Session::showSceneTrails(const std::vector<std::size_t>& trails) {
    // Before any step, storage order is the scene's order.
    if (trails.empty() || trails.front() >= world_.size()) return;
    selection_.select(world_.ids()[trails.front()]);
    view_.trails = TrailMode::Selected;
}

void Session::openEdit() {
    const auto id = selection_.id();
    if (!id) {
        say("Click a particle to select it, then Enter edits it");
        return;
    }
    prompt_.open(world_.get(*id));
    log("Editing particle " + std::to_string(id->slot));
}

void Session::closeEdit() {
    if (prompt_.active()) prompt_.close();
}

void Session::applyEdit() {
    const EditResult r = psb::app::applyEdit(world_, prompt_.target(), prompt_.texts());
    if (r.applied) {
        closeEdit();
        say(r.message);
        userAction("edit particle");
    } else {
        // The prompt stays open with its text, so the value can be corrected.
        prompt_.setError(r.message);
        say("Edit refused: " + r.message, Notice::Level::Warning);
    }
}

// ---------------------------------------------------------------------------------------------
// Files and leaving.

void Session::save() {
    saveTo(freeSavePath(options_.saveTo));
}

void Session::saveTo(const std::filesystem::path& path) {
    try {
        say(saveWorld(world_, sceneName_, sceneDescription_, path, sceneBins_));
        std::error_code ec;
        const auto full = std::filesystem::absolute(path, ec).lexically_normal();
        lastSave_ = ec ? path : full;
        rememberFile(*lastSave_);
        dirty_ = false;
        fileError_.clear();
    } catch (const std::exception& e) {  // SaveError; the old file is intact
        fileError_ = std::string("Save failed: ") + e.what();
        say(fileError_, Notice::Level::Error);
    }
}

// ---------------------------------------------------------------------------------------------
// Undo and redo.

void Session::undoOrRedo(bool redo) {
    // The clock as the screen shows it (the HUD's "Time"): an undo restores the whole state,
    // the time with it, and the message says so whenever that number changes.
    const double timeBefore = world_.time();
    const std::string shownBefore = quantity(timeBefore, "s");
    if (viewing_) show(timeline_.lastFrame());  // the present is what comes back after
    if (!(redo ? undo_.canRedo() : undo_.canUndo())) {
        say(redo ? "Nothing to redo" : "Nothing to undo");
        return;
    }
    // The world now goes to the other side as it is (moved, not copied): restore() replaces it.
    UndoState now = snapshot(std::move(world_));
    auto step = redo ? undo_.redo(std::move(now)) : undo_.undo(std::move(now));
    restore(std::move(step->state));
    std::string message = (redo ? "Redone: " : "Undone: ") + step->label;
    const std::string shownAfter = quantity(world_.time(), "s");
    if (shownAfter != shownBefore)
        message += (world_.time() < timeBefore ? " (back to " : " (forward to ") + shownAfter + ")";
    say(message);
}

// ---------------------------------------------------------------------------------------------
// Step back in time.

TimelineView Session::timeline() const {
    TimelineView v;
    v.current = v.earliest = v.latest = world_.time();
    if (timeline_.empty()) return v;
    v.earliest = timeline_.timeOf(timeline_.firstFrame());
    v.latest = std::max(world_.time(), timeline_.timeOf(timeline_.lastFrame()));
    if (viewing_) {
        v.latest = timeline_.timeOf(timeline_.lastFrame());
        v.current = timeline_.timeOf(*viewing_);
        v.viewingPast = true;
    }
    return v;
}

void Session::show(std::int64_t frame) {
    world_ = timeline_.seek(frame);
    viewing_.reset();
    if (frame < timeline_.lastFrame()) viewing_ = frame;
    accumulator_ = 0.0;
    changedSinceMeasure_ = true;
    now_ = sampleObservables(world_);
    accuracy_.resetReference(monitoredEnergy(world_));
}

void Session::leavePast() {
    if (!viewing_) return;
    // The world is the rebuilt frame (and what was done to it since): it carries on from there.
    timeline_.discardAfter(*viewing_);
    viewing_.reset();
    timeline_.edited();
}

void Session::stepBack() {
    seek(world_.time(), true);
}

void Session::stepForward() {
    if (!viewing_) {
        if (paused_) {
            stepRequested_ = true;  // the present: one new step
        } else {
            say("Pause (Space) to step through time");
        }
        return;
    }
    show(*viewing_ + 1);
}

void Session::seek(double seconds, bool oneFrameBack) {
    if (interaction_.mode() != Interaction::Mode::Idle) {
        say("Release the mouse button to step through time");
        return;
    }
    if (!std::isfinite(seconds)) {
        say("Cannot go to that time: it is not a number", Notice::Level::Warning);
        return;
    }
    if (!paused_) {
        paused_ = true;
        say("Paused");
    }
    if (!viewing_) timeline_.record(world_);  // the present, with any edit since the frame
    if (timeline_.empty()) return;
    const std::int64_t at = viewing_.value_or(timeline_.lastFrame());
    std::int64_t target = timeline_.frameAt(seconds);
    if (oneFrameBack) target = at - 1;
    if (target < timeline_.firstFrame()) {
        say(fmt("The recorded past starts at %.2f s (%.1f s kept)",
                timeline_.timeOf(timeline_.firstFrame()), timeline_.coveredSeconds()));
        return;
    }
    if (target != at) show(target);
}

void Session::toggleHelp() {
    const int pages =
        options_.insets.helpPagesFor
            ? options_.insets.helpPagesFor(camera_.viewportWidth(), camera_.viewportHeight())
            : 1;
    if (!showHelp_) {
        showHelp_ = true;
        helpPage_ = 0;
    } else if (static_cast<int>(helpPage_) + 1 < pages) {
        ++helpPage_;
    } else {
        showHelp_ = false;
    }
}

void Session::back() {
    if (quitPending_) {
        running_ = false;
    } else if (showHelp_) {
        showHelp_ = false;
    } else if (prompt_.active()) {
        closeEdit();
        say("Edit cancelled");
    } else {
        quit();
    }
}

void Session::quit() {
    if (!dirty_ || quitPending_) {
        running_ = false;
        return;
    }
    quitPending_ = true;
    say("Unsaved changes: Esc again quits without saving, Ctrl+S saves, any other key stays",
        Notice::Level::Warning);
}

// ---------------------------------------------------------------------------------------------
// The view.

bool Session::columnAsked() const {
    return view_.plots || view_.speeds || showProfile_ || binsShown();
}

bool Session::sideColumnFolded() const {
    const ViewInsets& in = options_.insets;
    const double scale = in.panelColumn / (kSideColumnMaxWidth + kPanelMargin);
    return columnAsked() &&
           !sideColumnFits(camera_.viewportWidth(), static_cast<int>(controlsInset()), scale);
}

void Session::fit() {
    const ViewInsets& in = options_.insets;
    // The momentum legend is three short lines: it does not cost the box a column.
    const bool column = columnAsked() && !sideColumnFolded();
    const double w = world_.def().width, h = world_.def().height, margin = 10.0;
    const double left = controlsInset();
    const double top =
        in.topFor ? std::max(in.top, in.topFor(camera_.viewportWidth() - static_cast<int>(left),
                                               sideColumnFolded()))
                  : in.top;
    double right = 0.0;
    if (column) {
        const double scale = in.panelColumn / (kSideColumnMaxWidth + kPanelMargin);
        right = std::min(in.panelColumn,
                         sideColumnWidth(camera_.viewportWidth(), static_cast<int>(left), scale) +
                             1.0 * kPanelMargin);
    } else {
        // A box that the window's height limits may leave width to spare: when it leaves the
        // inspector's whole column, the box moves left, keeps its size, and the inspector
        // (bottom right, on a click) does not cover it. Less room would only move the box off
        // centre and still leave it covered.
        camera_.fit(w, h, margin, top, in.bottom, 0.0, left);
        const double spare = camera_.viewportWidth() - left - camera_.toScreen(w) - 2.0 * margin;
        right = spare >= in.inspectorColumn ? in.inspectorColumn : 0.0;
    }
    camera_.fit(w, h, margin, top, in.bottom, right, left);
    const Vec2 topLeft = camera_.worldToScreen(Vec2::Zero());
    char buf[160];
    std::snprintf(buf, sizeof buf, "View: zoom %.6f px/m, box top-left at [%.2f, %.2f] px",
                  camera_.zoom(), topLeft.x(), topLeft.y());
    log(buf);
    fitted_ = true;
}

void Session::resize(int width, int height) {
    if (width == camera_.viewportWidth() && height == camera_.viewportHeight()) return;
    // A fitted view stays fitted; a view the user moved keeps its centre where it was.
    const Vec2 centre =
        camera_.screenToWorld(Vec2(camera_.viewportWidth() / 2.0, camera_.viewportHeight() / 2.0));
    camera_.setViewport(width, height);
    if (fitted_) {
        fit();
    } else {
        camera_.set(camera_.zoom(), centre - Vec2(width / 2.0, height / 2.0) / camera_.zoom());
    }
}

void Session::togglePanel(bool& flag, const char* on, const char* off) {
    flag = !flag;
    say(flag ? on : off);
    // The panel column sits beside the box: a fitted view makes room for it (or takes it back).
    if (fitted_) fit();
}

// ---------------------------------------------------------------------------------------------
// Time.

void Session::holdParticle(double now) {
    // Through the timeline's setters, so that a past frame replays the hand's moves.
    if (const auto h = interaction_.hold(world_, now, launchSettings())) {
        timeline_.setPosition(world_, h->id, h->position);
        timeline_.setVelocity(world_, h->id, h->velocity);
    }
}

void Session::setTimeScale(double value) {
    if (!std::isfinite(value)) return;
    timeScale_ = std::clamp(value, kMinTimeScale, kMaxTimeScale);
    reached_ = timeScale_;
    say("Time speed " + speedText(timeScale_));
}

void Session::stepOnce(double now) {
    holdParticle(now);
    const double dt = world_.solver().dt;
    world_.step(dt);
    timeline_.stepped(dt);
}

void Session::update(double realSeconds, double now, double budgetMs) {
    const auto t0 = std::chrono::steady_clock::now();
    const double dt = world_.solver().dt;
    const double simBefore = world_.time();
    lastNow_ = now;
    accuracy_.beginSteps(world_);
    if (!paused_) {
        accumulator_ += realSeconds * timeScale_;
        while (accumulator_ >= dt) {
            stepOnce(now);
            accumulator_ -= dt;
            // Catching up must not take longer than a frame, or each frame would fall further
            // behind: drop the backlog and let the simulation run slower than real time.
            if (msSince(t0) > budgetMs) {
                accumulator_ = 0.0;
                behindUntil_ = now + 1.0;
                break;
            }
        }
        if (realSeconds > 0.0) {
            // Smoothed over about half a second at 60 frames per second.
            const double rate = (world_.time() - simBefore) / realSeconds;
            reached_ += 0.1 * (rate - reached_);
        }
    } else if (stepRequested_) {
        stepOnce(now);
    }
    stepRequested_ = false;
    accuracy_.endSteps(world_);
    // Arrows shorten when the motion speeds up (a bullet scattering a crowd) but never grow
    // back on their own, so their lengths stay comparable over time; opening a scene resets it.
    view_.arrowSeconds = std::min(view_.arrowSeconds, arrowSecondsFor(world_));
    // Show the held particle exactly at the hand, paused or not.
    holdParticle(now);
    // The state as drawn is measured when the steps' own detection did not see it: nothing
    // stepped (paused, or a held particle moved), the exact mode (its events meet overlaps only
    // at collisions), or the user changed the world since. Running in discrete or substep mode
    // the steps' maximum already bounds it, and a broadphase pass a frame would cost ~2 ms at
    // 5·10⁴ particles.
    if (world_.counters().steps == 0 || world_.solver().mode == StepMode::Exact ||
        changedSinceMeasure_) {
        accuracy_.measureState(world_);
        changedSinceMeasure_ = false;
    } else {
        accuracy_.clearState();
    }
    checkSelection();
    // Always recorded (three compensated sums over the particles), so the plots and the centre
    // of mass path have a history the moment they are switched on. The accuracy monitor clears
    // the world's counters before each frame's steps; the series wants a running total.
    collisions_ += world_.counters().collisions;
    now_ = sampleObservables(world_);
    now_.collisions = collisions_;
    // A past frame shown is neither the present nor a new sample.
    if (!viewing_) {
        series_.record(now_);
        timeline_.record(world_);
    }
    lastStepMs_ = msSince(t0);
}

}  // namespace psb::app
