#pragma once
// A test fixture with a fresh directory of its own under the system's temporary directory,
// removed after the test: for the tests that write scenes and screenshots.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include <unistd.h>

namespace psb::app {

class TempDirTest : public ::testing::Test {
  protected:
    /// `prefix` names the directory (prefix-PID), so parallel test binaries do not share one.
    explicit TempDirTest(std::string prefix) : prefix_(std::move(prefix)) {}

    void SetUp() override {
        dir_ =
            std::filesystem::temp_directory_path() / (prefix_ + "-" + std::to_string(::getpid()));
        std::filesystem::remove_all(dir_);
        std::filesystem::create_directories(dir_);
    }
    void TearDown() override { std::filesystem::remove_all(dir_); }

    std::string prefix_;
    std::filesystem::path dir_;
};

}  // namespace psb::app
