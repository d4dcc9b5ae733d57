// The exported tables (data_tables.hpp): their columns, units and values, read back as a
// spreadsheet would.

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include <particle_sandbox/data_tables.hpp>
#include <particle_sandbox/world.hpp>

namespace psb {
namespace {

using Rows = std::vector<std::vector<std::string>>;

Rows parse(const std::string& text, char separator) {
    Rows rows;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) {
        std::vector<std::string> cells;
        std::string cell;
        std::istringstream fields(line);
        while (std::getline(fields, cell, separator))
            cells.push_back(cell);
        if (!line.empty() && line.back() == separator) cells.emplace_back();
        rows.push_back(cells);
    }
    return rows;
}

World twoBalls() {
    WorldDef def;
    def.width = 10.0;
    def.height = 10.0;
    def.walls = false;
    World w(def);
    w.add({.position = Vec2(3.0, 5.0), .velocity = Vec2(2.0, 0.0), .mass = 1.0, .radius = 0.5});
    w.add({.position = Vec2(6.0, 5.0), .velocity = Vec2(-1.0, 0.5), .mass = 3.0, .radius = 0.5});
    return w;
}

TEST(ValuesTable, EveryParticleWithSignedComponentsAndUnits) {
    const World w = twoBalls();
    const Rows rows = parse(valuesTable(w, csv::Separator::Comma), ',');
    ASSERT_EQ(rows.size(), 3u);
    EXPECT_EQ(rows[0], (std::vector<std::string>{"particle", "x_m", "y_m", "vx_m_per_s",
                                                 "vy_m_per_s", "px_kg_m_per_s", "py_kg_m_per_s",
                                                 "kinetic_energy_J", "mass_kg", "radius_m"}));
    EXPECT_EQ(rows[1],
              (std::vector<std::string>{"1", "3", "5", "2", "0", "2", "0", "2", "1", "0.5"}));
    EXPECT_EQ(rows[2], (std::vector<std::string>{"2", "6", "5", "-1", "0.5", "-3", "1.5", "1.875",
                                                 "3", "0.5"}));
}

TEST(ValuesTable, TabSeparatedForTheClipboard) {
    const std::string text = valuesTable(twoBalls(), csv::Separator::Tab);
    EXPECT_EQ(text.find(','), std::string::npos);
    EXPECT_EQ(parse(text, '\t')[2][3], "-1");
}

TEST(ValuesTable, YUpCountsFromTheFloorAndSaysSoInItsHeader) {
    World w = twoBalls();
    w.setAngularVelocity(w.ids()[0], 4.0);  // clockwise on screen
    const Rows rows = parse(valuesTable(w, csv::Separator::Comma, Axes{true, 10.0}), ',');
    ASSERT_EQ(rows.size(), 3u);
    EXPECT_EQ(rows[0], (std::vector<std::string>{
                           "particle", "x_m", "y_up_m", "vx_m_per_s", "vy_up_m_per_s",
                           "omega_ccw_rad_per_s", "px_kg_m_per_s", "py_up_kg_m_per_s",
                           "kinetic_energy_J", "rotational_energy_J", "mass_kg", "radius_m"}));
    EXPECT_EQ(rows[1], (std::vector<std::string>{"1", "3", "5", "2", "0", "-4", "2", "0", "2", "1",
                                                 "1", "0.5"}));
    EXPECT_EQ(rows[2], (std::vector<std::string>{"2", "6", "5", "-1", "-0.5", "0", "-3", "-1.5",
                                                 "1.875", "0", "3", "0.5"}));
}

TEST(TimeSeriesTable, CleanTimesAndTheGravityColumns) {
    World w = twoBalls();
    TimeSeries series(100);
    series.record(w);
    for (int k = 0; k < 30; ++k) {
        w.step(1.0 / 60.0);
        series.record(w);
    }
    const Rows rows = parse(timeSeriesTable(samplesOf(series), false, csv::Separator::Comma), ',');
    ASSERT_EQ(rows.size(), 32u);
    EXPECT_EQ(rows[0].front(), "time_s");
    EXPECT_EQ(rows[0].back(), "collision_rate_per_s");
    EXPECT_EQ(rows.back()[0], "0.5");
    EXPECT_EQ(rows[1][0], "0");
    EXPECT_EQ(rows[1][1], "3.875") << "kinetic energy, J";
    const Rows g = parse(timeSeriesTable(samplesOf(series), true, csv::Separator::Comma), ',');
    EXPECT_EQ(g[0].back(), "mechanical_energy_J");
    EXPECT_EQ(g[1].size(), 10u);
    // A rate counted over a window names it.
    const Rows windowed = parse(
        timeSeriesTable(samplesOf(series), false, csv::Separator::Comma, false, Axes{}, 0.5), ',');
    EXPECT_EQ(windowed[0].back(), "collision_rate_per_s_last_0.5_s");
}

TEST(TimeSeriesTable, ARateReadsToTheTwelveDigitsOfItsWindowsTime) {
    // A count divided by a window of added steps came out as 2.000000000000007 in the app's
    // export: the rate keeps the 12 digits its time has.
    std::vector<ObservablesSample> samples(2);
    samples[0].collisionRate = std::nan("");
    samples[1].time = 0.5;
    samples[1].collisionRate = 2.000000000000007;
    const Rows rows = parse(timeSeriesTable(samples, false, csv::Separator::Comma), ',');
    ASSERT_EQ(rows.size(), 3u);
    EXPECT_EQ(rows[1].back(), "") << "no rate before a whole window";
    EXPECT_EQ(rows[2].back(), "2");
}

TEST(TrajectoryTable, RowsPerParticlePerInstant) {
    World w = twoBalls();
    const std::vector<ParticleId> ids = w.ids();
    Trajectory t({ids[1], ids[0]});
    EXPECT_TRUE(t.record(w));
    EXPECT_FALSE(t.record(w)) << "nothing stepped";
    w.step(0.25);
    EXPECT_TRUE(t.record(w));
    const Rows rows = parse(trajectoryTable(t, csv::Separator::Comma), ',');
    ASSERT_EQ(rows.size(), 5u);
    EXPECT_EQ(rows[0], (std::vector<std::string>{"time_s", "particle", "x_m", "y_m", "vx_m_per_s",
                                                 "vy_m_per_s"}));
    EXPECT_EQ(rows[1], (std::vector<std::string>{"0", "2", "6", "5", "-1", "0.5"}));
    EXPECT_EQ(rows[4], (std::vector<std::string>{"0.25", "1", "3.5", "5", "2", "0"}));
    // With y up, heights from the floor and velocities up; with rotation, omega.
    const Rows up = parse(trajectoryTable(t, csv::Separator::Comma, true, Axes{true, 10.0}), ',');
    EXPECT_EQ(up[0], (std::vector<std::string>{"time_s", "particle", "x_m", "y_up_m", "vx_m_per_s",
                                               "vy_up_m_per_s", "omega_ccw_rad_per_s"}));
    EXPECT_EQ(up[1], (std::vector<std::string>{"0", "2", "6", "5", "-1", "-0.5", "0"}));
}

TEST(Trajectory, FollowsTheWorldBackInTimeAndStopsWhenFull) {
    World w = twoBalls();
    const World start = w;
    Trajectory t({w.ids()[0]}, 3);
    t.record(w);
    w.step(0.1);
    t.record(w);
    w.step(0.1);
    t.record(w);
    EXPECT_EQ(t.samples().size(), 3u);
    EXPECT_TRUE(t.full());
    w.step(0.1);
    EXPECT_FALSE(t.record(w));
    w = start;  // an undo back to t = 0
    w.step(0.05);
    EXPECT_TRUE(t.record(w));
    ASSERT_EQ(t.samples().size(), 2u) << "the samples after 0.05 s are dropped";
    EXPECT_EQ(t.samples()[1].time, 0.05);
}

TEST(CollisionTable, PairsWallsAndObstaclesWithSignedVelocitiesAndImpulse) {
    Collision pair;
    pair.time = 2.0 / 3.0;
    pair.a = {0, 0};
    pair.b = {1, 0};
    pair.aBefore = Vec2(2.0, 0.0);
    pair.aAfter = Vec2(-2.5, 0.0);
    pair.bBefore = Vec2(-1.0, 0.0);
    pair.bAfter = Vec2(0.5, 0.0);
    pair.impulse = Vec2(-4.5, 0.0);
    Collision wall;
    wall.time = 0.5;
    wall.with = Collision::With::Wall;
    wall.where = static_cast<std::uint32_t>(WallSide::Right);
    wall.a = {4, 2};
    wall.aBefore = Vec2(3.0, 1.0);
    wall.aAfter = Vec2(-1.5, 1.0);
    wall.impulse = Vec2(-9.0, 0.0);
    Collision peg = wall;
    peg.with = Collision::With::Obstacle;
    peg.where = 7;
    const Rows rows = parse(collisionTable({pair, wall, peg}, csv::Separator::Comma), ',');
    ASSERT_EQ(rows.size(), 4u);
    EXPECT_EQ(rows[0].size(), 14u);
    EXPECT_EQ(rows[0][12], "impulse_x_N_s");
    EXPECT_EQ(rows[1], (std::vector<std::string>{"0.666666666667", "1", "particle", "2", "2", "0",
                                                 "-2.5", "0", "-1", "0", "0.5", "0", "-4.5", "0"}));
    EXPECT_EQ(rows[2], (std::vector<std::string>{"0.5", "5", "wall", "right", "3", "1", "-1.5", "1",
                                                 "", "", "", "", "-9", "0"}));
    EXPECT_EQ(rows[3][2], "obstacle");
    EXPECT_EQ(rows[3][3], "7");
    const Rows up = parse(collisionTable({wall}, csv::Separator::Comma, Axes{true, 8.0}), ',');
    EXPECT_EQ(up[0][5], "vy_up_before_m_per_s");
    EXPECT_EQ(up[0][13], "impulse_y_up_N_s");
    EXPECT_EQ(up[1][5], "-1") << "moving down the screen: negative with y up";
}

}  // namespace
}  // namespace psb
