#include "assets.hpp"

#include <cstdlib>
#include <stdexcept>
#include <string>
#include <system_error>

#include <SDL.h>

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
        dirs.push_back(exeDir / ".." / "share" / "particle-sandbox" / "assets");
    }
#ifdef PSB_SOURCE_ASSETS_DIR
    dirs.emplace_back(PSB_SOURCE_ASSETS_DIR);
#endif
    dirs.emplace_back("assets");
    return dirs;
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
