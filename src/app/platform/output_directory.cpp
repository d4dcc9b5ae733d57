#include "platform/output_directory.hpp"

#include <system_error>

#include <unistd.h>

namespace psb::app {

std::filesystem::path directoryOf(const std::filesystem::path& path) {
    const std::filesystem::path parent = path.parent_path();
    return parent.empty() ? std::filesystem::path(".") : parent;
}

std::optional<std::string> outputDirectoryProblem(const std::filesystem::path& dir) {
    const std::filesystem::path d = dir.empty() ? std::filesystem::path(".") : dir;
    std::error_code ec;
    const auto status = std::filesystem::status(d, ec);
    if (!std::filesystem::exists(status)) return "directory " + d.string() + " does not exist";
    if (!std::filesystem::is_directory(status)) return d.string() + " is not a directory";
    // access() asks the kernel with the real ids, which is what open() will use here (the app
    // is never set-uid); permission bits alone would miss read-only mounts and ACLs.
    if (::access(d.c_str(), W_OK | X_OK) != 0) {
        return "directory " + d.string() + " is not writable";
    }
    return std::nullopt;
}

}  // namespace psb::app
