#pragma once
// Finding the files the app ships with (fonts, scenes) from wherever it was started.

#include <filesystem>
#include <string_view>
#include <vector>

namespace psb::app {

/// The places searched for `assets/`, in order: $PSB_ASSETS_DIR, `assets/` beside the
/// executable, `../share/particle-sandbox/assets` (an install), the directory the build was
/// configured with (a build tree), and `assets/` under the working directory.
[[nodiscard]] std::vector<std::filesystem::path> assetDirectories();

/// The full path of `relative` (e.g. "fonts/DejaVuSansMono.ttf") in the first directory that
/// has it. Throws std::runtime_error listing every place looked when none does.
[[nodiscard]] std::filesystem::path findAsset(std::string_view relative);

}  // namespace psb::app
