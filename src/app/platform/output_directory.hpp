#pragma once
// Checking, at start-up, that the directories the app will write into (the Ctrl+S scene, the
// F12 screenshots) exist and are writable, so a typo in a path is reported before any window
// opens instead of at the first save.

#include <filesystem>
#include <optional>
#include <string>

namespace psb::app {

/// Why files cannot be created in `dir` ("directory D does not exist", "D is not a directory",
/// "directory D is not writable"), or nullopt when they can. An empty path is the current
/// directory.
[[nodiscard]] std::optional<std::string> outputDirectoryProblem(const std::filesystem::path& dir);

/// The directory a file `path` would be written into ("." for a bare file name).
[[nodiscard]] std::filesystem::path directoryOf(const std::filesystem::path& path);

}  // namespace psb::app
