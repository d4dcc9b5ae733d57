#pragma once
// The page's settings (settings_file.hpp) in the browser's storage: IndexedDB, through
// Emscripten's IDBFS mounted on a folder of the page's file system. A broken file is ignored
// with a message and replaced.

#include <filesystem>
#include <string>
#include <vector>

#include "platform/settings_file.hpp"

namespace psb::app {

/// The file in the browser's storage: loaded once the storage is read (asynchronously, after
/// the program starts), saved when the options change.
class BrowserSettings {
  public:
    /// Mounts the storage at `folder` and starts reading it.
    explicit BrowserSettings(std::filesystem::path folder);

    /// Once the storage is read (then never again): the commands that restore the kept options
    /// over `view`, and in `problem` why a broken file was ignored. Nothing before that.
    [[nodiscard]] std::vector<Command> load(const ViewOptions& view, std::string& problem);
    /// Writes the kept options when they differ from the file's (after load).
    void save(const ViewOptions& view);

  private:
    std::filesystem::path file_;
    bool loaded_ = false;
    std::string written_;  ///< the file's text as last read or written
};

}  // namespace psb::app
