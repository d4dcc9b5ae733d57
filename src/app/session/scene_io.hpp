#pragma once
// The app's side of scene files: what it opens, the presets its keys switch between, and the
// Ctrl+S snapshot. Parsing, validation and atomic writing are the core's (scene.hpp).

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <particle_sandbox/scene.hpp>
#include <particle_sandbox/world.hpp>

#include "session/document.hpp"

namespace psb::app {

/// The scene in `file`, or the built-in default scene (psb::defaultScene) when there is none.
/// Throws SceneError naming the file and the problem.
[[nodiscard]] Scene openScene(const std::optional<std::filesystem::path>& file);

/// A scene file's name and description, for a list to choose from.
struct SceneListing {
    std::filesystem::path file;
    std::string name;         ///< the scene's own name, or the file's stem
    std::string summary;      ///< the description up to its first ':' or '.', one line
    std::string description;  ///< the whole description
};
/// The name and description of `file`; a file that cannot be read says so in its summary.
[[nodiscard]] SceneListing describeScene(const std::filesystem::path& file);

/// Where a save aimed at `path` goes without losing an earlier one: `path` itself when no file
/// is there, else the first free of stem-2.ext, stem-3.ext, ... beside it; made absolute, so the
/// message names the file wherever the program was started.
[[nodiscard]] std::filesystem::path freeSavePath(const std::filesystem::path& path);

/// A file name for a scene called `name`, for Save As to propose: its letters and digits in
/// lower case, other runs of characters as one '-', and ".json" ("Newton's cradle" is
/// "newton-s-cradle.json"; a name with neither is "scene.json").
[[nodiscard]] std::filesystem::path sceneFileName(const std::string& name);

/// The file a name typed for Save As names: trailing dots and spaces dropped ("lesson." is
/// "lesson"), then `extension` (".json" for a scene) added when no extension is left. A name with
/// nothing before its extension (".json"), or beginning with a dot (a hidden file no file list
/// would show), or a path holding a NUL character (the system would read only the part before it),
/// is refused: nullopt, and `why` says so.
[[nodiscard]] std::optional<std::filesystem::path> saveFileName(const std::filesystem::path& typed,
                                                                std::string& why,
                                                                const char* extension = ".json");

/// Saves `world` as a scene with `meta` (its name, description, trails, bins and dt) to `path`,
/// atomically (psb::saveScene): the old file survives any failure. Returns a line for the user
/// naming the absolute path; throws SaveError saying why it failed.
std::string saveWorld(const World& world, const SceneInfo& meta, const std::filesystem::path& path);

}  // namespace psb::app
