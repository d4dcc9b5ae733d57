#pragma once
// Every change a user makes, as a value. Keys, the mouse, the panel's controls and the tests
// all turn what they mean into a Command and hand it to Session::apply, the one place
// where commands change anything; keeping them plain values is what lets an undo history or a
// recorded session replay them later.
//
// Pointer positions are screen pixels (the session converts them through its camera), times are
// seconds on the clock the pointer events carry (SDL's ticks in the app).
//
// One command per action, whoever sends it: a key that steps a value (E, G, T, ',' and '.')
// sends the same Set... command as the control panel, with the value the step leads to.
//
// Each command type says how Session::apply treats it in its `traits` (see Traits below), so
// that a new command is classified where it is declared, not in lists elsewhere.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <variant>

#include <particle_sandbox/color.hpp>
#include <particle_sandbox/math.hpp>
#include <particle_sandbox/particle_id.hpp>
#include <particle_sandbox/solver_settings.hpp>

#include "session/box_area.hpp"
#include "session/edit_prompt.hpp"
#include "session/video_settings.hpp"
#include "session/view_options.hpp"

namespace psb::app::cmd {

/// A command's part in a gesture of the left button (a press, its drags, its release), which
/// undo files as one edit: a grab, drag and fling, or a grab and delete.
enum class Gesture : std::uint8_t {
    None,
    /// May begin one: when the hand or an obstacle tool takes the press, the state before it is
    /// kept until the gesture ends.
    Press,
    /// Ends it: its edit is filed with the state kept at the press. A press and a release set a
    /// particle kinematic and free, so the timeline keys the frame whether or not it edited.
    Release,
    /// Ends it while the hand holds a particle: the command deletes what the hand holds.
    EndsHold,
};

/// How Session::apply treats a command.
struct Traits {
    /// May change what undo restores: apply() keeps the state before it, for the history. (A
    /// command that `continues` a slider drag belongs to the drag's first and keeps nothing.)
    bool edits = false;
    /// Reaches the session while the edit prompt holds the keyboard: the prompt's own keys, the
    /// pointer, the view's geometry, the control panel's widgets (the mouse sends those),
    /// a screenshot and leaving. Every other command is held back while the prompt is open.
    bool whilePrompt = false;
    /// Reaches the session while a dialog is open (dialog.hpp): the dialog's answers, Esc,
    /// leaving, and what is not a user's choice (a pointer move, a resize). Every other command
    /// is held back until the dialog closes.
    bool whileDialog = false;
    Gesture gesture = Gesture::None;
};
/// Looks, moves the view, steers time or files: never an edit; held back by the prompt.
inline constexpr Traits kLooks{};
/// An edit sent by a key: held back by the prompt.
inline constexpr Traits kEdits{.edits = true};
/// Never an edit; reaches the session past the prompt (its keys, the mouse, the panel).
inline constexpr Traits kPastPrompt{.whilePrompt = true};
/// An edit that reaches the session past the prompt (the mouse, the panel).
inline constexpr Traits kEditsPastPrompt{.edits = true, .whilePrompt = true};
/// Not a user's choice (a pointer move, a resize), leaving, or a dialog's answer.
inline constexpr Traits kPassive{.whilePrompt = true, .whileDialog = true};
/// A dialog's answer that edits (a new scene).
inline constexpr Traits kEditsPassive{.edits = true, .whilePrompt = true, .whileDialog = true};

// The left button: grab, fling, launch, select.
struct PointerDown {
    static constexpr Traits traits{.edits = true, .whilePrompt = true, .gesture = Gesture::Press};
    Vec2 screen;
    double time = 0.0;
};
struct PointerMove {
    static constexpr Traits traits = kPassive;
    Vec2 screen;
    double time = 0.0;
};
struct PointerUp {
    static constexpr Traits traits{.whilePrompt = true, .gesture = Gesture::Release};
    Vec2 screen;
    double time = 0.0;
    /// A second finger came down (platform/touch.hpp): the press ends as a pinch begins, not
    /// as a click or a launch (a pinch on empty space said "Selection cleared"). A particle
    /// held is let go as it was.
    bool pinch = false;
};
/// The pointer is gone from the box: a finger lifted, or the mouse left the window. Nothing stays
/// drawn where it was (the Peg tool's shade of the peg a press would place).
struct PointerLeave {
    static constexpr Traits traits = kPassive;
};
/// Backspace/Delete: the held particle, else the selected particle, else the selected obstacle.
struct DeleteHeld {
    static constexpr Traits traits{.edits = true, .gesture = Gesture::EndsHold};
};

// The view.
struct Pan {
    static constexpr Traits traits = kPastPrompt;
    Vec2 pixels;
};  ///< the world slides by `pixels`
struct Zoom {
    static constexpr Traits traits = kPastPrompt;
    Vec2 screen;
    double factor = 1.0;
};  ///< about a screen point
struct Fit {
    static constexpr Traits traits = kLooks;
};
/// The drawable area, pixels, and where the box may go in it (the app fills `layout` in from the
/// view's layout of the window).
struct Resize {
    static constexpr Traits traits = kPassive;
    int width = 0;
    int height = 0;
    WindowLayout layout{};
};
struct ToggleHelp {
    static constexpr Traits traits = kLooks;
};

// Time.
struct TogglePause {
    static constexpr Traits traits = kLooks;
};
struct SingleStep {
    static constexpr Traits traits = kLooks;
};  ///< one step, while paused

// Step back in time (while paused; see Session::timeline()).
struct StepBack {
    static constexpr Traits traits = kLooks;
};  ///< one recorded frame back
struct StepForward {
    static constexpr Traits traits = kLooks;
};  ///< one recorded frame forward; at the latest frame, one new step
struct Seek {
    static constexpr Traits traits = kLooks;
    double seconds = 0.0;
};  ///< to the recorded frame at or before this simulated time, within the covered range
struct SeekBy {
    static constexpr Traits traits = kLooks;
    double seconds = 0.0;
};  ///< Seek to the time shown plus `seconds` (negative: back)

// Undo and redo of the user's edits.
struct Undo {
    static constexpr Traits traits = kLooks;
};
struct Redo {
    static constexpr Traits traits = kLooks;
};

// The world.
struct SpawnRandom {
    static constexpr Traits traits = kEdits;
};
struct ChangeSpawnMass {
    static constexpr Traits traits = kEdits;
    int direction = 0;
};  ///< -1 lighter, +1 heavier
/// Back to the set-up: the world when Play was last pressed after an edit (PhET's Restart).
struct Restart {
    static constexpr Traits traits = kEditsPastPrompt;
};
/// Back to the scene's file as last opened or saved (read again), or as built.
struct Revert {
    static constexpr Traits traits = kEditsPastPrompt;
};
/// Opens the New scene dialog (Ctrl+N).
struct AskNewScene {
    static constexpr Traits traits = kPastPrompt;
};
/// An empty box as `spec` says, with the laws and mode of the scene shown: the New scene
/// dialog's answer.
struct NewScene {
    static constexpr Traits traits = kEditsPassive;
    double width = 10.0;
    double height = 10.0;
    double gravity = 0.0;
    bool walls = true;
};
/// The scene's title and description, as the user wrote them.
struct SetSceneText {
    static constexpr Traits traits = kEditsPastPrompt;
    std::string name;
    std::string description;
};
struct OpenPreset {
    static constexpr Traits traits = kEdits;
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
    static constexpr Traits traits = kEdits;
    std::filesystem::path file;
};

// The selected particle's edit prompt.
struct OpenEdit {
    static constexpr Traits traits = kLooks;
};
struct EditType {
    static constexpr Traits traits = kPastPrompt;
    std::string text;
};
struct EditField {
    static constexpr Traits traits = kPastPrompt;
    bool back = false;
};  ///< Tab / Shift+Tab
struct EditBackspace {
    static constexpr Traits traits = kPastPrompt;
};
struct EditApply {
    static constexpr Traits traits = kEditsPastPrompt;
};

// Values set directly (the control panel's sliders, fields and buttons). A slider held and
// dragged sends one command per frame: the first with `continues` false, the rest true, so the
// drag is one user action (one undo step), not hundreds.
struct SetRestitution {
    static constexpr Traits traits = kEditsPastPrompt;
    double value = 1.0;
    bool continues = false;
};
struct SetFriction {
    static constexpr Traits traits = kEditsPastPrompt;
    double value = 0.0;  ///< Coulomb coefficient, >= 0
    bool continues = false;
};
/// The tangential restitution β of rough contacts, in [−1, 1] (WorldDef::tangentialRestitution):
/// 0 a sticking contact stops the slip, 1 perfectly rough (it reverses it, keeping the energy),
/// −1 smooth.
struct SetTangentialRestitution {
    static constexpr Traits traits = kEditsPastPrompt;
    double value = 0.0;
    bool continues = false;
};
/// Whether particles made from now on (launched, spawned) turn, or have fixed rotation (they
/// slide without turning, as a block or a puck): the Physics section's "Discs turn".
struct SetDiscsTurn {
    static constexpr Traits traits = kEditsPastPrompt;
    bool on = true;
};
/// Gravity on (`g` m/s² along `direction`, straight down unless said) or off.
struct SetGravity {
    static constexpr Traits traits = kEditsPastPrompt;
    bool on = false;
    double g = 9.81;
    bool continues = false;
    Vec2 direction = Vec2(0.0, 1.0);  ///< finite, not zero; its length does not matter
};
struct SetWalls {
    static constexpr Traits traits = kEditsPastPrompt;
    bool on = true;
};
/// The stepping mode; `substeps` for StepMode::Substep (2 or more).
struct SetMode {
    static constexpr Traits traits = kEditsPastPrompt;
    StepMode mode = StepMode::Discrete;
    int substeps = 4;
};
/// Simulated seconds per real second, within the session's limits.
struct SetTimeScale {
    static constexpr Traits traits = kEditsPastPrompt;
    double value = 1.0;
};
/// What the left mouse button does.
enum class Tool : std::uint8_t {
    Fling,   ///< a particle: grab and throw it; empty space: launch a new one (the default)
    Launch,  ///< every drag launches a new particle
    Select,  ///< clicks select, drags change nothing
    Pan,     ///< drags move the view
    Peg,     ///< a click places a peg (a fixed disc) at the cursor
    Wall,    ///< a drag draws a wall (a fixed segment) from the press to the release
};
struct SetTool {
    static constexpr Traits traits = kPastPrompt;
    Tool tool = Tool::Fling;
    bool toggle = false;  ///< a key: when `tool` is already on, back to Fling
};
/// The sizes of the obstacles the Peg and Wall tools make, metres (each finite, > 0, at most
/// half the box's smaller side).
struct SetObstacleSizes {
    static constexpr Traits traits = kPastPrompt;
    double pegRadius = 1.0;
    double wallThickness = 0.5;  ///< full thickness
};
/// Removes the obstacle at `index` (the panel's button; Backspace/Delete removes the selected
/// obstacle through DeleteHeld).
struct RemoveObstacle {
    static constexpr Traits traits = kEditsPastPrompt;
    std::size_t index = 0;
};
/// What launched particles are made of; radius 0 follows the mass (the original's rule, scaled
/// to the scene); no colour: a colour from the mass.
struct SetLaunchBody {
    static constexpr Traits traits = kEditsPastPrompt;
    double mass = 10.0;
    double radius = 0.0;
    std::optional<Color> color;
};
/// One value of one particle, as text (validated as the edit prompt validates it).
struct EditParticle {
    static constexpr Traits traits = kEditsPastPrompt;
    ParticleId id;
    ParticleField field = ParticleField::Mass;
    std::string text;
};
/// Removes one particle (the selected one, from the panel).
struct DeleteParticle {
    static constexpr Traits traits = kEditsPastPrompt;
    ParticleId id;
};
/// The selection set from a table (null clears it).
struct Select {
    static constexpr Traits traits = kPastPrompt;
    ParticleId id;
};
/// Show options set to a value (checkboxes, and the keys A, S, V, K, D, O with the flipped value).
using psb::app::ShowOption;
struct SetShow {
    static constexpr Traits traits = kPastPrompt;
    ShowOption option = ShowOption::Arrows;
    bool on = true;
};
/// Every free particle's velocity times `factor` (Heat, Cool in the Physics section): the
/// temperature, the mean kinetic energy, times factor².
struct ScaleSpeeds {
    static constexpr Traits traits = kEditsPastPrompt;
    double factor = 1.0;
};
/// The box resized to `width` × `height` metres with the particles in it (the Physics section's
/// Squeeze and Expand): their positions scaled with the box, their velocities kept, so a gas
/// keeps its temperature and its pressure follows the area. Refused where a particle would not
/// fit or two would overlap, and for a scene with obstacles or droppers.
struct ResizeBox {
    static constexpr Traits traits = kEditsPastPrompt;
    double width = 1.0;
    double height = 1.0;
};
/// The arrow scale, seconds of motion an arrow shows (the Show section's slider): kept as set.
struct SetArrowScale {
    static constexpr Traits traits = kPastPrompt;
    double seconds = 1.0 / 3.0;
    bool continues = false;  ///< part of a slider drag begun earlier (logged once)
};
/// The UI's scale (Ctrl+plus, Ctrl+minus, the Show section's slider): `scale` × the panel's,
/// the HUD's, the labels' and the charts' size at 100 %, kMinUiScale to kMaxUiScale (others are
/// refused). `automatic` (Ctrl+0, Auto): follow the window's height, `scale` being what the rule
/// gives now (the app fills it in: only it knows the window's size in points).
struct SetUiScale {
    static constexpr Traits traits = kPastPrompt;
    double scale = 1.0;
    bool automatic = false;
};
/// The most UI scale the window's width allows (mostUiScale; the app sends it: only it knows the
/// window's size in points). A scale set above it is kept, and used at this.
struct FitUiScale {
    static constexpr Traits traits = kPassive;
    double most = kMaxUiScale;
};
/// The window's colours (Ctrl+T, the Show section).
struct SetTheme {
    static constexpr Traits traits = kPastPrompt;
    Theme theme = Theme::Dark;
};
/// The stopwatch (lab_stopwatch.hpp): the Time section's buttons, U (start / stop) and
/// Shift+U (lap while running, reset while stopped).
struct Stopwatch {
    static constexpr Traits traits = kPastPrompt;
    enum class Action { StartStop, Lap, Reset, LapOrReset };
    Action action = Action::StartStop;
};
/// The trails shown (the panel's choice, and the key L with the next mode).
struct SetTrails {
    static constexpr Traits traits = kPastPrompt;
    int mode = 0;  ///< TrailMode as int: off, selected, all
};
/// The user's hands are on a touch screen (`on`): messages and hints name the panel's buttons
/// instead of keys (SessionOptions::touch). The app sends it when a finger first touches.
struct SetTouch {
    static constexpr Traits traits = kPassive;
    bool on = true;
};
/// The control panel shown or folded to a narrow strip (key C).
struct ToggleControls {
    static constexpr Traits traits = kPastPrompt;
};

// Files and leaving.
/// Ctrl+S: writes the scene's file when the user may (SceneFile::writable), else asks for a
/// name (the Save As dialog).
struct Save {
    static constexpr Traits traits = kPastPrompt;
};
/// Ctrl+Shift+S: opens the Save As dialog.
struct AskSaveAs {
    static constexpr Traits traits = kPastPrompt;
};
/// Saves to `path` as given (an existing file is replaced only when `overwrite` is set; else the
/// Save As dialog asks). The Save As dialog's answer.
struct SaveAs {
    static constexpr Traits traits = kPassive;
    std::filesystem::path path;
    bool overwrite = false;
};
/// The quit dialog's answer.
struct AnswerQuit {
    static constexpr Traits traits = kPassive;
    /// Quit: the answer of the dialog that asks with nothing unsaved (Enter); ignored while
    /// there are unsaved changes, whose answers are Save, Discard and Cancel.
    enum class Choice { Save, Discard, Cancel, Quit };
    Choice choice = Choice::Cancel;
};
/// Cancel: closes the dialog that is open, doing nothing.
struct CloseDialog {
    static constexpr Traits traits = kPassive;
};
struct Screenshot {
    static constexpr Traits traits = kPassive;
};  ///< the app writes the next frame's pixels

// Data out (data_out.hpp): tables to take away; recording the particles' paths
// (instruments.hpp).
/// The tables (psb::valuesTable and its neighbours in data_tables.hpp).
enum class DataTable : std::uint8_t {
    Values,        ///< every particle's state now
    TimeSeries,    ///< the plots' observables from the run's start, with the collision rate
    Trajectories,  ///< the recorded particles' t, x, y, vx, vy
    Collisions,    ///< the recorded particles' collisions
};
/// Writes `table` as CSV to `path`, atomically: a relative path is in the export folder (the
/// screenshots'), an empty one the table's own name there; ".csv" is added when the name has no
/// extension, and an existing file is never replaced (NAME-2.csv, ... instead).
struct ExportTable {
    static constexpr Traits traits = kPastPrompt;
    DataTable table = DataTable::Values;
    std::filesystem::path path;
};
/// Puts `table` on the clipboard as tab-separated text (the app hands it to the system, then
/// says what became of it with ClipboardResult).
struct CopyTable {
    static constexpr Traits traits = kPastPrompt;
    DataTable table = DataTable::Values;
};
/// What became of the text the last CopyTable gave the app: on the system's clipboard
/// (`copied`), or not, and why (a page's browser may refuse, and answers later).
struct ClipboardResult {
    static constexpr Traits traits = kPassive;
    bool copied = false;
    std::string why;
};
/// Starts recording the selected particle (with none selected: every particle, up to
/// DataRecorder's limit) every `every` steps, or stops; `every` 0 keeps the last choice.
struct SetRecording {
    static constexpr Traits traits = kPastPrompt;
    bool on = true;
    int every = 0;
};
/// Starts a video recording with `settings` (none: the last used), or stops the one running
/// (Ctrl+R, the Data section). The app's recorder writes it; the session keeps the choice.
struct ToggleVideo {
    static constexpr Traits traits = kPassive;
    std::optional<VideoSettings> settings;
};
/// The format and area the next video records with (the Video section); not a recording.
struct SetVideoSettings {
    static constexpr Traits traits = kPastPrompt;
    VideoSettings settings;
};
/// Esc: closes what is open (a dialog, the help, the edit prompt); with nothing open, asks in
/// the quit dialog whether to quit (a run, its recordings and measurements are lost on quitting
/// even with nothing unsaved), with Save, Discard and Cancel when there are unsaved changes.
struct Back {
    static constexpr Traits traits = kPassive;
};
/// The window's close button: quits, asking first (the quit dialog) when there are unsaved
/// changes; while that dialog is open it stays open.
struct Quit {
    static constexpr Traits traits = kPassive;
};

}  // namespace psb::app::cmd

