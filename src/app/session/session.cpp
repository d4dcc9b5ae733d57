// The session: its parts put together, each command handed to the part that owns what it
// changes and its edit filed for undo (apply), undo and redo, and the frame (update).

#include "session/session.hpp"

#include <chrono>
#include <type_traits>

#include "session/frame_step.hpp"
#include "session/start_over.hpp"
#include "session/units.hpp"

namespace psb::app {

Session::Session(World world, SceneInfo meta, SessionOptions options)
    : options_(std::move(options)),
      doc_(std::move(world), std::move(meta),
           psb::app::sceneFile(options_.sceneFile, options_.presets)),
      view_(options_),
      history_(options_.undo, options_.timeline),
      dataOut_(options_.exportDir, options_.inPage) {
    tools_.rng.seed(options_.seed);
    clock_.paused = options_.paused;
    for (const auto& file : options_.presets)
        presets_.push_back(describeScene(file));
    notices_.touch = options_.touch;
    StartOver parts = startOver();
    parts.scene(doc_);
    doc_.showTrails(tools_, view_);
    if (options_.sceneFile) {
        doc_.rememberFile(*options_.sceneFile);
        if (clock_.paused) {
            notices_.say("Opened " + options_.sceneFile->filename().string() + ": " +
                         doc_.meta.name + ", paused: " + notices_.key("Space", "Play") +
                         " starts it");
        }
    }
    if (!view_.controlsShown())
        notices_.say(std::string("The control panel is folded in this narrow window: ") +
                     notices_.key("C or >>", ">>") + " opens it");
}

void Session::setWorld(World world, SceneInfo meta, SceneFile file) {
    StartOver parts = startOver();
    doc_.open(std::move(world), std::move(meta), std::move(file), parts, notices_);
}

StartOver Session::startOver() {
    return {tools_, view_, clock_, history_, monitor_, instruments_, notices_};
}

std::vector<Notice> Session::takeNotices() {
    return notices_.take();
}

// ---------------------------------------------------------------------------------------------
// The one place commands are applied.

namespace {

/// `Part` has a handler for command `C`: `Part::handle(const C&, Part::Context&)`.
template <class Part, class C>
concept Handles = requires(Part& part, const C& c, typename Part::Context& x) {
    part.handle(c, x);
};

/// Whether `c` may edit: its type's trait, except that a command continuing a slider drag
/// belongs to the drag's first (which kept the state before it).
template <class T>
bool mayEdit(const T& c) {
    if constexpr (requires { c.continues; }) {
        return T::traits.edits && !c.continues;
    } else {
        return T::traits.edits;
    }
}

}  // namespace

template <class C>
void Session::route(const C& c) {
    constexpr bool own = requires {
        handle(c);
    };
    static_assert(Handles<Document, C> + Handles<Tools, C> + Handles<SceneView, C> +
                          Handles<SimClock, C> + Handles<History, C> + Handles<Instruments, C> +
                          Handles<DataOut, C> + own ==
                      1,
                  "every command has one owner: one part with a handle() for it");
    if constexpr (Handles<Document, C>) {
        StartOver parts = startOver();
        Document::Context x{options_, parts, tools_, view_, clock_, instruments_, notices_, edit_};
        doc_.handle(c, x);
    } else if constexpr (Handles<Tools, C>) {
        Tools::Context x{doc_, view_, instruments_.ruler, clock_, monitor_, notices_, edit_};
        tools_.handle(c, x);
    } else if constexpr (Handles<SceneView, C>) {
        SceneView::Context x{doc_, tools_, instruments_, notices_};
        view_.handle(c, x);
    } else if constexpr (Handles<SimClock, C>) {
        SimClock::Context x{doc_, history_, monitor_, notices_, edit_};
        clock_.handle(c, x);
    } else if constexpr (Handles<History, C>) {
        History::Context x{doc_, clock_, monitor_, tools_, notices_};
        history_.handle(c, x);
    } else if constexpr (Handles<Instruments, C>) {
        Instruments::Context x{doc_, tools_, view_, clock_, notices_};
        instruments_.handle(c, x);
    } else if constexpr (Handles<DataOut, C>) {
        DataOut::Context x{doc_, instruments_, view_, notices_};
        dataOut_.handle(c, x);
    } else {
        handle(c);  // Undo, Redo
    }
}

void Session::apply(const Command& command) {
    std::visit(
        [this](const auto& c) {
            constexpr cmd::Traits traits = std::decay_t<decltype(c)>::traits;
            // A dialog holds everything but its answers until it closes.
            if (doc_.dialog.open() && !traits.whileDialog) return;
            // While the edit prompt is open it takes the keyboard.
            if (tools_.prompt.active() && !traits.whilePrompt) return;
            // The state before an edit, for the undo history. A press keeps the state before
            // it until its release or the deletion of what it holds: the gesture (grab, drag,
            // fling or delete) is one edit.
            const bool edits = mayEdit(c);
            history_.before.reset();
            if (traits.gesture == cmd::Gesture::Release ||
                (traits.gesture == cmd::Gesture::EndsHold && tools_.holding())) {
                history_.before = std::move(history_.pressBefore);
                history_.pressBefore.reset();
            } else if (edits) {
                history_.before = snapshot(doc_.world);
            }
            edit_ = EditReport{};
            route(c);
            file(edit_);
            if (traits.gesture == cmd::Gesture::Press && tools_.gestureUnderWay()) {
                history_.pressBefore = std::move(history_.before);
            }
            history_.before.reset();
            // Whatever changed the world other than the timeline's setters makes its frame a
            // keyframe (a press and a release set a particle kinematic and free).
            if (edits || traits.gesture == cmd::Gesture::Release) history_.timeline.edited();
        },
        command);
}

// ---------------------------------------------------------------------------------------------
// Undo and redo.

void Session::file(const EditReport& edit) {
    const bool acted = !edit.action().empty();
    if (acted) {
        history_.leavePast();
        if (!edit.continues() || lastAction_ != edit.action()) {
            ++userActions_;
            lastAction_ = edit.action();
        }
    }
    // The state kept before the command, once (one command, one entry).
    if (!edit.label().empty() && history_.before) {
        history_.undo.record(edit.label(), clock_.lastNow(), std::move(*history_.before));
        history_.before.reset();
    }
    if (acted) {
        monitor_.edited(doc_.world);
        doc_.edited();
        history_.timeline.edited();
    }
}

UndoState Session::snapshot(World world) const {
    UndoState s{std::move(world),
                doc_.loaded,
                doc_.meta,
                tools_.selection.id().value_or(kNullParticle),
                tools_.selectedObstacle,
                tools_.spawn,
                clock_.scale(),
                doc_.dirty,
                doc_.file};
    // A particle in the hand is kinematic only while held: restored, it is free again.
    if (tools_.holding() && s.world.contains(tools_.hand.held())) {
        s.world.setKinematic(tools_.hand.held(), false);
    }
    return s;
}

void Session::restore(UndoState state) {
    const bool otherScene = doc_.restore(state);
    // The recorded frames belong to the state undone: the record starts again from here.
    startOver().world(doc_, otherScene);
    tools_.restore(state, doc_.world);
    clock_.setScale(state.timeScale);
    if (otherScene && view_.fitted()) view_.fit(doc_, notices_);
}

void Session::handle(const cmd::Undo&) {
    undoOrRedo(false);
}

void Session::handle(const cmd::Redo&) {
    undoOrRedo(true);
}

void Session::handle(const cmd::SetTouch& c) {
    options_.touch = c.on;
    notices_.touch = c.on;
}

void Session::undoOrRedo(bool redo) {
    // The clock as the screen shows it (the HUD's "Time"): an undo restores the whole state,
    // the time with it, and the message says so whenever that number changes.
    const double timeBefore = doc_.world.time();
    const std::string shownBefore = quantity(timeBefore, "s");
    // Viewing a past frame: the present comes back first.
    if (history_.viewing) history_.show(history_.timeline.lastFrame(), doc_, clock_, monitor_);
    if (!(redo ? history_.undo.canRedo() : history_.undo.canUndo())) {
        notices_.say(redo ? "Nothing to redo" : "Nothing to undo");
        return;
    }
    // The world now goes to the other side as it is (moved, not copied): restore() replaces it.
    UndoState now = snapshot(std::move(doc_.world));
    auto step = redo ? history_.undo.redo(std::move(now)) : history_.undo.undo(std::move(now));
    restore(std::move(step->state));
    std::string message = (redo ? "Redone: " : "Undone: ") + step->label;
    const std::string shownAfter = quantity(doc_.world.time(), "s");
    if (shownAfter != shownBefore) {
        message +=
            (doc_.world.time() < timeBefore ? " (back to " : " (forward to ") + shownAfter + ")";
    }
    notices_.say(message);
}

// ---------------------------------------------------------------------------------------------
// The frame.

double Session::stepOnce(double now) {
    tools_.hold(doc_.world, history_.timeline, now, view_.camera());
    const double dt = doc_.meta.dt;  // the scene's frame length
    // Whether the card listens is decided as the step starts, and holds for its records.
    const std::optional<ParticleId> selected = tools_.selection.id();
    const bool card = Instruments::cardListens(view_.options().collision, doc_.world);
    instruments_.beforeStep(doc_, card, selected);
    const double simulated = stepFrame(doc_.world, dt);
    // The time series samples on simulated time, whatever the frames (monitor.hpp).
    if (monitor_.stepped(doc_.world)) instruments_.data.sample(monitor_.series().back());
    instruments_.afterStep(doc_, card, selected);
    history_.timeline.stepped(dt);
    return simulated;
}

void Session::update(double realSeconds, double now, double budgetMs) {
    const auto t0 = std::chrono::steady_clock::now();
    monitor_.beginSteps(doc_.world);
    clock_.run(realSeconds, now, doc_.meta.dt, budgetMs, t0, [this, now] { return stepOnce(now); });
    monitor_.endSteps(doc_.world);
    // The arrow scale does not change by itself while a scene runs (launches, a bullet
    // scattering a crowd): arrow lengths stay comparable over time. A scene opened chooses one;
    // the Show section's slider sets it.
    // Show the held particle exactly at the hand, paused or not.
    tools_.hold(doc_.world, history_.timeline, now, view_.camera());
    tools_.checkSelection(doc_.world, notices_);
    instruments_.lastCollision.follow(tools_.selection.id());
    instruments_.lastCollision.dropAfter(doc_.world.time(), history_.viewing.has_value());
    // A past frame shown is neither the present nor a new sample. At a sample's instant (paused
    // there) the sample is the world as drawn, edits before Play included.
    if (monitor_.frameDone(doc_.world, !history_.viewing)) {
        instruments_.data.sample(monitor_.series().back());
    }
    if (!history_.viewing) history_.timeline.record(doc_.world);
    if (const std::string why = instruments_.data.takeStopReason(); !why.empty()) {
        notices_.say("Recording stopped: " + why, Notice::Level::Warning);
    }
    clock_.frameDone(t0);
}

}  // namespace psb::app
