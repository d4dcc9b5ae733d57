#pragma once
// The desktop program's settings file (settings_file.hpp) in the user's config folder, as the
// XDG Base Directory specification places it:
//   $XDG_CONFIG_HOME/particle-sandbox/settings.json   (~/.config/particle-sandbox/settings.json
//                                                      when XDG_CONFIG_HOME is unset or relative)
// read once at start, written atomically (a temporary file, then a rename: a crash half way
// leaves the old file) whenever a kept setting changes. A file that cannot be read or makes no
// sense is reported with its path and what is wrong, and ignored: the program starts with its
// defaults, never stops for it. --no-settings (and --bench) neither read nor write it; the
// tests point XDG_CONFIG_HOME at a temporary folder.

#include <filesystem>
#include <optional>
#include <string>

#include "platform/settings_file.hpp"

namespace psb::app {

/// The settings file for the environment's XDG_CONFIG_HOME and HOME (null when unset); nullopt
/// when neither gives an absolute folder.
[[nodiscard]] std::optional<std::filesystem::path> settingsPath(const char* xdgConfigHome,
                                                                const char* home);

class SettingsStore {
  public:
    explicit SettingsStore(std::filesystem::path file) : file_(std::move(file)) {}

    /// Reads the file over `view` (which the file's text is compared with from then on). A
    /// missing file reads as nothing; `problems` of the result name the file.
    [[nodiscard]] SettingsRead load(const ViewOptions& view);
    /// The file holds `view`'s settings (those load read, applied): nothing to write until
    /// they change.
    void keep(const ViewOptions& view) { kept_ = view; }
    /// Writes `view`'s kept settings when they differ from the file's. Returns what went wrong,
    /// naming the file, the first time a write fails (not again every change).
    [[nodiscard]] std::optional<std::string> save(const ViewOptions& view);

    [[nodiscard]] const std::filesystem::path& file() const { return file_; }

  private:
    std::filesystem::path file_;
    ViewOptions kept_;  ///< the settings as the file holds them (read or last written)
    bool failed_ = false;
};

}  // namespace psb::app
