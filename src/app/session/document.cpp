#include "session/document.hpp"

#include <unistd.h>

#include <algorithm>
#include <system_error>

#include "session/collision_feed.hpp"
#include "session/notices.hpp"
#include "session/particle_edit.hpp"
#include "session/scene_io.hpp"
#include "session/start_over.hpp"
#include "session/undo_history.hpp"

namespace psb::app {

SceneInfo sceneInfo(const Scene& scene, const std::optional<std::filesystem::path>& file) {
    SceneInfo info = scene;
    if (info.name.empty() && file) info.name = file->stem().string();
    return info;
}

namespace {

std::filesystem::path absolutePath(const std::filesystem::path& file) {
    std::error_code ec;
    const auto full = std::filesystem::absolute(file, ec).lexically_normal();
    return ec ? file : full;
}

}  // namespace

SceneFile sceneFile(const std::optional<std::filesystem::path>& file,
                    const std::vector<std::filesystem::path>& readOnly) {
    SceneFile f;
    if (!file) return f;
    f.path = absolutePath(*file);
    const bool preset = std::any_of(readOnly.begin(), readOnly.end(),
                                    [&](const auto& p) { return absolutePath(p) == *f.path; });
    f.writable = !preset && ::access(f.path->c_str(), W_OK) == 0;
    return f;
}

Document::Document(World w, SceneInfo m, SceneFile f) {
    replace(std::move(w), std::move(m), std::move(f));
}

void Document::replace(World w, SceneInfo m, SceneFile f) {
    loaded = std::make_shared<const World>(w);
    setup = loaded;
    editedSinceSetup = false;
    world = std::move(w);
    meta = std::move(m);
    file = std::move(f);
    loadedName = meta.name;
    loadedDescription = meta.description;
    savedSinceLoad = false;
    // "Saved to FILE" is said of the scene that was saved, not of the one replacing it.
    lastSave.reset();
    ++generation;
    dirty = false;
}

void Document::open(World w, SceneInfo m, SceneFile f, StartOver& startOver, Notices& notices) {
    const bool unsaved = dirty;
    const std::string was = meta.name;
    replace(std::move(w), std::move(m), std::move(f));
    startOver.scene(*this);
    if (unsaved) {
        notices.say("The unsaved changes to " + (was.empty() ? std::string("the scene") : was) +
                        " were replaced: " + notices.undoKey() + " brings them back",
                    Notice::Level::Warning);
    }
}

bool Document::restore(UndoState& state) {
    const bool otherScene = state.loaded != loaded;
    world = std::move(state.world);
    loaded = std::move(state.loaded);
    meta = std::move(state.meta);
    dirty = state.dirty;
    if (otherScene) {
        file = std::move(state.file);
        setup = loaded;
        editedSinceSetup = false;
    } else {
        editedSinceSetup = true;  // the world is not the set-up's any more
    }
    ++generation;  // views keyed to particles (trails) start over
    return otherScene;
}

void Document::edited() {
    dirty = true;
    editedSinceSetup = true;
}

bool Document::asOnDisk() const {
    return !savedSinceLoad && setup == loaded && meta.name == loadedName &&
           meta.description == loadedDescription;
}

bool Document::play() {
    if (!editedSinceSetup) return false;
    setup = std::make_shared<const World>(world);
    editedSinceSetup = false;
    return true;
}

void Document::rememberFile(const std::filesystem::path& known) {
    const std::filesystem::path f = absolutePath(known);
    recent.erase(std::remove(recent.begin(), recent.end(), f), recent.end());
    recent.insert(recent.begin(), f);
    if (recent.size() > kRecentFiles) recent.resize(kRecentFiles);
}

std::string Document::save(const std::filesystem::path& path) {
    std::string said = saveWorld(world, meta, path);
    lastSave = absolutePath(path);
    file = {lastSave, true};
    savedSinceLoad = true;
    rememberFile(*lastSave);
    dirty = false;
    fileError.clear();
    return said;
}

EditResult Document::editParticle(const CheckedEdit& edit, const Axes& axes) {
    return writeEdit(world, edit, axes);
}

void Document::listen(const std::optional<CollisionLog>& wanted) {
    psb::app::listen(world, wanted);
}

std::vector<Collision> Document::heard() {
    return psb::app::heard(world);
}

}  // namespace psb::app
