// Atomic file replacement (POSIX): write a temporary file beside the target, fsync it, rename
// it over the target, fsync the directory. rename(2) within one file system is atomic, so a
// reader, or a crash, sees the old file or the new one; a failure at any point before the
// rename leaves the old file untouched.
//
// A process killed while writing leaves nothing behind: where the file system has O_TMPFILE
// (Linux: ext4, xfs, btrfs, tmpfs) the contents are written to a file with no name, which is
// given its temporary name (linkat) only once it is complete and flushed, just before the
// rename. Elsewhere the temporary file has its name from the start, and a kill while writing
// leaves it; so every save first removes the temporaries that earlier saves of the same file
// left behind, those whose process (its id is in the name) no longer runs.
//
// A device or a pipe (/dev/null, /dev/stdout, a FIFO) is not a file to replace: renaming over
// it would put a regular file in its place (as root, /dev/null itself), so it is written in
// place, as a shell's `>` would.

#include <particle_sandbox/atomic_file.hpp>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <signal.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <random>
#include <string>
#include <vector>

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
        if (!released_ && !path_.empty()) ::unlink(path_.c_str());
    }
    /// An unnamed file (O_TMPFILE, path empty) was given `path`.
    void named(std::filesystem::path path) { path_ = std::move(path); }
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

/// The prefix of every temporary name a save of `target` uses: ".NAME.tmp-".
std::string tempPrefix(const std::filesystem::path& target) {
    std::string prefix = ".";  // appended, not '+': GCC 12 warns wrongly on "." + string
    prefix += target.filename().string();
    prefix += ".tmp-";
    return prefix;
}

/// Removes the temporaries of `target` in `dir` whose writer (the process id after the prefix)
/// is gone: what a save killed while writing left behind.
void removeStaleTemporaries(const std::filesystem::path& dir, const std::filesystem::path& target) {
    const std::string prefix = tempPrefix(target);
    std::error_code ec;
    std::vector<std::filesystem::path> stale;
    for (std::filesystem::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (name.compare(0, prefix.size(), prefix) != 0) continue;
        const std::string rest = name.substr(prefix.size());
        const std::size_t dash = rest.find('-');
        if (dash == 0 || dash == std::string::npos) continue;
        if (rest.find_first_not_of("0123456789") != dash) continue;  // not ours: PID-RANDOM
        errno = 0;
        const long pid = std::strtol(rest.c_str(), nullptr, 10);
        if (pid <= 0 || errno != 0) continue;
        if (pid != ::getpid() && ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH)
            stale.push_back(it->path());
    }
    for (const std::filesystem::path& p : stale)
        std::filesystem::remove(p, ec);
}

std::filesystem::path directoryOf(const std::filesystem::path& path) {
    return path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
}

/// Why a file cannot be renamed into place at `path`, as far as can be told without creating
/// anything.
std::optional<std::string> placeProblem(const std::filesystem::path& path) {
    if (path.empty()) return "empty path";
    const std::filesystem::path dir = directoryOf(path);
    std::error_code ec;
    const auto dirStatus = std::filesystem::status(dir, ec);
    if (!std::filesystem::exists(dirStatus)) return "directory " + dir.string() + " does not exist";
    if (!std::filesystem::is_directory(dirStatus)) return dir.string() + " is not a directory";
    if (std::filesystem::is_directory(path, ec)) return "a directory is in the way";
    return std::nullopt;
}

/// A path that exists and is neither a regular file nor a directory: a device or a pipe,
/// written in place (see the top of this file). stat follows links, so /dev/stdout counts.
bool writtenInPlace(const std::filesystem::path& path) {
    struct stat st {};
    return ::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode) && !S_ISDIR(st.st_mode);
}

/// A new temporary file in `dir` for `target`, open for writing: unnamed where the file system
/// can (`unnamed` set), else named `tmp` (created exclusively). -1 with errno on failure.
int openTemporary(const std::filesystem::path& dir, const std::filesystem::path& tmp,
                  bool& unnamed) {
    unnamed = true;
#ifdef O_TMPFILE
    int fd = ::open(dir.c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0644);
#else
    int fd = -1;
#endif
    if (fd < 0) {
        unnamed = false;
        fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
    }
    return fd;
}

