#include "platform/settings_store.hpp"

#include <exception>
#include <fstream>
#include <iterator>

#include <particle_sandbox/atomic_file.hpp>

namespace psb::app {

std::optional<std::filesystem::path> settingsPath(const char* xdgConfigHome, const char* home) {
    // The specification: a relative XDG_CONFIG_HOME is invalid and ignored.
    if (xdgConfigHome != nullptr && std::filesystem::path(xdgConfigHome).is_absolute()) {
        return std::filesystem::path(xdgConfigHome) / "particle-sandbox" / "settings.json";
    }
    if (home != nullptr && std::filesystem::path(home).is_absolute()) {
        return std::filesystem::path(home) / ".config" / "particle-sandbox" / "settings.json";
    }
    return std::nullopt;
}

SettingsRead SettingsStore::load(const ViewOptions& view) {
    kept_ = view;
    std::error_code ec;
    if (!std::filesystem::exists(file_, ec)) return {};
    const std::string where = "Settings file " + file_.string();
    std::ifstream in(file_, std::ios::binary);
    if (!in || std::filesystem::is_directory(file_, ec)) {
        return {{}, {where + " ignored: it cannot be read (the defaults are used)"}};
    }
    const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    try {
        SettingsRead read = readSettings(text, view);
        for (std::string& p : read.problems)
            p = where + ": " + p + " (left out)";
        return read;
    } catch (const std::exception& e) {
        return {{},
                {where + " ignored: " + e.what() +
                 " (the defaults are used; a setting changed writes it again)"}};
    }
}

std::optional<std::string> SettingsStore::save(const ViewOptions& view) {
    if (!keptSettingsDiffer(view, kept_)) return std::nullopt;
    kept_ = view;  // a failed write is not tried again until the next change
    try {
        std::filesystem::create_directories(file_.parent_path());
        writeFileAtomically(file_, settingsText(view));
        failed_ = false;
        return std::nullopt;
    } catch (const std::exception& e) {
        if (failed_) return std::nullopt;
        failed_ = true;
        return "The settings could not be kept in " + file_.string() + ": " + e.what();
    }
}

}  // namespace psb::app
