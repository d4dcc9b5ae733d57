// Start-up checks of the directories the app writes into.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "platform/output_directory.hpp"

namespace psb::app {
namespace {

namespace fs = std::filesystem;

fs::path scratch(const char* name) {
    const fs::path d =
        fs::temp_directory_path() / ("psb-outdir-" + std::to_string(::getpid())) / name;
    fs::remove_all(d);
    fs::create_directories(d);
    return d;
}

TEST(OutputDirectory, AWritableDirectoryHasNoProblem) {
    EXPECT_EQ(outputDirectoryProblem(scratch("ok")), std::nullopt);
    EXPECT_EQ(outputDirectoryProblem(""), std::nullopt);  // the current directory
}

TEST(OutputDirectory, AMissingDirectoryIsNamed) {
    const fs::path d = scratch("missing") / "no" / "such";
    EXPECT_EQ(outputDirectoryProblem(d), "directory " + d.string() + " does not exist");
}

TEST(OutputDirectory, AFileIsNotADirectory) {
    const fs::path f = scratch("file") / "plain.txt";
    std::ofstream(f) << "x";
    EXPECT_EQ(outputDirectoryProblem(f), f.string() + " is not a directory");
}

TEST(OutputDirectory, AReadOnlyDirectoryIsNotWritable) {
    if (::geteuid() == 0) GTEST_SKIP() << "root writes anywhere";
    const fs::path d = scratch("readonly");
    fs::permissions(d, fs::perms::owner_read | fs::perms::owner_exec);
    EXPECT_EQ(outputDirectoryProblem(d), "directory " + d.string() + " is not writable");
    fs::permissions(d, fs::perms::owner_all);
}

TEST(OutputDirectory, DirectoryOfABareFileNameIsTheCurrentOne) {
    EXPECT_EQ(directoryOf("save.json"), fs::path("."));
    EXPECT_EQ(directoryOf("out/save.json"), fs::path("out"));
}

}  // namespace
}  // namespace psb::app
