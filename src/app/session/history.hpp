#pragma once
// The session's past: the undo history of the user's edits (undo_history.hpp) and the recorded
// frames that step back in time (timeline.hpp), with what a command in progress keeps for them.
// Stepping through the recorded frames is its own: StepBack, StepForward, Seek and SeekBy.
//
// Step back. Every step and every move of the held particle goes through the timeline, which
// the session's update() ends with record(); other edits are reported with edited(). While
// paused, StepBack / StepForward / Seek show a recorded frame: the world is then a rebuilt copy
// of that frame, and nothing is recorded. Resuming, or any edit, from there carries on from
// that frame and forgets the frames after it (the edit is undoable; the forgotten frames are
// not restored by undo).

#include <cstdint>
#include <optional>
#include <utility>

#include <particle_sandbox/world.hpp>

#include "session/command.hpp"
#include "session/timeline.hpp"
#include "session/undo_history.hpp"

namespace psb::app {

class Monitor;
class Notices;
class SimClock;
struct Tools;

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

struct History {
    History(const UndoSettings& u, const TimelineSettings& t)
        : undo(u), timeline(t), timelineSettings(t) {}

    /// What stepping through the past reaches beyond it: the world shown is the frame's (the
    /// document), stepping pauses (the clock) and measures the frame (the monitor), and waits
    /// for the hand to let go (the tools).
    struct Context {
        Document& doc;
        SimClock& clock;
        Monitor& monitor;
        const Tools& tools;
        Notices& notices;
    };
    void handle(const cmd::StepBack& c, Context& x);
    void handle(const cmd::StepForward& c, Context& x);
    void handle(const cmd::Seek& c, Context& x);
    void handle(const cmd::SeekBy& c, Context& x);

    /// A new world (a scene opened, an undo): the recorded frames belong to the old one, and no
    /// press is in progress.
    void startOver() {
        timeline = Timeline(timelineSettings);
        viewing.reset();
        pressBefore.reset();
    }
    /// The recorded past and the frame shown, `world` being the world shown.
    [[nodiscard]] TimelineView view(const World& world) const;
    /// Shows recorded frame `frame` in `doc` (paused); the latest frame ends the viewing.
    void show(std::int64_t frame, Document& doc, SimClock& clock, Monitor& monitor);
    /// Viewing a past frame and about to change the world: carry on from that frame.
    void leavePast();

    UndoHistory undo;
    Timeline timeline;
    TimelineSettings timelineSettings;
    std::optional<UndoState> before;       ///< the state before the command being applied
    std::optional<UndoState> pressBefore;  ///< before the pointer's press, until its release
    std::optional<std::int64_t> viewing;   ///< the past frame shown, while paused

  private:
    /// To the frame at or before `seconds`, or (oneFrameBack) the frame before the one shown.
    void seek(double seconds, Context& x, bool oneFrameBack = false);
};

}  // namespace psb::app
