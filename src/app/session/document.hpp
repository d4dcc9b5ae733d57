#pragma once
// The scene the session shows, as a document: the world, the scene as it was loaded (Reset's
// target), what the scene says beyond its world (SceneMeta), and the files it came from and
// went to. The session owns one; undo keeps copies of the parts an edit can change.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <particle_sandbox/bins.hpp>
#include <particle_sandbox/scene.hpp>
#include <particle_sandbox/world.hpp>

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

struct Document {
    /// Files opened or saved lately, newest first (at most this many).
    static constexpr std::size_t kRecentFiles = 5;

    Document(World world, SceneMeta meta, std::filesystem::path saveTo);

    /// A new scene: `world` becomes the world and the scene as loaded; nothing is unsaved.
    void replace(World world, SceneMeta meta);
    /// Puts `file` first in the recent files (absolute, once).
    void rememberFile(const std::filesystem::path& file);
    /// Writes the world with its metadata to `path` atomically and makes it the last save;
    /// returns the line for the user. Throws SaveError (the old file is intact).
    std::string save(const std::filesystem::path& path);

    World world;
    std::shared_ptr<const World> loaded;  ///< the world as loaded, shared with undo's snapshots
    SceneMeta meta;
    /// Changes whenever the world is replaced (open, preset, reset, an undo to another scene):
    /// views keyed to particles (trails) start over.
    std::uint64_t generation = 0;
    bool dirty = false;            ///< changed since it was opened or last saved
    std::filesystem::path saveTo;  ///< where Save writes first (Save As changes it)
    std::optional<std::filesystem::path> lastSave;  ///< the file the last save wrote (absolute)
    std::string fileError;  ///< why the last open or save failed; empty once one succeeds
    std::vector<std::filesystem::path> recent;
};

}  // namespace psb::app
