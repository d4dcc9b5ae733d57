#pragma once
// The questions the session asks in a dialog drawn over the window: a name to save under (Save
// As), the box of a new scene, and what to do with unsaved changes when quitting. While one is
// open it holds every command but its own answers (command.hpp, Traits::whileDialog); Esc is
// Cancel. The session keeps what a dialog shows, so that it is tested without a window; the
// control panel's gui/dialogs.cpp draws it and sends the answer as a command.

#include <filesystem>
#include <string>

namespace psb::app {

/// A new scene's empty box: what the New scene dialog asks for, filled in from the scene shown.
struct NewSceneSpec {
    double width = 10.0;   ///< m
    double height = 10.0;  ///< m
    double gravity = 0.0;  ///< m/s², pointing down the screen; 0: none
    bool walls = true;
};

struct Dialog {
    enum class Kind { None, SaveAs, NewScene, Quit };
    Kind kind = Kind::None;
    /// Save As: the file proposed (absolute), whose folder the dialog shows in full.
    std::filesystem::path proposal;
    /// Save As: a file that exists and was named; the dialog asks whether to replace it.
    std::filesystem::path replace;
    /// Why the last answer was refused (a bad name, a failed save), shown in the dialog.
    std::string error;
    /// Save As: the file goes to the browser's downloads (a web page), not to a folder shown.
    bool download = false;
    /// Save As was opened by the quit dialog's Save: a successful save quits.
    bool quitAfterSave = false;
    /// Quit: there are unsaved changes (Save, Discard, Cancel); without them the dialog only
    /// asks whether to quit (Esc with nothing unsaved: Enter quits, Esc stays).
    bool unsaved = false;
    /// New scene: the values the dialog starts from.
    NewSceneSpec newScene;

    [[nodiscard]] bool open() const { return kind != Kind::None; }
};

}  // namespace psb::app
