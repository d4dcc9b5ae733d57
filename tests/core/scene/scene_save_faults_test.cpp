// A save that the system fails at each step — the disk fills during write(2), fsync(2) reports
// the delayed ENOSPC or EIO of a full or failing disk, close(2) reports a deferred error,
// rename(2) fails — says why and leaves the old file intact with no temporary file behind.
//
// A real full disk needs a small file system, and making one needs mount(2). Instead each case
// runs saveScene in a child process that has installed a seccomp filter making exactly one
// system call fail with the chosen errno (on the temporary file's descriptor, or on any path);
// the kernel then returns that error to the real code path, as a full disk would. This works as
// root and in containers (seccomp needs no privilege once no_new_privs is set). The child reports
// the SaveError message through shared memory, so it makes no system call after the save.

#include <gtest/gtest.h>

#include <signal.h>
#include <sys/mman.h>
#include <sys/prctl.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#if defined(__linux__) && defined(__x86_64__)
#include <linux/audit.h>
#include <linux/filter.h>
#include <linux/seccomp.h>
#define PSB_HAVE_SECCOMP 1
#endif

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstddef>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <particle_sandbox/atomic_file.hpp>
#include <particle_sandbox/presets.hpp>
#include <particle_sandbox/scene.hpp>

#include "test_util.hpp"

