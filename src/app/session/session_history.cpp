// The session's past: user actions filed for undo, undo and redo, and stepping back through the
// recorded frames (the rules are undo_history.hpp's and timeline.hpp's).

#include <cmath>

#include "session/session.hpp"
#include "session/session_text.hpp"
#include "session/units.hpp"

namespace psb::app {

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

void Session::undoOrRedo(bool redo) {
    // The clock as the screen shows it (the HUD's "Time"): an undo restores the whole state,
    // the time with it, and the message says so whenever that number changes.
    const double timeBefore = doc_.world.time();
    const std::string shownBefore = quantity(timeBefore, "s");
    if (history_.viewing)
        history_.show(history_.timeline.lastFrame(), doc_, clock_,
                      monitor_);  // the present comes back after
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

}  // namespace psb::app
