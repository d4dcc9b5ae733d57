#pragma once
// Finding the files the app ships with (fonts, scenes) from wherever it was started.

#include <filesystem>
#include <optional>
#include <string_view>
#include <vector>

namespace psb::app {

/// The places searched for the assets (`fonts/`, `scenes/`), in order: $PSB_ASSETS_DIR,
/// `assets/` beside the executable, the install's data directory relative to the executable
/// (`../share/particle-sandbox` for the default layout, so an installed tree can be moved), the
/// source tree's `assets/` the build was configured with (a build tree), and `assets/` under
/// the working directory.
[[nodiscard]] std::vector<std::filesystem::path> assetDirectories();

/// The first of assetDirectories() that holds both `fonts/` and `scenes/`; none if no place
/// does. What --help names as the place the presets are read from.
[[nodiscard]] std::optional<std::filesystem::path> assetDirectory();

/// The preset scene files shipped in assets/scenes/, in file-name order (01-..., 02-...);
/// empty when that directory cannot be found. The session is handed this list
/// (SessionOptions::presets), so it never looks for files itself.
[[nodiscard]] std::vector<std::filesystem::path> presetScenes();

/// The full path of `relative` (e.g. "fonts/DejaVuSansMono.ttf") in the first directory that
/// has it. Throws std::runtime_error listing every place looked when none does.
[[nodiscard]] std::filesystem::path findAsset(std::string_view relative);

}  // namespace psb::app
