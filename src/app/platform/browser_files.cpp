#include "platform/browser_files.hpp"

#include <sys/stat.h>

#include <system_error>
#include <utility>

#include <emscripten.h>

// The page's functions (web/index.html), called if it has them.
// clang-format off
EM_JS(void, psb_js_download, (const char* path), {
    if (typeof psbDownload === "function") psbDownload(UTF8ToString(path));
});
EM_JS(void, psb_js_ask_for_upload, (const char* folder), {
    if (typeof psbAskForUpload === "function") psbAskForUpload(UTF8ToString(folder));
});
// clang-format on

namespace psb::app {

namespace {

bool userFile(const std::filesystem::path& file) {
    const std::string ext = file.extension().string();
    return ext == ".json" || ext == ".csv" || ext == ".png";
}

}  // namespace

DownloadFolder::DownloadFolder(std::filesystem::path folder) : folder_(std::move(folder)) {
    std::error_code ec;
    std::filesystem::create_directories(folder_, ec);
}

DownloadFolder::Version DownloadFolder::versionOf(const std::filesystem::path& file) {
    struct stat st {};
    if (::stat(file.c_str(), &st) != 0) return {};
    return {static_cast<std::uint64_t>(st.st_ino), static_cast<std::uint64_t>(st.st_size),
            static_cast<std::int64_t>(st.st_mtime)};
}

void DownloadFolder::markSeen(const std::filesystem::path& file) {
    seen_[file.string()] = versionOf(file);
}

std::vector<std::string> DownloadFolder::offerNew() {
    std::vector<std::string> offered;
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(folder_, ec)) {
        const std::filesystem::path& file = entry.path();
        if (!entry.is_regular_file(ec) || !userFile(file)) continue;
        const Version v = versionOf(file);
        auto [it, added] = seen_.try_emplace(file.string(), v);
        if (!added && it->second == v) continue;
        it->second = v;
        psb_js_download(file.c_str());
        offered.push_back(file.filename().string());
    }
    return offered;
}

void askForUpload(const std::filesystem::path& folder) {
    psb_js_ask_for_upload(folder.c_str());
}

}  // namespace psb::app