namespace psb {
namespace {

namespace fs = std::filesystem;
using test::readFile;
using test::TempDir;

/// The temporary files a save of `target` may leave beside it (".NAME.tmp-PID-RANDOM").
std::vector<fs::path> temporariesOf(const fs::path& target) {
    std::vector<fs::path> found;
    const std::string prefix = "." + target.filename().string() + ".tmp-";
    for (const fs::directory_entry& e : fs::directory_iterator(target.parent_path()))
        if (e.path().filename().string().rfind(prefix, 0) == 0) found.push_back(e.path());
    return found;
}

TEST(SaveKilled, ASaveKilledAtAnyMomentLeavesTheOldOrTheNewFileAndNoTemporaryAfterTheNextSave) {
    // A child saves 32 MiB over and over; it is killed (SIGKILL, no clean-up possible) at a
    // different moment each time. The file is then whole, the old contents or the new, and the
    // next save leaves no temporary file in the folder, whatever the kills left.
    TempDir dir("psb-save-kill");
    const fs::path file = dir.path() / "big.json";
    const std::string old(1 << 20, 'o'), next(std::size_t{32} << 20, 'n');
    writeFileAtomically(file, old);
    int leftAfterKill = 0;
    for (int trial = 0; trial < 12; ++trial) {
        const pid_t pid = ::fork();
        ASSERT_GE(pid, 0);
        if (pid == 0) {
            for (;;)
                writeFileAtomically(file, next);
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(3 + 11 * trial));
        ::kill(pid, SIGKILL);
        int status = 0;
        ::waitpid(pid, &status, 0);
        ASSERT_TRUE(WIFSIGNALED(status));
        const std::string now = readFile(file);
        EXPECT_TRUE(now == old || now == next)
            << "trial " << trial << ": a torn file of " << now.size() << " bytes";
        leftAfterKill += static_cast<int>(temporariesOf(file).size());
    }
    writeFileAtomically(file, old);
    EXPECT_TRUE(temporariesOf(file).empty()) << temporariesOf(file).size() << " temporaries left ("
                                             << leftAfterKill << " seen right after the kills)";
    EXPECT_EQ(readFile(file), old);
    // Where the file system has O_TMPFILE a kill while writing leaves nothing even before the
    // next save: a name is given only to a complete file, an instant before the rename.
    RecordProperty("temporaries_seen_right_after_kills", leftAfterKill);
}

TEST(SaveKilled, ASaveRemovesOnlyTheTemporariesWhoseWriterIsGone) {
    TempDir dir("psb-save-stale");
    const fs::path file = dir.path() / "scene.json";
    // A process that has ended: its id names no process now.
    const pid_t gone = ::fork();
    ASSERT_GE(gone, 0);
    if (gone == 0) ::_exit(0);
    ::waitpid(gone, nullptr, 0);
    const fs::path stale = dir.path() / (".scene.json.tmp-" + std::to_string(gone) + "-42");
    const fs::path alive = dir.path() / ".scene.json.tmp-1-42";  // init: another writer, live
    const fs::path other = dir.path() / (".other.json.tmp-" + std::to_string(gone) + "-42");
    const fs::path notOurs = dir.path() / ".scene.json.tmp-notes";
    for (const fs::path& p : {stale, alive, other, notOurs})
        std::ofstream(p) << "{";
    writeFileAtomically(file, "{}");
    EXPECT_FALSE(fs::exists(stale)) << "a dead writer's temporary is left";
    EXPECT_TRUE(fs::exists(alive)) << "a live writer's temporary was removed";
    EXPECT_TRUE(fs::exists(other)) << "another file's temporary was removed";
    EXPECT_TRUE(fs::exists(notOurs)) << "a file not named as our temporaries was removed";
    EXPECT_EQ(readFile(file), "{}");
}

#ifdef PSB_HAVE_SECCOMP

/// Installs a filter under which the listed system calls fail with `err` when their first
/// argument equals `fd`, or, with fd < 0, when it is above 2 (a path pointer, AT_FDCWD);
/// everything else is allowed. Returns false if the kernel refuses the filter.
bool failSyscalls(std::initializer_list<long> calls, int err, int fd) {
    std::vector<sock_filter> f;
    auto stmt = [&](std::uint16_t code, std::uint32_t k) { f.push_back(BPF_STMT(code, k)); };
    auto jump = [&](std::uint16_t code, std::uint32_t k, std::uint8_t jt, std::uint8_t jf) {
        f.push_back(BPF_JUMP(code, k, jt, jf));
    };
    stmt(BPF_LD | BPF_W | BPF_ABS, offsetof(seccomp_data, arch));
    jump(BPF_JMP | BPF_JEQ | BPF_K, AUDIT_ARCH_X86_64, 1, 0);
    stmt(BPF_RET | BPF_K, SECCOMP_RET_ALLOW);
    stmt(BPF_LD | BPF_W | BPF_ABS, offsetof(seccomp_data, nr));
    for (const long nr : calls) {
        // Matching call: go on to the argument test; else try the next call.
        jump(BPF_JMP | BPF_JEQ | BPF_K, static_cast<std::uint32_t>(nr), 0, 4);
        stmt(BPF_LD | BPF_W | BPF_ABS, offsetof(seccomp_data, args[0]));  // low 32 bits
        if (fd >= 0) {
            jump(BPF_JMP | BPF_JEQ | BPF_K, static_cast<std::uint32_t>(fd), 1, 0);
        } else {
            jump(BPF_JMP | BPF_JGT | BPF_K, 2, 1, 0);  // unsigned: AT_FDCWD (-100) is above 2
        }
        stmt(BPF_RET | BPF_K, SECCOMP_RET_ALLOW);
        stmt(BPF_RET | BPF_K, SECCOMP_RET_ERRNO | (static_cast<std::uint32_t>(err) & 0xffff));
    }
    stmt(BPF_RET | BPF_K, SECCOMP_RET_ALLOW);
    sock_fprog prog{static_cast<unsigned short>(f.size()), f.data()};
    if (::prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) != 0) return false;
    return ::syscall(SYS_seccomp, SECCOMP_SET_MODE_FILTER, 0, &prog) == 0;
}

/// Result of a save run in a child under the filter.
struct Outcome {
    bool filterInstalled = false;
    bool threw = false;
    std::string message;
};

/// Which descriptor a call's first argument must be for the fault to hit.
enum class Target {
    TemporaryFile,  ///< the descriptor the save will open next (write, fsync, close)
    AnyPath,        ///< calls that take a path or AT_FDCWD first (open, rename)
};

Outcome saveUnderFault(const Scene& scene, const fs::path& file, std::initializer_list<long> calls,
                       int err, Target target) {
    struct Shared {
        int state;  // 0 nothing, 1 no filter, 2 saved, 3 SaveError
        char message[1024];
    };
    void* mem =
        ::mmap(nullptr, sizeof(Shared), PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0);
    if (mem == MAP_FAILED) return {};
    auto* shared = new (mem) Shared{};
    const pid_t pid = ::fork();
    if (pid == 0) {
        // The save's temporary file gets the lowest free descriptor. Hitting only that one
        // keeps the sanitizers' own pipes and files working (ASan probes memory by writing it
        // to a pipe, and stops if that write fails with anything but EFAULT).
        int fd = -1;
        if (target == Target::TemporaryFile) {
            fd = ::dup(0);
            ::close(fd);
        }
        if (!failSyscalls(calls, err, fd)) {
            shared->state = 1;
            ::_exit(0);
        }
        try {
            saveScene(scene, file);
            shared->state = 2;
        } catch (const SaveError& e) {
            std::strncpy(shared->message, e.what(), sizeof shared->message - 1);
            shared->state = 3;
        }
        ::_exit(0);
    }
    int status = 0;
    ::waitpid(pid, &status, 0);
    Outcome o;
    o.filterInstalled = shared->state >= 2;
    o.threw = shared->state == 3;
    o.message = shared->message;
    ::munmap(mem, sizeof(Shared));
    return o;
}

class SceneSaveFault : public testing::Test {
  protected:
    void SetUp() override {
        file_ = dir_.path() / "scene.json";
        saveScene(defaultScene(), file_);
        before_ = readFile(file_);
        next_ = defaultScene();
        next_.name = "must not be written";
    }

