// writeFileAtomically's check before the fact (atomicWriteProblem) and its writes into devices
// and pipes. What a save does when the system fails it midway is in scene_save_faults_test.cpp.

#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <optional>
#include <set>
#include <string>

#include <particle_sandbox/atomic_file.hpp>
#include <particle_sandbox/scene.hpp>

#include "test_util.hpp"

namespace psb {
namespace {

namespace fs = std::filesystem;
using test::readFile;
using test::TempDir;

std::set<fs::path> listing(const fs::path& dir) {
    std::set<fs::path> names;
    for (const fs::directory_entry& e : fs::directory_iterator(dir))
        names.insert(e.path().filename());
    return names;
}

/// What writeFileAtomically says after "cannot save PATH: ", or nullopt when it wrote.
std::optional<std::string> saveFailure(const fs::path& path) {
    try {
        writeFileAtomically(path, "new");
    } catch (const SaveError& e) {
        const std::string prefix = "cannot save " + path.string() + ": ";
        const std::string what = e.what();
        EXPECT_EQ(what.rfind(prefix, 0), 0u) << what;
        return what.substr(prefix.size());
    }
    return std::nullopt;
}

TEST(AtomicWriteProblem, NamesWhatWouldMakeTheWriteFailInTheWritesOwnWords) {
    const TempDir tmp("psb-atomic-check");
    const fs::path dir = tmp.path();
    std::ofstream(dir / "plain") << "a file, not a folder";
    fs::create_directory(dir / "folder");
    const struct {
        fs::path path;
        std::string problem;
    } cases[] = {
        {dir / "no" / "such" / "x.json",
         "directory " + (dir / "no" / "such").string() + " does not exist"},
        {dir / "plain" / "x.json", (dir / "plain").string() + " is not a directory"},
        {dir / "folder", "a directory is in the way"},
        {fs::path(), "empty path"},
    };
    for (const auto& c : cases) {
        EXPECT_EQ(atomicWriteProblem(c.path), c.problem) << c.path;
        EXPECT_EQ(saveFailure(c.path), c.problem) << c.path;
    }
}

TEST(AtomicWriteProblem, AFolderThatTakesNoNewFileIsFoundByTryingOne) {
    if (::geteuid() == 0) GTEST_SKIP() << "root creates files in a read-only folder";
    const TempDir tmp("psb-atomic-check");
    const fs::path dir = tmp.path() / "read-only";
    fs::create_directory(dir);
    fs::permissions(dir, fs::perms::owner_read | fs::perms::owner_exec);
    const std::string problem =
        "cannot create a temporary file in " + dir.string() + " (Permission denied)";
    EXPECT_EQ(atomicWriteProblem(dir / "x.json"), problem);
    EXPECT_EQ(saveFailure(dir / "x.json"), problem);
}

TEST(AtomicWriteProblem, CheckingChangesNothingAndLeavesNothingBehind) {
    const TempDir tmp("psb-atomic-check");
    const fs::path dir = tmp.path();
    std::ofstream(dir / "old.json") << "old contents";
    const std::set<fs::path> before = listing(dir);
    EXPECT_EQ(atomicWriteProblem(dir / "old.json"), std::nullopt);
    EXPECT_EQ(atomicWriteProblem(dir / "new.json"), std::nullopt);
    EXPECT_EQ(listing(dir), before) << "no temporary left, no new file made";
    EXPECT_EQ(readFile(dir / "old.json"), "old contents");
}

TEST(AtomicWriteProblem, ADeviceThatCanBeWrittenIsNoProblem) {
    EXPECT_EQ(atomicWriteProblem("/dev/null"), std::nullopt);
}

TEST(WriteFileAtomically, APipeIsWrittenInPlaceNotReplacedByAFile) {
    const TempDir tmp("psb-atomic-fifo");
    const fs::path fifo = tmp.path() / "pipe";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    // A reader that does not block: with it open, opening the pipe for writing does not wait.
    const int reader = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    ASSERT_GE(reader, 0);
    EXPECT_EQ(atomicWriteProblem(fifo), std::nullopt);
    writeFileAtomically(fifo, "through the pipe");
    char buf[64] = {};
    const ssize_t n = ::read(reader, buf, sizeof buf);
    ::close(reader);
    EXPECT_EQ(std::string(buf, n > 0 ? static_cast<std::size_t>(n) : 0), "through the pipe");
    EXPECT_TRUE(fs::is_fifo(fifo)) << "the pipe is still a pipe";
    EXPECT_EQ(listing(tmp.path()), std::set<fs::path>{"pipe"});
}

}  // namespace
}  // namespace psb