namespace psb::app {

using Command = std::variant<
    cmd::PointerDown, cmd::PointerMove, cmd::PointerUp, cmd::PointerLeave, cmd::DeleteHeld,
    cmd::Pan, cmd::Zoom, cmd::Fit, cmd::Resize, cmd::ToggleHelp, cmd::TogglePause, cmd::SingleStep,
    cmd::StepBack, cmd::StepForward, cmd::Seek, cmd::SeekBy, cmd::Undo, cmd::Redo, cmd::SpawnRandom,
    cmd::ChangeSpawnMass, cmd::Restart, cmd::OpenPreset, cmd::OpenFile, cmd::OpenEdit,
    cmd::EditType, cmd::EditField, cmd::EditBackspace, cmd::EditApply, cmd::Save, cmd::Screenshot,
    cmd::Back, cmd::Quit, cmd::SetRestitution, cmd::SetFriction, cmd::SetGravity, cmd::SetWalls,
    cmd::SetMode, cmd::SetTimeScale, cmd::SetTool, cmd::SetLaunchBody, cmd::EditParticle,
    cmd::DeleteParticle, cmd::Select, cmd::SetShow, cmd::SetTrails, cmd::ToggleControls,
    cmd::SaveAs, cmd::SetObstacleSizes, cmd::RemoveObstacle, cmd::Revert, cmd::AskNewScene,
    cmd::NewScene, cmd::SetSceneText, cmd::AskSaveAs, cmd::AnswerQuit, cmd::CloseDialog,
    cmd::ExportTable, cmd::CopyTable, cmd::ClipboardResult, cmd::SetRecording, cmd::ToggleVideo,
    cmd::SetVideoSettings, cmd::Stopwatch, cmd::ScaleSpeeds, cmd::ResizeBox, cmd::SetArrowScale,
    cmd::SetTangentialRestitution, cmd::SetDiscsTurn, cmd::SetUiScale, cmd::FitUiScale,
    cmd::SetTheme, cmd::SetTouch>;

}  // namespace psb::app
