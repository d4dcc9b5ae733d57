// The session's document: opening scenes and presets, resetting, saving, and leaving (the
// document itself is document.hpp; reading and writing files is scene_io.hpp's).

#include <filesystem>

#include "session/session.hpp"
#include "session/session_text.hpp"

namespace psb::app {

void Session::handle(const cmd::Reset&) {
    // The scene as loaded stays the one shared with the undo history's snapshots.
    std::shared_ptr<const World> loaded = doc_.loaded;
    setWorld(World(*loaded), doc_.meta);
    doc_.loaded = std::move(loaded);
    remember("reset");
    say("Reset to the scene as loaded: " + std::to_string(doc_.world.size()) + " particles");
}

void Session::handle(const cmd::OpenPreset& c) {
    const auto& presets = options_.presets;
    if (presets.empty()) {
        say("No preset scenes found (assets/scenes)");
        return;
    }
    std::size_t k = nextPreset_ % presets.size();
    if (c.index >= 0) {
        if (static_cast<std::size_t>(c.index) >= presets.size()) {
            say("No preset " + std::to_string(c.index + 1) + " (there are " +
                std::to_string(presets.size()) + ")");
            return;
        }
        k = static_cast<std::size_t>(c.index);
    }
    const std::uint64_t before = doc_.generation;
    openFile(presets[k]);
    nextPreset_ = (k + 1) % presets.size();
    if (doc_.generation == before) return;  // not opened: the error is said
    // Presets open paused: many are over in seconds (a Galton board, a bullet), and a teacher
    // wants to show the start before it runs.
    clock_.paused = true;
    clock_.restart();
    const std::string key = cmd::presetKey(static_cast<int>(k));
    say("Preset " + std::to_string(k + 1) + " of " + std::to_string(presets.size()) +
        (key.empty() ? std::string() : " (key " + key + ")") + ", paused: Space starts it");
}

void Session::handle(const cmd::OpenFile& c) {
    openFile(c.file);
}

void Session::openFile(const std::optional<std::filesystem::path>& file) {
    try {
        const Scene scene = psb::app::openScene(file);
        World world = makeWorld(scene);
        setWorld(std::move(world), sceneMeta(scene, file));
        remember("open scene");
        // A new scene starts at its own pace: a time speed asked for the last one would make
        // this one look wrong without saying why.
        std::string speedReset;
        if (clock_.scale() != 1.0) {
            speedReset = "; time speed back to x1 (was " + speedText(clock_.scale()) + ")";
            clock_.setScale(1.0);
        }
        showSceneTrails(doc_.meta.trails);
        if (file) doc_.rememberFile(*file);
        say("Opened " + (file ? file->filename().string() : std::string("the built-in scene")) +
            ": " + doc_.meta.name + " (" + std::to_string(doc_.world.size()) + " particles)" +
            speedReset);
        doc_.fileError.clear();
    } catch (const std::exception& e) {  // SceneError, or a scene the world refuses
        doc_.fileError = std::string("Cannot open scene: ") + e.what();
        say(doc_.fileError, Notice::Level::Error);
    }
}

void Session::showSceneTrails(const std::vector<std::size_t>& trails) {
    // Before any step, storage order is the scene's order.
    if (trails.empty() || trails.front() >= doc_.world.size()) return;
    tools_.selection.select(doc_.world.ids()[trails.front()]);
    view_.trails = TrailMode::Selected;
}

void Session::handle(const cmd::Save&) {
    saveTo(freeSavePath(doc_.saveTo));
}

void Session::handle(const cmd::SaveAs& c) {
    if (c.path.empty()) {
        say("Save: type a file name first", Notice::Level::Warning);
        return;
    }
    std::string why;
    const std::optional<std::filesystem::path> named = saveFileName(c.path, why);
    if (!named) {
        // The panel's status line says so too, not the save before it.
        doc_.fileError = "Save: " + why;
        say(doc_.fileError, Notice::Level::Warning);
        return;
    }
    std::filesystem::path path = *named;
    std::error_code ec;
    if (!c.overwrite && std::filesystem::exists(path, ec)) path = freeSavePath(path);
    doc_.saveTo = path;
    saveTo(path);
}

void Session::saveTo(const std::filesystem::path& path) {
    try {
        say(doc_.save(path));
    } catch (const std::exception& e) {  // SaveError; the old file is intact
        doc_.fileError = std::string("Save failed: ") + e.what();
        say(doc_.fileError, Notice::Level::Error);
    }
}

void Session::handle(const cmd::Back&) {
    if (quitPending_) {
        running_ = false;
    } else if (showHelp_) {
        showHelp_ = false;
    } else if (tools_.prompt.active()) {
        tools_.closePrompt();
        say("Edit cancelled");
    } else {
        quit();
    }
}

void Session::handle(const cmd::Quit&) {
    quit();
}

void Session::quit() {
    if (!doc_.dirty || quitPending_) {
        running_ = false;
        return;
    }
    quitPending_ = true;
    say("Unsaved changes: Esc again quits without saving, Ctrl+S saves, any other key stays",
        Notice::Level::Warning);
}

}  // namespace psb::app
