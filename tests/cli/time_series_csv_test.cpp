// particle-sim --timeseries: the CSV's shape, and the physics it must show.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <particle_sandbox/time_series.hpp>
#include <particle_sandbox/world.hpp>

#include "cli_app.hpp"
#include "time_series_csv.hpp"

namespace psb::cli {
namespace {

namespace fs = std::filesystem;

/// A closed 200 m box with 300 discs from the scene generator, restitution `e`.
std::string gasScene(double e) {
    return R"({"version": 1, "world": {"width": 200, "height": 200, "walls": true,
        "restitution": )" +
           std::to_string(e) + R"(},
        "solver": {"dt": 0.01},
        "generate": {"count": 300, "radius": 2, "mass": 1, "temperature": 500, "seed": 3}})";
}

class TimeSeriesCsv : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("psb-timeseries-" +
                std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    fs::path writeScene(const std::string& json) const {
        const fs::path p = dir_ / "scene.json";
        std::ofstream(p) << json;
        return p;
    }

    int run(std::vector<std::string> args) {
        args.insert(args.begin(), "particle-sim");
        out_.str("");
        err_.str("");
        return runCli(args, out_, err_, false);
    }

    /// The rows of a CSV file as numbers; the header is checked and dropped.
    static std::vector<std::vector<double>> readCsv(const fs::path& p) {
        std::ifstream in(p);
        std::string line;
        std::getline(in, line);
        EXPECT_EQ(line, kTimeSeriesCsvHeader);
        std::vector<std::vector<double>> rows;
        while (std::getline(in, line)) {
            std::vector<double> row;
            std::stringstream ss(line);
            std::string cell;
            while (std::getline(ss, cell, ','))
                row.push_back(cell.empty() ? std::nan("") : std::stod(cell));
            if (!line.empty() && line.back() == ',') row.push_back(std::nan(""));
            EXPECT_EQ(row.size(), 8u) << line;
            rows.push_back(row);
        }
        return rows;
    }

    fs::path dir_;
    std::ostringstream out_, err_;
};

TEST_F(TimeSeriesCsv, ElasticClosedBoxKeepsItsKineticEnergyInEveryRow) {
    const fs::path csv = dir_ / "ts.csv";
    ASSERT_EQ(run({writeScene(gasScene(1.0)), "--duration", "2", "--timeseries", csv}), kExitOk)
        << err_.str();
    const auto rows = readCsv(csv);
    ASSERT_EQ(rows.size(), 201u);  // t = 0 and 200 steps
    const double e0 = rows[0][1];
    EXPECT_GT(e0, 0.0);
    for (const auto& r : rows)
        EXPECT_NEAR(r[1], e0, 1e-9 * e0) << "t = " << r[0];
    EXPECT_EQ(rows[0][0], 0.0);
    EXPECT_TRUE(std::isnan(rows[0][7])) << "the first row has no interval: an empty rate";
    EXPECT_NEAR(rows.back()[0], 2.0, 1e-12);
    EXPECT_GT(rows.back()[6], 0.0);  // the gas collided
}

TEST_F(TimeSeriesCsv, InelasticBoxLosesKineticEnergyAndNeverGainsIt) {
    const fs::path csv = dir_ / "ts.csv";
    ASSERT_EQ(run({writeScene(gasScene(0.8)), "--duration", "2", "--timeseries", csv}), kExitOk)
        << err_.str();
    const auto rows = readCsv(csv);
    ASSERT_EQ(rows.size(), 201u);
    for (std::size_t k = 1; k < rows.size(); ++k)
        EXPECT_LE(rows[k][1], rows[k - 1][1] * (1.0 + 1e-12)) << "t = " << rows[k][0];
    EXPECT_LT(rows.back()[1], 0.9 * rows[0][1]);
}

TEST_F(TimeSeriesCsv, EveryNStepsPlusTheFinalState) {
    const fs::path csv = dir_ / "ts.csv";
    ASSERT_EQ(run({writeScene(gasScene(1.0)), "--duration", "1.05", "--timeseries", csv,
                   "--timeseries-every", "10"}),
              kExitOk)
        << err_.str();
    const auto rows = readCsv(csv);
    ASSERT_EQ(rows.size(), 12u);  // t = 0, 0.1, ..., 1.0, and the last step at 1.05
    EXPECT_NEAR(rows[1][0], 0.1, 1e-12);
    EXPECT_NEAR(rows[10][0], 1.0, 1e-12);
    EXPECT_NEAR(rows[11][0], 1.05, 1e-12);
    // Each row's rate times its interval is its share of the collisions.
    double count = 0.0;
    for (std::size_t k = 1; k < rows.size(); ++k)
        count += rows[k][7] * (rows[k][0] - rows[k - 1][0]);
    EXPECT_NEAR(count, rows.back()[6], 1e-6);
}

