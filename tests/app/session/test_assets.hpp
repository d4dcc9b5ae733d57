#pragma once
// The shipped scenes, for the session tests. The app finds them through the platform layer
// (platform/assets.hpp, which asks SDL where the program is); the session tests link no SDL, so
// they read them from the source tree's assets/ directly.

#include <filesystem>
#include <string_view>
#include <vector>

#include <particle_sandbox/presets.hpp>

namespace psb::app {

/// `relative` (e.g. "scenes/09-galton-board.json") in the source tree's assets/.
[[nodiscard]] inline std::filesystem::path testAsset(std::string_view relative) {
    return std::filesystem::path(PSB_ASSETS_DIR) / relative;
}

/// The preset scene files, in the order the app lists them (platform's presetScenes()).
[[nodiscard]] inline std::vector<std::filesystem::path> testPresets() {
    return sceneFiles(std::filesystem::path(PSB_ASSETS_DIR) / "scenes");
}

}  // namespace psb::app
