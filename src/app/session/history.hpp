#pragma once
// The session's past: the undo history of the user's edits (undo_history.hpp) and the recorded
// frames that step back in time (timeline.hpp), with what a command in progress keeps for them.

#include <cstdint>
#include <optional>

#include "session/timeline.hpp"
#include "session/undo_history.hpp"

namespace psb::app {

struct History {
    History(const UndoSettings& u, const TimelineSettings& t)
        : undo(u), timeline(t), timelineSettings(t) {}

    /// A new world (a scene opened, an undo): the recorded frames belong to the old one, and no
    /// press is in progress.
    void startOver() {
        timeline = Timeline(timelineSettings);
        viewing.reset();
        pressBefore.reset();
    }

    UndoHistory undo;
    Timeline timeline;
    TimelineSettings timelineSettings;
    std::optional<UndoState> before;       ///< the state before the command being applied
    std::optional<UndoState> pressBefore;  ///< before the pointer's press, until its release
    std::optional<std::int64_t> viewing;   ///< the past frame shown, while paused
};

}  // namespace psb::app
