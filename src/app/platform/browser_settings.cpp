#include "platform/browser_settings.hpp"

#include <exception>
#include <fstream>
#include <sstream>

#include <emscripten.h>
#include <particle_sandbox/atomic_file.hpp>

// The page's storage (Emscripten's IDBFS over IndexedDB).
// clang-format off
EM_JS(void, psb_js_mount_settings, (const char* folder), {
    const path = UTF8ToString(folder);
    Module.psbSettingsRead = false;
    try {
        FS.mkdir(path);
        FS.mount(IDBFS, {}, path);
    } catch (e) {
        console.warn("No storage for the settings: " + e);
        Module.psbSettingsRead = true;
        return;
    }
    FS.syncfs(true, (err) => {
        if (err) console.warn("The settings could not be read from the browser's storage: " + err);
        Module.psbSettingsRead = true;
    });
});
EM_JS(int, psb_js_settings_read, (), {
    return Module.psbSettingsRead ? 1 : 0;
});
EM_JS(void, psb_js_persist_settings, (), {
    FS.syncfs(false, (err) => {
        if (err) console.warn("The settings could not be stored: " + err);
    });
});
// clang-format on

namespace psb::app {

BrowserSettings::BrowserSettings(std::filesystem::path folder) : file_(folder / "settings.json") {
    psb_js_mount_settings(folder.c_str());
}

std::vector<Command> BrowserSettings::load(const ViewOptions& view, std::string& problem) {
    if (loaded_ || psb_js_settings_read() == 0) return {};
    loaded_ = true;
    std::ifstream in(file_);
    if (!in) {
        written_ = settingsText(view);  // none yet: the defaults are not written until changed
        return {};
    }
    std::stringstream text;
    text << in.rdbuf();
    written_ = text.str();
    try {
        SettingsRead read = readSettings(written_, view);
        for (const std::string& p : read.problems)
            problem += (problem.empty() ? "" : "; ") + p;
        if (!problem.empty())
            problem = "The settings kept in this browser: " + problem + " (left out)";
        return std::move(read.commands);
    } catch (const std::exception& e) {
        problem = "The settings kept in this browser were ignored (" + std::string(e.what()) +
                  ") and replaced by the defaults";
        written_.clear();
        return {};
    }
}

void BrowserSettings::save(const ViewOptions& view) {
    if (!loaded_) return;
    std::string text = settingsText(view);
    if (text == written_) return;
    try {
        writeFileAtomically(file_, text);
        written_ = std::move(text);
        psb_js_persist_settings();
    } catch (const std::exception&) {
        written_ = std::move(text);  // not again every frame; the storage said why in the console
    }
}

}  // namespace psb::app
