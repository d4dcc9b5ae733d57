// particle-sim checks every file it will write before the run starts: a bad path costs no
// simulation, writes none of the other outputs and changes nothing that exists.

#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "cli_app.hpp"
#include "output_check.hpp"

namespace psb::cli {
namespace {

namespace fs = std::filesystem;

class OutputCheck : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("psb-output-check-" +
                std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    /// Runs the 6-particle preset for `duration` with `args` after it.
    int run(const std::string& duration, std::vector<std::string> args) {
        args.insert(args.begin(),
                    {"particle-sim", std::string(PSB_ASSETS_DIR) + "/scenes/01-original.json",
                     "--duration", duration});
        out_.str("");
        err_.str("");
        return runCli(args, out_, err_, false);
    }

    std::set<fs::path> listing() const {
        std::set<fs::path> names;
        for (const fs::directory_entry& e : fs::recursive_directory_iterator(dir_))
            names.insert(e.path().lexically_relative(dir_));
        return names;
    }

    std::string path(const std::string& name) const { return (dir_ / name).string(); }

    fs::path dir_;
    std::ostringstream out_, err_;
};

TEST_F(OutputCheck, AnOutputIntoAMissingFolderStopsTheRunBeforeAnyOutputIsWritten) {
    EXPECT_EQ(run("0.5", {"--timeseries", path("ts.csv"), "--save", path("no/such/final.json")}),
              kExitFailure);
    EXPECT_EQ(err_.str(), "particle-sim: error: --save: cannot write " +
                              path("no/such/final.json") + ": directory " + path("no/such") +
                              " does not exist\n");
    EXPECT_EQ(out_.str(), "") << "no report: the run did not happen";
    EXPECT_EQ(listing(), std::set<fs::path>{}) << "the time series was not written either";
}

TEST_F(OutputCheck, EveryOutputOptionIsCheckedAndNamedInTheMessage) {
    fs::create_directory(dir_ / "run-track.csv");  // where --track would write
    const struct {
        std::vector<std::string> args;
        std::string message;
    } cases[] = {
        {{"--report", path("missing/r.json")},
         "--report: cannot write " + path("missing/r.json") + ": directory " + path("missing") +
             " does not exist"},
        {{"--save", path("missing/s.json")},
         "--save: cannot write " + path("missing/s.json") + ": directory " + path("missing") +
             " does not exist"},
        {{"--timeseries", path("missing/t.csv")},
         "--timeseries: cannot write " + path("missing/t.csv") + ": directory " + path("missing") +
             " does not exist"},
        {{"--timeseries", path("run.csv"), "--track", "1"},
         "--track: cannot write " + path("run-track.csv") + ": a directory is in the way"},
        {{"--save", dir_.string()},
         "--save: cannot write " + dir_.string() + ": a directory is in the way"},
    };
    for (const auto& c : cases) {
        // 10^6 s of the preset is 6e7 steps: were the check after the run, this would not end.
        EXPECT_EQ(run("1e6", c.args), kExitFailure) << c.message;
        EXPECT_EQ(err_.str(), "particle-sim: error: " + c.message + "\n");
    }
    EXPECT_EQ(listing(), std::set<fs::path>{"run-track.csv"});
}

TEST_F(OutputCheck, TheCheckLeavesFilesThatAreThereAsTheyWere) {
    std::ofstream(dir_ / "ts.csv") << "an older time series";
    EXPECT_EQ(run("0.5", {"--timeseries", path("ts.csv"), "--report", path("no/r.json")}),
              kExitFailure);
    std::ifstream in(dir_ / "ts.csv");
    EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), "an older time series");
    EXPECT_EQ(listing(), std::set<fs::path>{"ts.csv"}) << "no temporary file left behind";
}

TEST_F(OutputCheck, TwoOptionsNamingOneFileAreACommandLineError) {
    EXPECT_EQ(run("0.5", {"--report", path("out.json"), "--save", path("./out.json")}), kExitUsage);
    EXPECT_EQ(err_.str(), "particle-sim: error: --report and --save name the same file, " +
                              path("./out.json") + "\n");
    // The time series and a report where --track would write.
    EXPECT_EQ(run("0.5",
                  {"--report", path("a-track.csv"), "--timeseries", path("a.csv"), "--track", "1"}),
              kExitUsage);
    EXPECT_EQ(err_.str(), "particle-sim: error: --report and --track name the same file, " +
                              path("a-track.csv") + "\n");
    EXPECT_EQ(listing(), std::set<fs::path>{});
}

TEST_F(OutputCheck, APipeIsWrittenIntoAndStaysAPipe) {
    // As --report /dev/null is (a pipe here, so that a build without this behaviour cannot
    // replace the machine's /dev/null when the test runs as root).
    const fs::path fifo = dir_ / "pipe";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    const int reader = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    ASSERT_GE(reader, 0);
    EXPECT_EQ(run("0.5", {"--report", fifo.string()}), kExitOk) << err_.str();
    std::string report(1 << 16, '\0');
    const ssize_t n = ::read(reader, report.data(), report.size());
    ::close(reader);
    report.resize(n > 0 ? static_cast<std::size_t>(n) : 0);
    EXPECT_NE(report.find("\"wall_collisions\""), std::string::npos) << report;
    EXPECT_TRUE(fs::is_fifo(fifo));
}

TEST(OutputsOf, ListsEveryFileTheRunWritesWithItsOption) {
    RunOptions o;
    o.report = "-";
    EXPECT_TRUE(outputsOf(o).empty()) << "'-' is standard output, not a file";
    o.report = "r.json";
    o.save = "s.json";
    o.timeseries = "runs/ts.csv";
    o.track = {1, 2};
    const std::vector<Output> out = outputsOf(o);
    ASSERT_EQ(out.size(), 4u);
    EXPECT_EQ(out[0].option, "--report");
    EXPECT_EQ(out[0].path, "r.json");
    EXPECT_EQ(out[1].option, "--save");
    EXPECT_EQ(out[2].option, "--timeseries");
    EXPECT_EQ(out[3].option, "--track");
    EXPECT_EQ(out[3].path, "runs/ts-track.csv");
}

}  // namespace
}  // namespace psb::cli
