#pragma once
// Every change a user makes, as a value. Keys, the mouse, the tests and (next) on-screen
// buttons all turn what they mean into a Command and hand it to Session::apply, the one place
// where commands change anything; keeping them plain values is what lets an undo history or a
// recorded session replay them later.
//
// Pointer positions are screen pixels (the session converts them through its camera), times are
// seconds on the clock the pointer events carry (SDL's ticks in the app).

#include <filesystem>
#include <string>
#include <variant>

#include <particle_sandbox/math.hpp>

namespace psb::app::cmd {

// The left button: grab, fling, launch, select.
struct PointerDown {
    Vec2 screen;
    double time = 0.0;
};
struct PointerMove {
    Vec2 screen;
    double time = 0.0;
};
struct PointerUp {
    Vec2 screen;
    double time = 0.0;
};
/// Backspace/Delete: the held particle.
struct DeleteHeld {};

// The view.
struct Pan {
    Vec2 pixels;
};  ///< the world slides by `pixels`
struct Zoom {
    Vec2 screen;
    double factor = 1.0;
};  ///< about a screen point
struct Fit {};
struct Resize {
    int width = 0;
    int height = 0;
};  ///< the drawable area, pixels
struct ToggleArrows {};
struct ToggleLabels {};
struct ToggleHelp {};
struct ToggleProfile {};
struct ToggleMomentum {};
struct CycleTrails {};
struct TogglePlots {};
struct ToggleSpeeds {};

// Time.
struct TogglePause {};
struct SingleStep {};  ///< one step, while paused
struct ScaleTime {
    double factor = 1.0;
};  ///< time speed times `factor`

// Step back in time (while paused; see Session::timeline()).
struct StepBack {};     ///< one recorded frame back
struct StepForward {};  ///< one recorded frame forward; at the latest frame, one new step
struct Seek {
    double seconds = 0.0;
};  ///< to the recorded frame at or before this simulated time, within the covered range
struct SeekBy {
    double seconds = 0.0;
};  ///< Seek to the time shown plus `seconds` (negative: back)

// Undo and redo of the user's edits.
struct Undo {};
struct Redo {};

// The world.
struct SpawnRandom {};
struct ChangeSpawnMass {
    int direction = 0;
};  ///< -1 lighter, +1 heavier
struct ChangeRestitution {
    int direction = 0;
};
struct ToggleGravity {};
struct NextMode {};
struct Reset {};
struct OpenPreset {
    int index = -1;
};  ///< by position in the preset list; -1: the next one

/// The keys that open presets by number: 1-9 the first nine, 0 the tenth, Shift+1-9 the 11th to
/// the 19th (Shift+0 the tenth too). `digit` 0..9; returns the preset's index.
[[nodiscard]] constexpr int presetForDigit(int digit, bool shift) {
    if (digit == 0) return 9;
    return shift ? 10 + digit - 1 : digit - 1;
}
/// The key that opens preset `index` ("7", "0", "Shift+3"); empty when no key does.
[[nodiscard]] inline std::string presetKey(int index) {
    if (index >= 0 && index < 9) return std::to_string(index + 1);
    if (index == 9) return "0";
    if (index >= 10 && index < 19) return "Shift+" + std::to_string(index - 9);
    return {};
}
struct OpenFile {
    std::filesystem::path file;
};

// The selected particle's edit prompt.
struct OpenEdit {};
struct EditType {
    std::string text;
};
struct EditField {
    bool back = false;
};  ///< Tab / Shift+Tab
struct EditBackspace {};
struct EditApply {};

// Files and leaving.
struct Save {};
struct Screenshot {};  ///< the app writes the next frame's pixels
/// Esc: closes what is open (the help, the edit prompt, a quit question); with nothing open,
/// quits, asking first when there are unsaved changes.
struct Back {};
/// The window's close button: quits, asking first when there are unsaved changes.
struct Quit {};

}  // namespace psb::app::cmd

namespace psb::app {

using Command =
    std::variant<cmd::PointerDown, cmd::PointerMove, cmd::PointerUp, cmd::DeleteHeld, cmd::Pan,
                 cmd::Zoom, cmd::Fit, cmd::Resize, cmd::ToggleArrows, cmd::ToggleLabels,
                 cmd::ToggleHelp, cmd::ToggleProfile, cmd::ToggleMomentum, cmd::CycleTrails,
                 cmd::TogglePlots, cmd::ToggleSpeeds, cmd::TogglePause, cmd::SingleStep,
                 cmd::ScaleTime, cmd::StepBack, cmd::StepForward, cmd::Seek, cmd::SeekBy, cmd::Undo,
                 cmd::Redo, cmd::SpawnRandom, cmd::ChangeSpawnMass, cmd::ChangeRestitution,
                 cmd::ToggleGravity, cmd::NextMode, cmd::Reset, cmd::OpenPreset, cmd::OpenFile,
                 cmd::OpenEdit, cmd::EditType, cmd::EditField, cmd::EditBackspace, cmd::EditApply,
                 cmd::Save, cmd::Screenshot, cmd::Back, cmd::Quit>;

}  // namespace psb::app
