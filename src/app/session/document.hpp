#pragma once
// The scene the session shows, as a document: the world, the scene as it was loaded, the set-up
// Restart returns to, what the scene says beyond its world (SceneInfo), and the file it belongs
// to. The session owns one; undo keeps copies of the parts an edit can change.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <particle_sandbox/axes.hpp>
#include <particle_sandbox/bins.hpp>
#include <particle_sandbox/collision_log.hpp>
#include <particle_sandbox/scene.hpp>
#include <particle_sandbox/world.hpp>

#include "session/command.hpp"
#include "session/dialog.hpp"

namespace psb::app {

struct CheckedEdit;
class EditReport;
struct EditResult;
struct Instruments;
class Notices;
class SceneView;
struct SessionOptions;
class SimClock;
struct StartOver;
struct Tools;
struct UndoState;

/// What `scene`, opened from `file` (none: the built-in scene), says of itself (the document
/// keeps it with the world, and a save writes it back). Its name is the scene's own, else the
/// file's stem.
[[nodiscard]] SceneInfo sceneInfo(const Scene& scene,
                                  const std::optional<std::filesystem::path>& file);

/// The file a scene belongs to, as a document program sees it.
struct SceneFile {
    /// The file it was opened from or last saved to (a preset's too): Revert reads it again.
    std::optional<std::filesystem::path> path;
    /// Save writes `path` without asking: the user opened it from a file they may write, or
    /// named it in Save As. Presets, new scenes and read-only files ask for a name first.
    bool writable = false;
};

/// The SceneFile of a scene opened from `file` (none: a built-in or new scene): absolute, and
/// writable when the user may write it and it is not one of `readOnly` (the presets).
[[nodiscard]] SceneFile sceneFile(const std::optional<std::filesystem::path>& file,
                                  const std::vector<std::filesystem::path>& readOnly = {});

/// The control panel's ranges for the world's laws and box.
inline constexpr double kMaxPanelGravity = 1000.0;  ///< m/s²
inline constexpr int kMaxPanelSubsteps = 64;
/// A new or resized box's sides, metres.
inline constexpr double kMinBoxSide = 0.01;
inline constexpr double kMaxBoxSide = 1e6;

struct Document {
    /// Files opened or saved lately, newest first (at most this many).
    static constexpr std::size_t kRecentFiles = 5;

    Document(World world, SceneInfo meta, SceneFile file);

    /// What the document's commands reach beyond it: where files go and which are presets
    /// (the options), every part that starts over from a world put in place, the tools (the
    /// edit prompt closed, the particle whose trail a scene shows selected), the view (that
    /// trail shown, the help Esc closes), the clock (a scene opens paused, at its own pace; a
    /// new mode owes no time) and the recording a restart stops.
    struct Context {
        const SessionOptions& options;
        StartOver& startOver;
        Tools& tools;
        SceneView& view;
        SimClock& clock;
        const Instruments& instruments;
        Notices& notices;
        EditReport& edit;
    };
    // Files, the scene's text, dialogs and leaving (document_files.cpp).
    void handle(const cmd::OpenPreset& c, Context& x);
    void handle(const cmd::OpenFile& c, Context& x);
    void handle(const cmd::AskNewScene& c, Context& x);
    void handle(const cmd::NewScene& c, Context& x);
    void handle(const cmd::Restart& c, Context& x);
    void handle(const cmd::Revert& c, Context& x);
    void handle(const cmd::SetSceneText& c, Context& x);
    void handle(const cmd::Save& c, Context& x);
    void handle(const cmd::AskSaveAs& c, Context& x);
    void handle(const cmd::SaveAs& c, Context& x);
    void handle(const cmd::AnswerQuit& c, Context& x);
    void handle(const cmd::CloseDialog& c, Context& x);
    void handle(const cmd::Back& c, Context& x);
    void handle(const cmd::Quit& c, Context& x);
    // The world's laws, its stepping mode, its speeds and its box (document_laws.cpp).
    void handle(const cmd::SetRestitution& c, Context& x);
    void handle(const cmd::SetFriction& c, Context& x);
    void handle(const cmd::SetTangentialRestitution& c, Context& x);
    void handle(const cmd::SetGravity& c, Context& x);
    void handle(const cmd::SetWalls& c, Context& x);
    void handle(const cmd::SetMode& c, Context& x);
    void handle(const cmd::ScaleSpeeds& c, Context& x);
    void handle(const cmd::ResizeBox& c, Context& x);