TEST_F(TimeSeriesCsv, BadOptionsAreUsageErrorsNamingTheOption) {
    const std::string scene = writeScene(gasScene(1.0));
    EXPECT_EQ(run({scene, "--duration", "1", "--timeseries", ""}), kExitUsage);
    EXPECT_NE(err_.str().find("--timeseries: needs a path"), std::string::npos) << err_.str();
    EXPECT_EQ(run({scene, "--duration", "1", "--timeseries", "x.csv", "--timeseries-every", "0"}),
              kExitUsage);
    EXPECT_NE(err_.str().find("--timeseries-every: must be in [1,"), std::string::npos);
    EXPECT_EQ(run({scene, "--duration", "1", "--timeseries", "x.csv", "--timeseries-every", "nan"}),
              kExitUsage);
    EXPECT_NE(err_.str().find("--timeseries-every: expected an integer"), std::string::npos);
    EXPECT_EQ(run({scene, "--duration", "1", "--timeseries-every", "5"}), kExitUsage);
    EXPECT_NE(err_.str().find("--timeseries-every: needs --timeseries PATH"), std::string::npos);
    // 1e6 s at 0.01 s is 1e8 steps: too many rows at every step, refused before running.
    EXPECT_EQ(run({scene, "--duration", "1e6", "--timeseries", (dir_ / "big.csv").string()}),
              kExitUsage);
    EXPECT_NE(err_.str().find("--timeseries-every: 100000001 rows is more than the limit"),
              std::string::npos)
        << err_.str();
    EXPECT_FALSE(fs::exists(dir_ / "big.csv"));
}

TEST_F(TimeSeriesCsv, UnwritablePathFailsWithoutLeavingAFile) {
    const fs::path csv = dir_ / "no" / "such" / "ts.csv";
    EXPECT_EQ(run({writeScene(gasScene(1.0)), "--duration", "0.1", "--timeseries", csv}),
              kExitFailure);
    EXPECT_NE(err_.str().find("ts.csv"), std::string::npos) << err_.str();
    EXPECT_FALSE(fs::exists(csv));
}

}  // namespace
}  // namespace psb::cli

namespace psb::cli {
namespace {

TEST(TimeSeriesCsvGravity, AddsPotentialAndMechanicalEnergyColumns) {
    WorldDef def;
    def.width = def.height = 10.0;
    def.gravity = {0.0, 2.0};
    World w(def, {.mode = StepMode::Exact});
    w.add({.position = {5.0, 5.0}, .mass = 3.0, .radius = 1.0});
    TimeSeries series(4);
    series.record(w);
    w.step(1.0);
    series.record(w);
    const std::string csv = timeSeriesCsv(series, true);
    std::istringstream in(csv);
    std::string header, first, second;
    std::getline(in, header);
    std::getline(in, first);
    std::getline(in, second);
    EXPECT_EQ(header, std::string(kTimeSeriesCsvHeader) + kTimeSeriesCsvGravityColumns);
    // Row 2: 1 s of free fall from 5 m above the floor: potential 24 J, kinetic 6 J, total 30 J.
    std::vector<double> row;
    std::stringstream ss(second);
    for (std::string cell; std::getline(ss, cell, ',');)
        row.push_back(cell.empty() ? std::nan("") : std::stod(cell));
    ASSERT_EQ(row.size(), 10u);
    EXPECT_NEAR(row[8], 24.0, 1e-12);
    EXPECT_NEAR(row[9], 30.0, 1e-12);
    EXPECT_EQ(timeSeriesCsv(series).find("potential"), std::string::npos);
}

TEST(TimeSeriesCsvRotation, AddsRotationalEnergyAndAngularMomentumColumns) {
    WorldDef def;
    def.width = def.height = 10.0;
    World w(def, {.mode = StepMode::Exact});
    // m = 2, r = 1, k = 1/2: I = 1; ω = 3: ½ I ω² = 4.5 J; L = m (x vy − y vx) + I ω = 2 (5·1) + 3.
    w.add({.position = {5.0, 5.0},
           .velocity = {0.0, 1.0},
           .mass = 2.0,
           .radius = 1.0,
           .angularVelocity = 3.0});
    TimeSeries series(4);
    series.record(w);
    w.step(1.0);
    series.record(w);
    const std::string csv = timeSeriesCsv(series, false, true);
    std::istringstream in(csv);
    std::string header, first;
    std::getline(in, header);
    std::getline(in, first);
    EXPECT_EQ(header, std::string(kTimeSeriesCsvHeader) + kTimeSeriesCsvRotationColumns);
    std::vector<double> row;
    std::stringstream ss(first);
    // The first row's rate is an empty cell: there is no interval yet.
    for (std::string cell; std::getline(ss, cell, ',');)
        row.push_back(cell.empty() ? std::nan("") : std::stod(cell));
    ASSERT_EQ(row.size(), 10u);
    EXPECT_TRUE(std::isnan(row[7]));
    EXPECT_EQ(row[8], 4.5);
    EXPECT_EQ(row[9], 13.0);
    EXPECT_EQ(timeSeriesCsv(series).find("rotational"), std::string::npos);
}

}  // namespace
}  // namespace psb::cli
