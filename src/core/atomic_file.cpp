// Atomic file replacement (POSIX): write a temporary file beside the target, fsync it, rename
// it over the target, fsync the directory. rename(2) within one file system is atomic, so a
// reader, or a crash, sees the old file or the new one; a failure at any point before the
// rename leaves the old file untouched.

#include <particle_sandbox/atomic_file.hpp>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <random>
#include <string>

#include <particle_sandbox/scene.hpp>

namespace psb {
namespace {

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& why) {
    throw SaveError("cannot save " + path.string() + ": " + why);
}

std::string errnoText(int err) {
    return std::strerror(err);
}

/// Closes the descriptor and removes the temporary file unless release() was called.
class TempFile {
  public:
    TempFile(int fd, std::filesystem::path path) : fd_(fd), path_(std::move(path)) {}
    TempFile(const TempFile&) = delete;
    TempFile& operator=(const TempFile&) = delete;
    ~TempFile() {
        if (fd_ >= 0) ::close(fd_);
        if (!released_) ::unlink(path_.c_str());
    }
    [[nodiscard]] int fd() const { return fd_; }
    int close() {
        const int r = ::close(fd_);
        fd_ = -1;
        return r;
    }
    void release() { released_ = true; }

  private:
    int fd_;
    std::filesystem::path path_;
    bool released_ = false;
};

}  // namespace

void writeFileAtomically(const std::filesystem::path& path, std::string_view contents) {
    if (path.empty()) fail(path, "empty path");
    const std::filesystem::path dir =
        path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
    std::error_code ec;
    const auto dirStatus = std::filesystem::status(dir, ec);
    if (!std::filesystem::exists(dirStatus))
        fail(path, "directory " + dir.string() + " does not exist");
    if (!std::filesystem::is_directory(dirStatus)) fail(path, dir.string() + " is not a directory");
    if (std::filesystem::is_directory(path, ec)) fail(path, "a directory is in the way");

    // A name that cannot collide with another writer: pid plus random bits, O_EXCL to be sure.
    std::random_device rd;
    std::string tmpName = ".";
    tmpName += path.filename().string();
    tmpName += ".tmp-";
    tmpName += std::to_string(::getpid());
    tmpName += '-';
    tmpName += std::to_string(rd());
    const std::filesystem::path tmp = dir / tmpName;
    const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
    if (fd < 0)
        fail(path,
             "cannot create a temporary file in " + dir.string() + " (" + errnoText(errno) + ")");
    TempFile file(fd, tmp);

    const char* data = contents.data();
    std::size_t left = contents.size();
    while (left > 0) {
        const ssize_t n = ::write(file.fd(), data, left);
        if (n < 0) {
            if (errno == EINTR) continue;
            fail(path, "write failed (" + errnoText(errno) + ")");
        }
        data += n;
        left -= static_cast<std::size_t>(n);
    }
    if (::fsync(file.fd()) != 0) fail(path, "fsync failed (" + errnoText(errno) + ")");
    // Keep the target's permissions if it exists (a scene the user made read-only for others
    // stays so); otherwise the 0644 above, less the umask.
    struct stat st {};
    if (::stat(path.c_str(), &st) == 0) ::fchmod(file.fd(), st.st_mode & 07777);
    if (file.close() != 0) fail(path, "close failed (" + errnoText(errno) + ")");
    if (::rename(tmp.c_str(), path.c_str()) != 0) {
        fail(path, "rename failed (" + errnoText(errno) + ")");
    }
    file.release();
    // Make the rename itself durable; failing here cannot undo it, so it is best effort.
    const int dfd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dfd >= 0) {
        ::fsync(dfd);
        ::close(dfd);
    }
}

}  // namespace psb