    /// Saves under the fault and checks the message, the old file and the directory.
    void expectFailure(std::initializer_list<long> calls, int err, const std::string& why,
                       Target target = Target::TemporaryFile) {
        const Outcome o = saveUnderFault(next_, file_, calls, err, target);
        if (!o.filterInstalled) GTEST_SKIP() << "the kernel refused a seccomp filter";
        ASSERT_TRUE(o.threw) << "the save succeeded although it could not";
        EXPECT_EQ(o.message, "cannot save " + file_.string() + ": " + why);
        EXPECT_EQ(readFile(file_), before_) << "the old file changed";
        EXPECT_EQ(std::distance(fs::directory_iterator(dir_.path()), fs::directory_iterator{}), 1)
            << "a temporary file was left behind";
    }

    TempDir dir_{"psb-save-fault"};
    fs::path file_;
    std::string before_;
    Scene next_;
};

TEST_F(SceneSaveFault, ADiskThatFillsDuringTheWriteLeavesTheOldFile) {
    expectFailure({SYS_write}, ENOSPC, "write failed (No space left on device)");
}

TEST_F(SceneSaveFault, ADiskFullReportedOnlyAtFsyncLeavesTheOldFile) {
    // Delayed allocation (ext4, XFS) and network file systems report ENOSPC here.
    expectFailure({SYS_fsync}, ENOSPC, "fsync failed (No space left on device)");
}

TEST_F(SceneSaveFault, AnIoErrorAtFsyncLeavesTheOldFile) {
    expectFailure({SYS_fsync}, EIO, "fsync failed (Input/output error)");
}

TEST_F(SceneSaveFault, AnErrorDeferredToCloseLeavesTheOldFile) {
    expectFailure({SYS_close}, EIO, "close failed (Input/output error)");
}

TEST_F(SceneSaveFault, ARenameThatFailsLeavesTheOldFileAndRemovesTheTemporary) {
    expectFailure({SYS_rename, SYS_renameat, SYS_renameat2}, ENOSPC,
                  "rename failed (No space left on device)", Target::AnyPath);
}

TEST_F(SceneSaveFault, AFullDirectoryThatTakesNoNewFileIsReported) {
    // Creating the temporary needs a directory entry, which a full disk may refuse.
    expectFailure(
        {SYS_open, SYS_openat}, ENOSPC,
        "cannot create a temporary file in " + dir_.path().string() + " (No space left on device)",
        Target::AnyPath);
}

#else

TEST(SceneSaveFault, NeedsSeccompOnLinuxX86_64) {
    GTEST_SKIP() << "fault injection by seccomp is written for Linux on x86-64";
}

#endif

}  // namespace
}  // namespace psb
