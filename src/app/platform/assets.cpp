#include "platform/assets.hpp"

#include <cstdlib>
#include <stdexcept>
#include <string>
#include <system_error>

#include <SDL.h>

#include <particle_sandbox/presets.hpp>

namespace psb::app {

std::vector<std::filesystem::path> assetDirectories() {
    std::vector<std::filesystem::path> dirs;
    if (const char* env = std::getenv("PSB_ASSETS_DIR"); env != nullptr && *env != '\0') {
        dirs.emplace_back(env);
    }
    if (char* base = SDL_GetBasePath(); base != nullptr) {
        const std::filesystem::path exeDir(base);
        SDL_free(base);
        dirs.push_back(exeDir / "assets");
#ifdef PSB_INSTALL_ASSETS_FROM_BINDIR
        dirs.push_back((exeDir / PSB_INSTALL_ASSETS_FROM_BINDIR).lexically_normal());
#endif
    }
#ifdef PSB_SOURCE_ASSETS_DIR
    dirs.emplace_back(PSB_SOURCE_ASSETS_DIR);
#endif
    dirs.emplace_back("assets");
    return dirs;
}

std::optional<std::filesystem::path> assetDirectory() {
    for (const auto& dir : assetDirectories()) {
        std::error_code ec;
        if (std::filesystem::is_directory(dir / "fonts", ec) &&
            std::filesystem::is_directory(dir / "scenes", ec)) {
            return dir;
        }
    }
    return std::nullopt;
}

std::vector<std::filesystem::path> presetScenes() {
    for (const auto& dir : assetDirectories()) {
        std::error_code ec;
        if (std::filesystem::is_directory(dir / "scenes", ec)) return sceneFiles(dir / "scenes");
    }
    return {};
}

std::filesystem::path findAsset(std::string_view relative) {
    std::string looked;
    for (const auto& dir : assetDirectories()) {
        const auto candidate = dir / relative;
        std::error_code ec;
        if (std::filesystem::is_regular_file(candidate, ec)) return candidate;
        looked += "\n  " + candidate.string();
    }
    throw std::runtime_error("cannot find asset '" + std::string(relative) + "'; looked in:" +
                             looked + "\n(set PSB_ASSETS_DIR to the assets directory)");
}

}  // namespace psb::app
