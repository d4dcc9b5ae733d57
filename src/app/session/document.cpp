#include "session/document.hpp"

#include <algorithm>
#include <system_error>

#include "session/scene_io.hpp"

namespace psb::app {

SceneMeta sceneMeta(const Scene& scene, const std::optional<std::filesystem::path>& file) {
    SceneMeta m;
    m.name = scene.name.empty() && file ? file->stem().string() : scene.name;
    m.description = scene.description;
    m.trails = scene.trails;
    m.bins = scene.bins;
    m.dt = scene.dt;
    return m;
}

Document::Document(World w, SceneMeta m, std::filesystem::path to) : saveTo(std::move(to)) {
    replace(std::move(w), std::move(m));
}

void Document::replace(World w, SceneMeta m) {
    loaded = std::make_shared<const World>(w);
    world = std::move(w);
    meta = std::move(m);
    ++generation;
    dirty = false;
}

void Document::rememberFile(const std::filesystem::path& file) {
    std::error_code ec;
    const auto full = std::filesystem::absolute(file, ec).lexically_normal();
    const std::filesystem::path f = ec ? file : full;
    recent.erase(std::remove(recent.begin(), recent.end(), f), recent.end());
    recent.insert(recent.begin(), f);
    if (recent.size() > kRecentFiles) recent.resize(kRecentFiles);
}

std::string Document::save(const std::filesystem::path& path) {
    std::string said = saveWorld(world, meta, path);
    std::error_code ec;
    const auto full = std::filesystem::absolute(path, ec).lexically_normal();
    lastSave = ec ? path : full;
    rememberFile(*lastSave);
    dirty = false;
    fileError.clear();
    return said;
}

}  // namespace psb::app
