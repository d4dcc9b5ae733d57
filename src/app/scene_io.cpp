#include "scene_io.hpp"

#include <system_error>

#include <particle_sandbox/presets.hpp>

#include "assets.hpp"

namespace psb::app {

Scene openScene(const std::optional<std::filesystem::path>& file) {
    return file ? loadScene(*file) : defaultScene();
}

std::vector<std::filesystem::path> presetScenes() {
    for (const auto& dir : assetDirectories()) {
        std::error_code ec;
        if (std::filesystem::is_directory(dir / "scenes", ec)) return sceneFiles(dir / "scenes");
    }
    return {};
}

std::string saveWorld(const World& world, const std::string& name,
                      const std::filesystem::path& path) {
    saveScene(sceneFromWorld(world, name), path);
    return "Saved " + std::to_string(world.size()) + " particles to " + path.string();
}

}  // namespace psb::app
