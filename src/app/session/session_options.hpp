#pragma once
// How a session starts: what the command line and the app tell it once (session.hpp).

#include <cstdint>
#include <filesystem>
#include <optional>
#include <vector>

#include "session/box_area.hpp"
#include "session/timeline.hpp"
#include "session/undo_history.hpp"

namespace psb::app {

struct SessionOptions {
    /// The file the first world came from (none: built in), for Save and Revert.
    std::optional<std::filesystem::path> sceneFile;
    /// What Save As proposes (--save-to), when given; else a name from the scene's, in
    /// `saveFolder`.
    std::optional<std::filesystem::path> saveTo;
    std::filesystem::path saveFolder = ".";
    std::filesystem::path exportDir = ".";       ///< where ExportTable writes a relative name
    std::vector<std::filesystem::path> presets;  ///< what OpenPreset opens (read-only)
    std::uint32_t seed = 1;                      ///< random spawns
    bool paused = false;
    bool arrows = true;
    /// The app runs in a web page: Esc with nothing open does not quit (a page has nothing
    /// to quit to; a window's Esc quits, asking first when there are unsaved changes); files
    /// written (scenes, tables) are handed to the browser as downloads, so messages and dialogs
    /// name the file and the browser's downloads, not the page's folder; the help lists the
    /// page's keys.
    bool inPage = false;
    /// A touch screen is the user's hands (a page on a phone or a tablet; a finger seen since,
    /// cmd::SetTouch): messages and hints name the panel's buttons, not keys.
    bool touch = false;
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

}  // namespace psb::app
