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

std::filesystem::path freeSavePath(const std::filesystem::path& path) {
    std::error_code ec;
    std::filesystem::path p = std::filesystem::absolute(path, ec);
    if (ec) p = path;
    if (!std::filesystem::exists(p, ec)) return p;
    const std::string stem = p.stem().string(), ext = p.extension().string();
    for (int k = 2;; ++k) {
        std::filesystem::path candidate = p.parent_path() / (stem + "-" + std::to_string(k) + ext);
        if (!std::filesystem::exists(candidate, ec)) return candidate;
    }
}

std::string saveWorld(const World& world, const std::string& name, const std::string& description,
                      const std::filesystem::path& path) {
    saveScene(sceneFromWorld(world, name, description), path);
    std::error_code ec;
    const std::filesystem::path shown = std::filesystem::absolute(path, ec).lexically_normal();
    return "Saved " + std::to_string(world.size()) + " particles to " +
           (ec ? path : shown).string();
}

}  // namespace psb::app
