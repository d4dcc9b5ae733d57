#pragma once
// The user's files in the browser (the web build only): a page reads no path on the user's
// computer and writes none. What the app writes in one folder of the page's memory file system
// (scenes saved, CSV tables, screenshots) is handed to the browser as a download, its own save
// dialog; a scene the user picks with the browser's file chooser is copied into that folder
// and arrives as an SDL_DROPFILE event with its path, which Input turns into OpenFile like any
// path. The page's half is web/index.html (psbAskForUpload, psbDownload).

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace psb::app {

/// The folder the app saves in, watched for files to download.
class DownloadFolder {
  public:
    explicit DownloadFolder(std::filesystem::path folder);

    [[nodiscard]] const std::filesystem::path& folder() const { return folder_; }
    /// Hands the browser every file the user saves (scenes, CSV tables, PNG screenshots) written
    /// in the folder since the last call (a file replaced by an atomic write counts as written);
    /// returns their names.
    std::vector<std::string> offerNew();
    /// Takes `file` as already offered (an upload written there by the page).
    void markSeen(const std::filesystem::path& file);

  private:
    struct Version {
        std::uint64_t inode = 0;
        std::uint64_t size = 0;
        std::int64_t mtime = 0;
        bool operator==(const Version&) const = default;
    };
    [[nodiscard]] static Version versionOf(const std::filesystem::path& file);

    std::filesystem::path folder_;
    std::map<std::string, Version> seen_;
};

/// Opens the browser's file chooser for a scene file; the page writes the file it gets into
/// `folder` and calls psb_web_uploaded() (browser_loop.cpp) with its path.
void askForUpload(const std::filesystem::path& folder);

}  // namespace psb::app
