#include "session/session.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <type_traits>

#include <particle_sandbox/diagnostics.hpp>
#include <particle_sandbox/scene.hpp>

#include "session/physics_controls.hpp"
#include "session/scene_io.hpp"
#include "session/session_text.hpp"
#include "session/stopwatch.hpp"
#include "session/units.hpp"

namespace psb::app {

namespace {

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
    layout_ = options_.layout;
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
                resize(c);
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

}  // namespace psb::app
