// particle-sim --track: the chosen particles' paths beside the time series, with the app's
// trajectory columns; bad lists refused before any step.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cli_app.hpp"
#include "run_options.hpp"
#include "time_series_csv.hpp"

namespace psb::cli {
namespace {

namespace fs = std::filesystem;

/// Two discs heading for each other along y = 5 in a 10 m box without walls: 1 kg at 2 m/s and
/// 3 kg at -1 m/s; they meet at t = 2/3 s and leave at -2.5 and +0.5 m/s (e = 1).
constexpr const char* kTwoBalls = R"({"version": 1,
    "world": {"width": 10, "height": 10, "walls": false, "restitution": 1},
    "solver": {"dt": 0.01, "mode": "exact"},
    "particles": [
        {"x": 3, "y": 5, "vx": 2, "vy": 0, "mass": 1, "radius": 0.5},
        {"x": 6, "y": 5, "vx": -1, "vy": 0, "mass": 3, "radius": 0.5}]})";

class Track : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("psb-track-" +
                std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
        std::ofstream(dir_ / "balls.json") << kTwoBalls;
    }
    void TearDown() override { fs::remove_all(dir_); }

    int run(std::vector<std::string> args) {
        args.insert(args.begin(), {"particle-sim", (dir_ / "balls.json").string()});
        out_.str("");
        err_.str("");
        return runCli(args, out_, err_, false);
    }

    static std::vector<std::vector<std::string>> read(const fs::path& p) {
        std::ifstream in(p);
        std::vector<std::vector<std::string>> rows;
        for (std::string line; std::getline(in, line);) {
            std::vector<std::string> row;
            std::stringstream ss(line);
            for (std::string cell; std::getline(ss, cell, ',');)
                row.push_back(cell);
            rows.push_back(row);
        }
        return rows;
    }

    fs::path dir_;
    std::ostringstream out_, err_;
};

TEST_F(Track, WritesEachChosenParticleAtEachTimeSeriesRow) {
    const fs::path ts = dir_ / "run.csv";
    ASSERT_EQ(run({"--duration", "1", "--timeseries", ts.string(), "--timeseries-every", "25",
                   "--track", "2,1"}),
              kExitOk)
        << err_.str();
    EXPECT_EQ(trackPath(ts), dir_ / "run-track.csv");
    const auto rows = read(dir_ / "run-track.csv");
    ASSERT_EQ(rows.size(), 1u + 5u * 2u) << "t = 0, 0.25, 0.5, 0.75, 1 for two particles";
    EXPECT_EQ(rows[0], (std::vector<std::string>{"time_s", "particle", "x_m", "y_m", "vx_m_per_s",
                                                 "vy_m_per_s"}));
    EXPECT_EQ(rows[1], (std::vector<std::string>{"0", "2", "6", "5", "-1", "0"}));
    EXPECT_EQ(rows[2], (std::vector<std::string>{"0", "1", "3", "5", "2", "0"}));
    EXPECT_EQ(rows[3][0], "0.25") << "a clean time, not 0.25000000000000006";
    // After the collision (t = 2/3 s): the textbook velocities, -2.5 and +0.5 m/s.
    EXPECT_EQ(rows[9][0], "1");
    EXPECT_NEAR(std::stod(rows[9][4]), 0.5, 1e-12);    // particle 2
    EXPECT_NEAR(std::stod(rows[10][4]), -2.5, 1e-12);  // particle 1
    // The time series has its rows at the same instants.
    EXPECT_EQ(read(ts).size(), 6u);
}

TEST_F(Track, BadListsAreRefusedNamingWhatIsWrong) {
    const std::string ts = (dir_ / "run.csv").string();
    EXPECT_EQ(run({"--duration", "1", "--timeseries", ts, "--track", "1,7"}), kExitUsage);
    EXPECT_NE(err_.str().find("--track: no particle 7: the scene has 2 particles, numbered 1 to 2"),
              std::string::npos)
        << err_.str();
    EXPECT_FALSE(fs::exists(dir_ / "run.csv")) << "refused before any file is written";
    EXPECT_EQ(run({"--duration", "1", "--track", "1"}), kExitUsage);
    EXPECT_NE(err_.str().find("--track: needs --timeseries PATH"), std::string::npos);
    EXPECT_EQ(run({"--duration", "1", "--timeseries", ts, "--track", "1,1"}), kExitUsage);
    EXPECT_NE(err_.str().find("--track: particle 1 is listed twice"), std::string::npos);
    EXPECT_EQ(run({"--duration", "1", "--timeseries", ts, "--track", "a"}), kExitUsage);
    EXPECT_NE(err_.str().find("--track: expected an integer, got 'a'"), std::string::npos);
}

TEST(TrackList, NumbersCountFromOneInTheHelpAndTheMessages) {
    std::string help;
    try {
        (void)parseRunOptions({"particle-sim", "--help"});
    } catch (const HelpRequested& h) {
        help = h.what();
    }
    EXPECT_EQ(help.find("indices"), std::string::npos) << "numbers are not 0-based indices";
    EXPECT_NE(help.find("1 for the first"), std::string::npos) << help;
    try {
        (void)parseTrackList("1,,2");
        ADD_FAILURE() << "accepted an empty item";
    } catch (const UsageError& e) {
        EXPECT_STREQ(e.what(),
                     "--track: an empty item in '1,,2' (particle numbers separated by commas, e.g. "
                     "1,4)");
    }
}

TEST(TrackList, ParsesNumbersAndRefusesEverythingElse) {
    EXPECT_EQ(parseTrackList("1"), (std::vector<std::uint32_t>{1}));
    EXPECT_EQ(parseTrackList("5,2,17"), (std::vector<std::uint32_t>{5, 2, 17}));
    // Every malformed list is a UsageError with a message, never a crash or a silent skip.
    for (const char* bad : {"", ",", "0", "1,", ",1", "1,,2", "-1", "1.5", "x", "1 ,2", "1e3",
                            "99999999999999999999", "4294967295", "0x10", "+", "3,3"}) {
        try {
            (void)parseTrackList(bad);
            ADD_FAILURE() << "accepted '" << bad << "'";
        } catch (const UsageError& e) {
            EXPECT_NE(std::string(e.what()).find("--track"), std::string::npos) << bad;
        }
    }
}

}  // namespace
}  // namespace psb::cli
