// The session's past: user actions filed for undo, undo and redo, and stepping back through the
// recorded frames (the rules are undo_history.hpp's and timeline.hpp's).

#include <cmath>

#include "session/session.hpp"
#include "session/session_text.hpp"
#include "session/units.hpp"

namespace psb::app {

// ---------------------------------------------------------------------------------------------
// Undo and redo.

void Session::userAction(const char* what, bool continues) {
    leavePast();
    if (!continues || lastAction_ != what) {
        ++userActions_;
        lastAction_ = what;
    }
    remember(what);
    monitor_.edited(doc_.world);
    doc_.edited();
    history_.timeline.edited();
}

void Session::remember(const char* what) {
    if (!history_.before) return;  // already filed (one command, one entry)
    history_.undo.record(what, clock_.lastNow(), std::move(*history_.before));
    history_.before.reset();
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
    if (tools_.hand.mode() == Interaction::Mode::Holding && s.world.contains(tools_.hand.held())) {
        s.world.setKinematic(tools_.hand.held(), false);
    }
    return s;
}

void Session::restore(UndoState state) {
    const bool otherScene = state.loaded != doc_.loaded;
    doc_.world = std::move(state.world);
    doc_.loaded = std::move(state.loaded);
    doc_.meta = std::move(state.meta);
    doc_.dirty = state.dirty;
    if (otherScene) {
        doc_.file = std::move(state.file);
        doc_.setup = doc_.loaded;
        doc_.editedSinceSetup = false;
    } else {
        doc_.editedSinceSetup = true;  // the world is not the set-up's any more
    }
    ++doc_.generation;  // views keyed to particles (trails) start over
    // The recorded frames belong to the state undone: the record starts again from here.
    startOver(otherScene);
    tools_.spawn = state.spawn;
    clock_.setScale(state.timeScale);
    if (!state.selection.isNull() && doc_.world.contains(state.selection)) {
        tools_.selection.select(state.selection);
    }
    if (state.selectedObstacle && *state.selectedObstacle < doc_.world.obstacles().size()) {
        tools_.selectedObstacle = state.selectedObstacle;
    }
    if (otherScene && fitted_) fit();
}

void Session::handle(const cmd::Undo&) {
    undoOrRedo(false);
}

void Session::handle(const cmd::Redo&) {
    undoOrRedo(true);
}

void Session::undoOrRedo(bool redo) {
    // The clock as the screen shows it (the HUD's "Time"): an undo restores the whole state,
    // the time with it, and the message says so whenever that number changes.
    const double timeBefore = doc_.world.time();
    const std::string shownBefore = quantity(timeBefore, "s");
    if (history_.viewing) show(history_.timeline.lastFrame());  // the present comes back after
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
// Step back in time.

TimelineView Session::timeline() const {
    const Timeline& t = history_.timeline;
    TimelineView v;
    v.current = v.earliest = v.latest = doc_.world.time();
    if (t.empty()) return v;
    v.earliest = t.timeOf(t.firstFrame());
    v.latest = std::max(doc_.world.time(), t.timeOf(t.lastFrame()));
    if (history_.viewing) {
        v.latest = t.timeOf(t.lastFrame());
        v.current = t.timeOf(*history_.viewing);
        v.viewingPast = true;
    }
    return v;
}

void Session::show(std::int64_t frame) {
    doc_.world = history_.timeline.seek(frame);
    history_.viewing.reset();
    if (frame < history_.timeline.lastFrame()) history_.viewing = frame;
    clock_.restart();
    monitor_.showFrame(doc_.world);
}

void Session::leavePast() {
    if (!history_.viewing) return;
    // The world is the rebuilt frame (and what was done to it since): it carries on from there.
    history_.timeline.discardAfter(*history_.viewing);
    history_.viewing.reset();
    history_.timeline.edited();
}

void Session::handle(const cmd::StepBack&) {
    seek(doc_.world.time(), true);
}

void Session::handle(const cmd::StepForward&) {
    if (!history_.viewing) {
        if (clock_.paused) {
            clock_.stepRequested = true;  // the present: one new step
        } else {
            notices_.say("Pause (Space) to step through time");
        }
        return;
    }
    show(*history_.viewing + 1);
}

void Session::handle(const cmd::Seek& c) {
    seek(c.seconds);
}

void Session::handle(const cmd::SeekBy& c) {
    seek(timeline().current + c.seconds);
}

void Session::seek(double seconds, bool oneFrameBack) {
    Timeline& t = history_.timeline;
    if (tools_.hand.mode() != Interaction::Mode::Idle) {
        notices_.say("Release the mouse button to step through time");
        return;
    }
    if (!std::isfinite(seconds)) {
        notices_.say("Cannot go to that time: it is not a number", Notice::Level::Warning);
        return;
    }
    if (!clock_.paused) {
        clock_.paused = true;
        notices_.say("Paused");
    }
    if (!history_.viewing) t.record(doc_.world);  // the present, with any edit since the frame
    if (t.empty()) return;
    const std::int64_t at = history_.viewing.value_or(t.lastFrame());
    std::int64_t target = t.frameAt(seconds);
    if (oneFrameBack) target = at - 1;
    if (target < t.firstFrame()) {
        notices_.say(fmt("The recorded past starts at %.2f s (%.1f s kept)",
                         t.timeOf(t.firstFrame()), t.coveredSeconds()));
        return;
    }
    if (target != at) show(target);
}

}  // namespace psb::app
