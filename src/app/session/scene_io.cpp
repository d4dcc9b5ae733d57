#include "session/scene_io.hpp"

#include <algorithm>
#include <cctype>
#include <system_error>

#include <particle_sandbox/presets.hpp>

namespace psb::app {

Scene openScene(const std::optional<std::filesystem::path>& file) {
    return file ? loadScene(*file) : defaultScene();
}

SceneListing describeScene(const std::filesystem::path& file) {
    SceneListing info;
    info.file = file;
    info.name = file.stem().string();
    try {
        const Scene scene = loadScene(file);
        if (!scene.name.empty()) info.name = scene.name;
        info.description = scene.description;
    } catch (const std::exception& e) {  // SceneError: listed, and refused when opened
        info.summary = std::string("cannot be read: ") + e.what();
        return info;
    }
    const std::string& d = info.description;
    std::size_t end = d.size();
    for (const char* stop : {": ", ". "})
        end = std::min(end, d.find(stop));
    info.summary = d.substr(0, end);
    if (!info.summary.empty() && info.summary.back() == '.') info.summary.pop_back();
    return info;
}

std::optional<std::filesystem::path> saveFileName(const std::filesystem::path& typed,
                                                  std::string& why, const char* extension) {
    // Built by appending: GCC 12 warns wrongly (-Wrestrict) on "'" + string.
    const auto quoted = [](const std::string& text) {
        std::string q(1, '\'');
        q += text;
        q += '\'';
        return q;
    };
    if (typed.native().find('\0') != std::string::npos) {
        why = "a file name cannot hold a NUL character";
        return std::nullopt;
    }
    std::string name = typed.filename().string();
    while (!name.empty() && (name.back() == '.' || name.back() == ' '))
        name.pop_back();
    if (typed.filename().empty()) {
        why = "the path ends in a folder; type a file name after it";
        return std::nullopt;
    }
    if (name.empty()) {
        why = quoted(typed.filename().string());
        why += " is not a file name";
        return std::nullopt;
    }
    if (name.front() == '.') {
        why = quoted(name);
        why +=
            " would be a hidden file with no name before its extension; type a name such as "
            "lesson.json";
        return std::nullopt;
    }
    std::filesystem::path path = typed.parent_path() / name;
    if (path.extension().empty()) path += extension;
    return path;
}

std::filesystem::path sceneFileName(const std::string& name) {
    std::string stem;
    for (const char ch : name) {
        const auto c = static_cast<unsigned char>(ch);
        if (std::isalnum(c) != 0 && c < 128) {
            stem += static_cast<char>(std::tolower(c));
        } else if (!stem.empty() && stem.back() != '-') {
            stem += '-';
        }
        if (stem.size() >= 60) break;
    }
    while (!stem.empty() && stem.back() == '-')
        stem.pop_back();
    return (stem.empty() ? std::string("scene") : stem) + ".json";
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

std::string saveWorld(const World& world, const SceneInfo& meta,
                      const std::filesystem::path& path) {
    Scene scene = sceneFromWorld(world, meta.dt, meta.name, meta.description);
    // The trails' indices were the scene's order when it opened; edits since may have changed
    // it, so a save does not claim them.
    scene.bins = meta.bins;
    saveScene(scene, path);
    std::error_code ec;
    const std::filesystem::path shown = std::filesystem::absolute(path, ec).lexically_normal();
    return "Saved " + std::to_string(world.size()) + " particles to " +
           (ec ? path : shown).string();
}

}  // namespace psb::app