    /// A new scene from `file`: `world` becomes the world, the scene as loaded and the set-up;
    /// nothing is unsaved.
    void replace(World world, SceneInfo meta, SceneFile file);
    /// replace(), and every part starts over from the new scene (`startOver`). Replacing unsaved
    /// changes is undoable, as every change is; it is said, so that a scene opened by a stray
    /// key (a digit opens a preset) is not taken for lost.
    void open(World world, SceneInfo meta, SceneFile file, StartOver& startOver, Notices& notices);
    /// A scene that marks particles' trails opens with the first of them selected and its trail
    /// shown (the marks are indices in the scene's order: the world's before any step).
    void showTrails(Tools& tools, SceneView& view) const;
    /// Puts back what undo keeps of the document (`state`'s world, scene as loaded, meta,
    /// unsaved flag; its file with another scene); returns whether it is another scene.
    bool restore(UndoState& state);
    /// The user edited the scene: unsaved, and the next Play makes a new set-up.
    void edited();
    /// Play was pressed: after an edit, the world as it is becomes the set-up Restart returns
    /// to (PhET's Restart); returns whether it did.
    bool play();
    /// The world is the scene as loaded, with the title and description it had, and nothing was
    /// saved since: the document is what its file (or the built-in scene) holds.
    [[nodiscard]] bool asOnDisk() const;
    /// Puts `file` first in the recent files (absolute, once).
    void rememberFile(const std::filesystem::path& known);
    /// Writes the world with its metadata to `path` atomically, makes it the last save and the
    /// scene's file (writable: the user named it); returns the line for the user. Throws
    /// SaveError (the old file is intact, and nothing changes here).
    std::string save(const std::filesystem::path& path);
    /// What Save As proposes: --save-to, else a free name after the scene's in the save folder.
    [[nodiscard]] std::filesystem::path saveProposal(const SessionOptions& options) const;
    /// What the New scene dialog starts from: the box of the scene shown.
    [[nodiscard]] NewSceneSpec newSceneDefaults() const;
    /// Writes a checked edit of a particle (edit_prompt.hpp, particle_edit.hpp) into the world.
    EditResult editParticle(const CheckedEdit& edit, const Axes& axes);
    /// Has the world record `wanted` from its next step (nothing when none): what the
    /// instruments want together (collision_feed.hpp).
    void listen(const std::optional<CollisionLog>& wanted);
    /// What the world recorded in the step just made (none when it records nothing).
    [[nodiscard]] std::vector<Collision> heard();

    World world;
    std::shared_ptr<const World> loaded;  ///< the world as loaded, shared with undo's snapshots
    /// Restart's target: the world when Play was last pressed after an edit (else as loaded).
    std::shared_ptr<const World> setup;
    bool editedSinceSetup = false;
    SceneInfo meta;
    SceneFile file;
    /// The title and description as loaded, and whether a save came since (asOnDisk()).
    std::string loadedName, loadedDescription;
    bool savedSinceLoad = false;
    /// Changes whenever the world is replaced (open, preset, reset, an undo to another scene):
    /// views keyed to particles (trails) start over.
    std::uint64_t generation = 0;
    bool dirty = false;  ///< changed since it was opened or last saved
    /// The file the last save of the scene shown wrote (absolute); none once another opens.
    std::optional<std::filesystem::path> lastSave;
    std::string fileError;  ///< why the last open or save failed; empty once one succeeds
    std::vector<std::filesystem::path> recent;
    std::size_t nextPreset = 0;  ///< the preset OpenPreset without an index opens
    /// The dialog open (Save As, New scene, the quit question), if any.
    Dialog dialog;
    bool running = true;  ///< false once the user has left

  private:
    /// Opens `path` (none: the built-in scene), saying "VERB FILE: ..."; false when it could
    /// not (the error is said).
    bool openFile(const std::optional<std::filesystem::path>& path, Context& x,
                  const char* verb = "Opened");
    /// Saves to `path`, saying so; false when it failed (the error is said).
    bool saveTo(const std::filesystem::path& path, Context& x);
    void closeDialog();
    /// Leaves, asking first when there are unsaved changes, or always when `ask` (Esc: a
    /// keystroke away from losing a lesson's run).
    void quit(Context& x, bool ask);
};

}  // namespace psb::app
