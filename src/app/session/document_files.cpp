// The document's files: opening scenes and presets, a new scene, restarting and reverting,
// the scene's title and description, saving (Save and Save As, as document programs do), and
// leaving with the quit dialog (reading and writing files is scene_io.hpp's; the dialogs'
// state is dialog.hpp's).

#include <cmath>
#include <filesystem>

#include "session/document.hpp"
#include "session/edit_report.hpp"
#include "session/instruments.hpp"
#include "session/notices.hpp"
#include "session/scene_io.hpp"
#include "session/scene_view.hpp"
#include "session/session_options.hpp"
#include "session/session_text.hpp"
#include "session/sim_clock.hpp"
#include "session/start_over.hpp"
#include "session/tools.hpp"
#include "session/units.hpp"

namespace psb::app {

// ---------------------------------------------------------------------------------------------
// Opening.

void Document::handle(const cmd::OpenPreset& c, Context& x) {
    const auto& presets = x.options.presets;
    if (presets.empty()) {
        x.notices.say("No preset scenes found (assets/scenes)");
        return;
    }
    std::size_t k = nextPreset % presets.size();
    if (c.index >= 0) {
        if (static_cast<std::size_t>(c.index) >= presets.size()) {
            x.notices.say("No preset " + std::to_string(c.index + 1) + " (there are " +
                          std::to_string(presets.size()) + ")");
            return;
        }
        k = static_cast<std::size_t>(c.index);
    }
    const std::uint64_t before = generation;
    openFile(presets[k], x);
    nextPreset = (k + 1) % presets.size();
    if (generation == before) return;  // not opened: the error is said
    // Presets open paused: many are over in seconds (a Galton board, a bullet), and a teacher
    // wants to show the start before it runs.
    x.clock.paused = true;
    x.clock.restart();
    const std::string key = cmd::presetKey(static_cast<int>(k));
    x.notices.say("Preset " + std::to_string(k + 1) + " of " + std::to_string(presets.size()) +
                  (key.empty() || x.notices.touch ? std::string() : " (key " + key + ")") +
                  ", paused: " + x.notices.key("Space", "Play") + " starts it");
}

void Document::handle(const cmd::OpenFile& c, Context& x) {
    openFile(c.file, x);
}

bool Document::openFile(const std::optional<std::filesystem::path>& path, Context& x,
                        const char* verb) {
    try {
        const Scene scene = psb::app::openScene(path);
        open(makeWorld(scene), sceneInfo(scene, path), psb::app::sceneFile(path, x.options.presets),
             x.startOver, x.notices);
        x.edit.remember("open scene");
        // A new scene starts at its own pace: a time speed asked for the last one would make
        // this one look wrong without saying why.
        std::string speedReset;
        if (x.clock.scale() != 1.0) {
            speedReset = "; time speed back to x1 (was " + speedText(x.clock.scale()) + ")";
            x.clock.setScale(1.0);
        }
        showTrails(x.tools, x.view);
        if (path) rememberFile(*path);
        x.notices.say(std::string(verb) + " " +
                      (path ? path->filename().string() : std::string("the built-in scene")) +
                      ": " + meta.name + " (" + std::to_string(world.size()) + " particles)" +
                      speedReset);
        fileError.clear();
        return true;
    } catch (const std::exception& e) {  // SceneError, or a scene the world refuses
        fileError = std::string("Cannot open scene: ") + e.what();
        x.notices.say(fileError, Notice::Level::Error);
        return false;
    }
}

void Document::showTrails(Tools& tools, SceneView& view) const {
    // Before any step, storage order is the scene's order.
    const std::vector<std::size_t>& trails = meta.trails;
    if (trails.empty() || trails.front() >= world.size()) return;
    tools.selection.select(world.ids()[trails.front()]);
    view.showTrails(TrailMode::Selected);
}

NewSceneSpec Document::newSceneDefaults() const {
    const WorldDef& d = world.def();
    NewSceneSpec spec;
    spec.width = d.width;
    spec.height = d.height;
    spec.gravity = d.gravity.norm();
    spec.walls = d.walls;
    return spec;
}

void Document::handle(const cmd::AskNewScene&, Context&) {
    closeDialog();
    dialog.kind = Dialog::Kind::NewScene;
    dialog.newScene = newSceneDefaults();
}

void Document::handle(const cmd::NewScene& c, Context& x) {
    const auto refuse = [this, &x](const std::string& why) {
        dialog.error = why;
        x.notices.say("New scene: " + why, Notice::Level::Warning);
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
    WorldDef box;
    box.width = c.width;
    box.height = c.height;
    box.walls = c.walls;
    box.gravity = Vec2(0.0, c.gravity);
    box.restitution = world.def().restitution;
    box.friction = world.def().friction;
    World empty(box, world.solver());
    SceneInfo newMeta{"New scene"};
    newMeta.dt = meta.dt;
    closeDialog();
    open(std::move(empty), std::move(newMeta), SceneFile{}, x.startOver, x.notices);
    x.edit.remember("new scene");
    x.clock.paused = true;
    x.clock.restart();
    x.notices.say(
        fmt("New scene: an empty box %s x %s", quantity(c.width, "m").c_str(),
            quantity(c.height, "m").c_str()) +
        (c.gravity > 0.0 ? fmt(", gravity %g m/s\u00b2", c.gravity) : std::string(", no gravity")) +
        ", paused: fling or launch particles into it, then " + x.notices.key("Space", "Play"));
}

// ---------------------------------------------------------------------------------------------
// Restart and revert.

void Document::handle(const cmd::Restart&, Context& x) {
    // The set-up stays the one shared with the document (and the scene as loaded with undo).
    const std::shared_ptr<const World> target = setup;
    const bool wasEdited = editedSinceSetup;
    world = World(*target);
    ++generation;  // views keyed to particles (trails) start over
    x.startOver.world(*this, true);
    setup = target;
    editedSinceSetup = wasEdited;
    // Back to the scene exactly as its file has it: nothing is unsaved. Any other set-up keeps
    // the changes that made it.
    if (asOnDisk()) dirty = false;
    x.edit.remember("restart");
    const bool asLoaded = target == loaded;
    x.notices.say(std::string("Restarted: back to ") +
                  (asLoaded ? "the scene as it opened" : "the set-up as Play last started it") +
                  " (" + std::to_string(world.size()) +
                  " particles, t = " + quantity(world.time(), "s") + ")");
}

void Document::handle(const cmd::Revert&, Context& x) {
    if (file.path) {
        openFile(file.path, x, "Reverted to");
        return;
    }
    // A built-in or new scene: as it was made.
    world = World(*loaded);
    setup = loaded;
    editedSinceSetup = false;
    dirty = false;
    ++generation;
    x.startOver.world(*this, true);
    x.edit.remember("revert");
    x.notices.say("Reverted to " + meta.name + " as it was made (it has no file)");
}

void Document::handle(const cmd::SetSceneText& c, Context& x) {
    if (c.name == meta.name && c.description == meta.description) return;
    const bool renamed = c.name != meta.name;
    meta.name = c.name;
    meta.description = c.description;
    x.notices.say(renamed ? "Title: " + (c.name.empty() ? std::string("(none)") : c.name)
                          : std::string("Description changed"));
    x.edit.userAction(renamed ? "rename scene" : "describe scene");
}

// ---------------------------------------------------------------------------------------------
// Saving.

std::filesystem::path Document::saveProposal(const SessionOptions& options) const {
    if (options.saveTo) return freeSavePath(*options.saveTo);
    const std::filesystem::path name = file.path ? file.path->filename() : sceneFileName(meta.name);
    return freeSavePath(options.saveFolder / name);
}

void Document::handle(const cmd::Save&, Context& x) {
    if (file.writable && file.path) {
        saveTo(*file.path, x);
        return;
    }
    handle(cmd::AskSaveAs{}, x);
}

void Document::handle(const cmd::AskSaveAs&, Context& x) {
    const bool quitAfter = dialog.kind == Dialog::Kind::Quit;
    closeDialog();
    x.tools.closePrompt();
    dialog.kind = Dialog::Kind::SaveAs;
    dialog.proposal = saveProposal(x.options);
    dialog.quitAfterSave = quitAfter;
    dialog.download = x.options.inPage;
    x.notices.say(std::string("Save as: type a file name, ") +
                  x.notices.key("Enter saves, Esc cancels", "then Save or Cancel") + " (" +
                  (dialog.download ? std::string("the browser downloads it")
                                   : "folder " + dialog.proposal.parent_path().string()) +
                  ")");
}

void Document::handle(const cmd::SaveAs& c, Context& x) {
    std::string why;
    const std::optional<std::filesystem::path> named =
        c.path.empty() ? std::nullopt : saveFileName(c.path, why);
    if (c.path.empty()) {
        dialog.error = "Save: type a file name first";
        x.notices.say(dialog.error, Notice::Level::Warning);
        return;
    }
    if (!named) {
        // The dialog and the panel's status line say so too, not the save before it.
        dialog.error = fileError = "Save: " + why;
        x.notices.say(fileError, Notice::Level::Warning);
        return;
    }
    std::filesystem::path path = *named;
    // A relative name is in the folder the dialog shows.
    if (path.is_relative() && dialog.kind == Dialog::Kind::SaveAs) {
        path = dialog.proposal.parent_path() / path;
    }
    std::error_code ec;
    // A download never replaces anything the user has: the browser names it anew.
    if (!c.overwrite && !x.options.inPage && std::filesystem::exists(path, ec)) {
        // Never a silent overwrite: the dialog asks.
        const bool quitAfter = dialog.quitAfterSave;
        if (dialog.kind != Dialog::Kind::SaveAs) dialog.proposal = path;
        dialog.kind = Dialog::Kind::SaveAs;
        dialog.quitAfterSave = quitAfter;
        dialog.replace = std::filesystem::absolute(path, ec).lexically_normal();
        x.notices.say(path.filename().string() + " exists: Replace it, or choose another name",
                      Notice::Level::Warning);
        return;
    }
    if (!saveTo(path, x)) {
        dialog.error = fileError;
        return;
    }
    const bool quitAfter = dialog.quitAfterSave;
    closeDialog();
    if (quitAfter) running = false;
}

bool Document::saveTo(const std::filesystem::path& path, Context& x) {
    try {
        const std::string saved = save(path);
        x.notices.say(x.options.inPage ? fmt("Saved %zu particles as %s", world.size(),
                                             path.filename().string().c_str())
                                       : saved);
        return true;
    } catch (const std::exception& e) {  // SaveError; the old file is intact
        fileError = std::string("Save failed: ") + e.what();
        x.notices.say(fileError, Notice::Level::Error);
        return false;
    }
}

// ---------------------------------------------------------------------------------------------
// Dialogs and leaving.

void Document::closeDialog() {
    dialog = Dialog{};
}

void Document::handle(const cmd::CloseDialog&, Context& x) {
    if (!dialog.open()) return;
    const bool quitting = dialog.kind == Dialog::Kind::Quit || dialog.quitAfterSave;
    closeDialog();
    x.notices.say(quitting ? "Quit cancelled" : "Cancelled");
}

void Document::handle(const cmd::Back&, Context& x) {
    if (dialog.open()) {
        handle(cmd::CloseDialog{}, x);
    } else if (x.view.helpShown()) {
        x.view.closeHelp();
    } else if (x.tools.prompt.active()) {
        x.tools.closePrompt();
        x.notices.say("Edit cancelled");
    } else if (x.options.inPage) {
        x.notices.say("Esc closes a dialog, the help or the edit prompt; nothing is open");
    } else {
        quit(x, true);
    }
}

void Document::handle(const cmd::Quit&, Context& x) {
    // While a dialog is open, closing the window again leaves the question standing.
    if (dialog.open()) return;
    quit(x, false);
}

void Document::quit(Context& x, bool ask) {
    if (!dirty && !ask) {
        running = false;
        return;
    }
    x.tools.closePrompt();
    dialog.kind = Dialog::Kind::Quit;
    dialog.unsaved = dirty;
    if (dirty) {
        x.notices.say("Unsaved changes to " + meta.name + ": Save, Discard or Cancel",
                      Notice::Level::Warning);
    } else {
        x.notices.say(std::string("Quit Particle Sandbox? ") +
                      x.notices.key("Enter quits, Esc stays", "Quit or Stay"));
    }
}

void Document::handle(const cmd::AnswerQuit& c, Context& x) {
    if (dialog.kind != Dialog::Kind::Quit) return;
    // Nothing unsaved: the question is only whether to quit; with unsaved changes only Save,
    // Discard and Cancel answer it.
    if (!dialog.unsaved && c.choice != cmd::AnswerQuit::Choice::Cancel) {
        closeDialog();
        running = false;
        return;
    }
    switch (c.choice) {
        case cmd::AnswerQuit::Choice::Save:
            if (file.writable && file.path) {
                closeDialog();
                if (saveTo(*file.path, x)) running = false;
            } else {
                handle(cmd::AskSaveAs{}, x);  // keeps quitAfterSave
            }
            return;
        case cmd::AnswerQuit::Choice::Discard:
            closeDialog();
            x.notices.log("Quit without saving");
            running = false;
            return;
        case cmd::AnswerQuit::Choice::Cancel:
            handle(cmd::CloseDialog{}, x);
            return;
        case cmd::AnswerQuit::Choice::Quit:
            return;
    }
}

}  // namespace psb::app
