// The session's document: opening scenes and presets, a new scene, restarting and reverting,
// saving (Save and Save As, as document programs do), and leaving with the quit dialog (the
// document itself is document.hpp; reading and writing files is scene_io.hpp's; the dialogs'
// state is dialog.hpp's).

#include <cmath>
#include <filesystem>

#include "session/session.hpp"
#include "session/session_text.hpp"
#include "session/units.hpp"

namespace psb::app {

// ---------------------------------------------------------------------------------------------
// Opening.

void Session::handle(const cmd::OpenPreset& c) {
    const auto& presets = options_.presets;
    if (presets.empty()) {
        notices_.say("No preset scenes found (assets/scenes)");
        return;
    }
    std::size_t k = nextPreset_ % presets.size();
    if (c.index >= 0) {
        if (static_cast<std::size_t>(c.index) >= presets.size()) {
            notices_.say("No preset " + std::to_string(c.index + 1) + " (there are " +
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
    notices_.say("Preset " + std::to_string(k + 1) + " of " + std::to_string(presets.size()) +
                 (key.empty() ? std::string() : " (key " + key + ")") +
                 ", paused: Space starts it");
}

void Session::handle(const cmd::OpenFile& c) {
    openFile(c.file);
}

bool Session::openFile(const std::optional<std::filesystem::path>& file, const char* verb) {
    try {
        const Scene scene = psb::app::openScene(file);
        World world = makeWorld(scene);
        setWorld(std::move(world), sceneMeta(scene, file),
                 psb::app::sceneFile(file, options_.presets));
        edit_.remember("open scene");
        // A new scene starts at its own pace: a time speed asked for the last one would make
        // this one look wrong without saying why.
        std::string speedReset;
        if (clock_.scale() != 1.0) {
            speedReset = "; time speed back to x1 (was " + speedText(clock_.scale()) + ")";
            clock_.setScale(1.0);
        }
        showSceneTrails(doc_.meta.trails);
        if (file) doc_.rememberFile(*file);
        notices_.say(std::string(verb) + " " +
                     (file ? file->filename().string() : std::string("the built-in scene")) + ": " +
                     doc_.meta.name + " (" + std::to_string(doc_.world.size()) + " particles)" +
                     speedReset);
        doc_.fileError.clear();
        return true;
    } catch (const std::exception& e) {  // SceneError, or a scene the world refuses
        doc_.fileError = std::string("Cannot open scene: ") + e.what();
        notices_.say(doc_.fileError, Notice::Level::Error);
        return false;
    }
}

void Session::showSceneTrails(const std::vector<std::size_t>& trails) {
    // Before any step, storage order is the scene's order.
    if (trails.empty() || trails.front() >= doc_.world.size()) return;
    tools_.selection.select(doc_.world.ids()[trails.front()]);
    view_.showTrails(TrailMode::Selected);
}

NewSceneSpec Session::newSceneDefaults() const {
    const WorldDef& d = doc_.world.def();
    NewSceneSpec spec;
    spec.width = d.width;
    spec.height = d.height;
    spec.gravity = d.gravity.norm();
    spec.walls = d.walls;
    return spec;
}

void Session::handle(const cmd::AskNewScene&) {
    closeDialog();
    dialog_.kind = Dialog::Kind::NewScene;
    dialog_.newScene = newSceneDefaults();
}

void Session::handle(const cmd::NewScene& c) {
    const auto refuse = [this](const std::string& why) {
        dialog_.error = why;
        notices_.say("New scene: " + why, Notice::Level::Warning);
    };
    const auto sizeOk = [](double v) {
        return std::isfinite(v) && v >= kMinBoxSide && v <= kMaxBoxSide;
    };
    if (!sizeOk(c.width) || !sizeOk(c.height)) {
        refuse(fmt("the box must be 0.01 m to 1e6 m wide and high, got %g m x %g m", c.width,
                   c.height));
        return;
    }
    if (!(std::isfinite(c.gravity) && c.gravity >= 0.0 && c.gravity <= kMaxPanelGravity)) {
        refuse(fmt("gravity must be 0 to %g m/s\u00b2, got %g", kMaxPanelGravity, c.gravity));
        return;
    }
    // The laws and the mode of the scene shown carry over: only the box is new.
    WorldDef def;
    def.width = c.width;
    def.height = c.height;
    def.walls = c.walls;
    def.gravity = Vec2(0.0, c.gravity);
    def.restitution = doc_.world.def().restitution;
    def.friction = doc_.world.def().friction;
    World world(def, doc_.world.solver());
    SceneMeta meta{"New scene"};
    meta.dt = doc_.meta.dt;
    closeDialog();
    setWorld(std::move(world), std::move(meta), SceneFile{});
    edit_.remember("new scene");
    clock_.paused = true;
    clock_.restart();
    notices_.say(
        fmt("New scene: an empty box %s x %s", quantity(c.width, "m").c_str(),
            quantity(c.height, "m").c_str()) +
        (c.gravity > 0.0 ? fmt(", gravity %g m/s\u00b2", c.gravity) : std::string(", no gravity")) +
        ", paused: fling or launch particles into it, then Space");
}

// ---------------------------------------------------------------------------------------------
// Restart and revert.

void Session::handle(const cmd::Restart&) {
    // The set-up stays the one shared with the document (and the scene as loaded with undo).
    const std::shared_ptr<const World> setup = doc_.setup;
    const bool edited = doc_.editedSinceSetup;
    const bool wasRecording = instruments_.data.recording();
    doc_.world = World(*setup);
    ++doc_.generation;  // views keyed to particles (trails) start over
    startOver(true, true);
    doc_.setup = setup;
    doc_.editedSinceSetup = edited;
    // Back to the scene exactly as its file has it: nothing is unsaved. Any other set-up keeps
    // the changes that made it.
    if (doc_.asOnDisk()) doc_.dirty = false;
    edit_.remember("restart");
    const bool loaded = setup == doc_.loaded;
    notices_.say(std::string("Restarted: back to ") +
                 (loaded ? "the scene as it opened" : "the set-up as Play last started it") + " (" +
                 std::to_string(doc_.world.size()) +
                 " particles, t = " + quantity(doc_.world.time(), "s") + ")");
    if (wasRecording) {
        notices_.say(
            "Recording stopped: what it recorded stays in the Data section to export until X "
            "records again");
    }
}

void Session::handle(const cmd::Revert&) {
    if (doc_.file.path) {
        openFile(doc_.file.path, "Reverted to");
        return;
    }
    // A built-in or new scene: as it was made.
    const std::shared_ptr<const World> loaded = doc_.loaded;
    doc_.world = World(*loaded);
    doc_.setup = loaded;
    doc_.editedSinceSetup = false;
    doc_.dirty = false;
    ++doc_.generation;
    startOver(true);
    edit_.remember("revert");
    notices_.say("Reverted to " + doc_.meta.name + " as it was made (it has no file)");
}

void Session::handle(const cmd::SetSceneText& c) {
    if (c.name == doc_.meta.name && c.description == doc_.meta.description) return;
    const bool renamed = c.name != doc_.meta.name;
    doc_.meta.name = c.name;
    doc_.meta.description = c.description;
    notices_.say(renamed ? "Title: " + (c.name.empty() ? std::string("(none)") : c.name)
                         : std::string("Description changed"));
    edit_.userAction(renamed ? "rename scene" : "describe scene");
}

// ---------------------------------------------------------------------------------------------
// Saving.

std::filesystem::path Session::saveProposal() const {
    if (options_.saveTo) return freeSavePath(*options_.saveTo);
    const std::filesystem::path name =
        doc_.file.path ? doc_.file.path->filename() : sceneFileName(doc_.meta.name);
    return freeSavePath(options_.saveFolder / name);
}

void Session::handle(const cmd::Save&) {
    if (doc_.file.writable && doc_.file.path) {
        saveTo(*doc_.file.path);
        return;
    }
    handle(cmd::AskSaveAs{});
}

void Session::handle(const cmd::AskSaveAs&) {
    const bool quitAfter = dialog_.kind == Dialog::Kind::Quit;
    closeDialog();
    tools_.closePrompt();
    dialog_.kind = Dialog::Kind::SaveAs;
    dialog_.proposal = saveProposal();
    dialog_.quitAfterSave = quitAfter;
    dialog_.download = options_.inPage;
    notices_.say("Save as: type a file name, Enter saves, Esc cancels (" +
                 (dialog_.download ? std::string("the browser downloads it")
                                   : "folder " + dialog_.proposal.parent_path().string()) +
                 ")");
}

void Session::handle(const cmd::SaveAs& c) {
    std::string why;
    const std::optional<std::filesystem::path> named =
        c.path.empty() ? std::nullopt : saveFileName(c.path, why);
    if (c.path.empty()) {
        dialog_.error = "Save: type a file name first";
        notices_.say(dialog_.error, Notice::Level::Warning);
        return;
    }
    if (!named) {
        // The dialog and the panel's status line say so too, not the save before it.
        dialog_.error = doc_.fileError = "Save: " + why;
        notices_.say(doc_.fileError, Notice::Level::Warning);
        return;
    }
    std::filesystem::path path = *named;
    // A relative name is in the folder the dialog shows.
    if (path.is_relative() && dialog_.kind == Dialog::Kind::SaveAs) {
        path = dialog_.proposal.parent_path() / path;
    }
    std::error_code ec;
    // A download never replaces anything the user has: the browser names it anew.
    if (!c.overwrite && !options_.inPage && std::filesystem::exists(path, ec)) {
        // Never a silent overwrite: the dialog asks.
        const bool quitAfter = dialog_.quitAfterSave;
        if (dialog_.kind != Dialog::Kind::SaveAs) dialog_.proposal = path;
        dialog_.kind = Dialog::Kind::SaveAs;
        dialog_.quitAfterSave = quitAfter;
        dialog_.replace = std::filesystem::absolute(path, ec).lexically_normal();
        notices_.say(path.filename().string() + " exists: Replace it, or choose another name",
                     Notice::Level::Warning);
        return;
    }
    if (!saveTo(path)) {
        dialog_.error = doc_.fileError;
        return;
    }
    const bool quitAfter = dialog_.quitAfterSave;
    closeDialog();
    if (quitAfter) running_ = false;
}

bool Session::saveTo(const std::filesystem::path& path) {
    try {
        const std::string saved = doc_.save(path);
        notices_.say(options_.inPage ? fmt("Saved %zu particles as %s", doc_.world.size(),
                                           path.filename().string().c_str())
                                     : saved);
        return true;
    } catch (const std::exception& e) {  // SaveError; the old file is intact
        doc_.fileError = std::string("Save failed: ") + e.what();
        notices_.say(doc_.fileError, Notice::Level::Error);
        return false;
    }
}

// ---------------------------------------------------------------------------------------------
// Dialogs and leaving.

void Session::closeDialog() {
    dialog_ = Dialog{};
}

void Session::handle(const cmd::CloseDialog&) {
    if (!dialog_.open()) return;
    const bool quitting = dialog_.kind == Dialog::Kind::Quit || dialog_.quitAfterSave;
    closeDialog();
    notices_.say(quitting ? "Quit cancelled" : "Cancelled");
}

void Session::handle(const cmd::Back&) {
    if (dialog_.open()) {
        handle(cmd::CloseDialog{});
    } else if (view_.helpShown()) {
        view_.closeHelp();
    } else if (tools_.prompt.active()) {
        tools_.closePrompt();
        notices_.say("Edit cancelled");
    } else if (options_.inPage) {
        notices_.say("Esc closes a dialog, the help or the edit prompt; nothing is open");
    } else {
        quit();
    }
}

void Session::handle(const cmd::Quit&) {
    // While a dialog is open, closing the window again leaves the question standing.
    if (dialog_.open()) return;
    quit();
}

void Session::quit() {
    if (!doc_.dirty) {
        running_ = false;
        return;
    }
    tools_.closePrompt();
    dialog_.kind = Dialog::Kind::Quit;
    notices_.say("Unsaved changes to " + doc_.meta.name + ": Save, Discard or Cancel",
                 Notice::Level::Warning);
}

void Session::handle(const cmd::AnswerQuit& c) {
    if (dialog_.kind != Dialog::Kind::Quit) return;
    switch (c.choice) {
        case cmd::AnswerQuit::Choice::Save:
            if (doc_.file.writable && doc_.file.path) {
                closeDialog();
                if (saveTo(*doc_.file.path)) running_ = false;
            } else {
                handle(cmd::AskSaveAs{});  // keeps quitAfterSave
            }
            return;
        case cmd::AnswerQuit::Choice::Discard:
            closeDialog();
            notices_.log("Quit without saving");
            running_ = false;
            return;
        case cmd::AnswerQuit::Choice::Cancel:
            handle(cmd::CloseDialog{});
            return;
    }
}

}  // namespace psb::app