/// A name that cannot collide with another writer: pid plus random bits (O_EXCL makes sure).
std::filesystem::path temporaryName(const std::filesystem::path& dir,
                                    const std::filesystem::path& target) {
    std::random_device rd;
    return dir / (tempPrefix(target) + std::to_string(::getpid()) + '-' + std::to_string(rd()));
}

void writeAll(const std::filesystem::path& path, int fd, std::string_view contents) {
    const char* data = contents.data();
    std::size_t left = contents.size();
    while (left > 0) {
        const ssize_t n = ::write(fd, data, left);
        if (n < 0) {
            if (errno == EINTR) continue;
            fail(path, "write failed (" + errnoText(errno) + ")");
        }
        data += n;
        left -= static_cast<std::size_t>(n);
    }
}

void writeInPlace(const std::filesystem::path& path, std::string_view contents) {
    const int fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
    if (fd < 0) fail(path, "cannot open it for writing (" + errnoText(errno) + ")");
    TempFile file(fd, {});  // only closes the descriptor: no path, nothing to remove
    writeAll(path, file.fd(), contents);
    if (file.close() != 0) fail(path, "close failed (" + errnoText(errno) + ")");
}

}  // namespace

std::optional<std::string> atomicWriteProblem(const std::filesystem::path& path) {
    if (!path.empty() && writtenInPlace(path)) {
        if (::access(path.c_str(), W_OK) != 0)
            return "cannot open it for writing (" + errnoText(errno) + ")";
        return std::nullopt;
    }
    if (auto problem = placeProblem(path)) return problem;
    const std::filesystem::path dir = directoryOf(path);
    const std::filesystem::path tmp = temporaryName(dir, path);
    bool unnamed = true;
    const int fd = openTemporary(dir, tmp, unnamed);
    if (fd < 0) {
        return "cannot create a temporary file in " + dir.string() + " (" + errnoText(errno) + ")";
    }
    ::close(fd);
    if (!unnamed) ::unlink(tmp.c_str());
    return std::nullopt;
}

void writeFileAtomically(const std::filesystem::path& path, std::string_view contents) {
    if (!path.empty() && writtenInPlace(path)) {
        writeInPlace(path, contents);
        return;
    }
    if (auto problem = placeProblem(path)) fail(path, *problem);
    const std::filesystem::path dir = directoryOf(path);
    const std::filesystem::path tmp = temporaryName(dir, path);
    // Unnamed until complete where the file system can (see the top of this file).
    bool unnamed = true;
    const int fd = openTemporary(dir, tmp, unnamed);
    if (fd < 0)
        fail(path,
             "cannot create a temporary file in " + dir.string() + " (" + errnoText(errno) + ")");
    TempFile file(fd, unnamed ? std::filesystem::path() : tmp);
    // After the open, so that the temporary has the lowest free descriptor (the fault tests
    // rely on it) and is never taken for a stale one (it has no name yet, or this process's id).
    removeStaleTemporaries(dir, path);

    writeAll(path, file.fd(), contents);
    if (::fsync(file.fd()) != 0) fail(path, "fsync failed (" + errnoText(errno) + ")");
    // Keep the target's permissions if it exists (a scene the user made read-only for others
    // stays so); otherwise the 0644 above, less the umask.
    struct stat st {};
    if (::stat(path.c_str(), &st) == 0) ::fchmod(file.fd(), st.st_mode & 07777);
    if (unnamed) {
        // Give the complete file its temporary name; a kill from here on leaves a whole file
        // under that name, which the next save removes.
        const std::string self = "/proc/self/fd/" + std::to_string(file.fd());
        if (::linkat(AT_FDCWD, self.c_str(), AT_FDCWD, tmp.c_str(), AT_SYMLINK_FOLLOW) != 0)
            fail(path, "cannot name the temporary file (" + errnoText(errno) + ")");
        file.named(tmp);
    }
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
