#pragma once
// The scene the session shows, as a document: the world, the scene as it was loaded, the set-up
// Restart returns to, what the scene says beyond its world (SceneMeta), and the file it belongs
// to. The session owns one; undo keeps copies of the parts an edit can change.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <particle_sandbox/bins.hpp>
#include <particle_sandbox/collision_log.hpp>
#include <particle_sandbox/scene.hpp>
#include <particle_sandbox/world.hpp>

#include "session/particle_edit.hpp"

namespace psb::app {

/// What a scene file says that the world does not keep: read once when the scene opens, kept
/// with the world, written back when it is saved.
struct SceneMeta {
    // Initialised, so that SceneMeta{"name"} names only what it gives.
    std::string name = {};
    std::string description = {};
    /// Indices (in the scene's order) of the particles whose trail shows from the start.
    std::vector<std::size_t> trails = {};
    /// The board's bins and what they should hold (a Galton board's), if the scene has them.
    std::optional<Bins> bins = {};
    /// The scene's frame length (Scene::dt, the file's `solver.dt`), seconds: what the session
    /// steps the world by, and what a save writes. The world keeps no copy. The default is the
    /// built-in scene's (the original's frame).
    double dt = 1.0 / 60.0;
};

/// The metadata of `scene`, opened from `file` (none: the built-in scene). Its name is the
/// scene's own, else the file's stem.
[[nodiscard]] SceneMeta sceneMeta(const Scene& scene,
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

struct Document {
    /// Files opened or saved lately, newest first (at most this many).
    static constexpr std::size_t kRecentFiles = 5;

    Document(World world, SceneMeta meta, SceneFile file);

    /// A new scene from `file`: `world` becomes the world, the scene as loaded and the set-up;
    /// nothing is unsaved.
    void replace(World world, SceneMeta meta, SceneFile file);
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
    SceneMeta meta;
    SceneFile file;
    /// The title and description as loaded, and whether a save came since (asOnDisk()).
    std::string loadedName, loadedDescription;
    bool savedSinceLoad = false;
    /// Changes whenever the world is replaced (open, preset, reset, an undo to another scene):
    /// views keyed to particles (trails) start over.
    std::uint64_t generation = 0;
    bool dirty = false;                             ///< changed since it was opened or last saved
    std::optional<std::filesystem::path> lastSave;  ///< the file the last save wrote (absolute)
    std::string fileError;  ///< why the last open or save failed; empty once one succeeds
    std::vector<std::filesystem::path> recent;
};

}  // namespace psb::app
