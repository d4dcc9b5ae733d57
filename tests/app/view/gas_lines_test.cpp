// The gas instruments' lines: names, units, the ± of the measured pressure, and what shows
// before anything is measured.

#include "view/gas_lines.hpp"

#include <gtest/gtest.h>

namespace psb::app {
namespace {

TEST(GasLines, ReadAsAPersonReadsThem) {
    GasReading r;
    r.particles = 4000;
    r.kT = 0.101;
    r.coverage = 0.16;
    r.window = 5.0;
    r.pressure = 12.21;
    r.pressureError = 0.208;
    r.idealPressure = 8.36;
    r.hardDiskPressure = 11.9;
    r.pairRate = 12194;
    r.wallRate = 420;
    const auto lines = gasLines(r);
    ASSERT_EQ(lines.size(), 6u);
    EXPECT_EQ(lines[0].name, "Temperature kT");
    EXPECT_EQ(lines[0].value, "101 mJ");
    EXPECT_EQ(lines[1].name, "Pressure, measured");
    EXPECT_EQ(lines[1].value, "12.21 \u00b1 0.21 N/m") << "the error to two figures";
    EXPECT_NE(lines[1].help.find("over the last 5 s"), std::string::npos);
    EXPECT_NE(lines[1].help.find("the line their centres reach"), std::string::npos);
    EXPECT_EQ(lines[2].value, "8.36 N/m");
    EXPECT_EQ(lines[3].value, "11.9 N/m");
    EXPECT_NE(lines[3].help.find("covering 16 %"), std::string::npos);
    EXPECT_EQ(lines[4].value, "12 200 pair/s, 420 wall/s") << "never 1.22e+04";
    // The rates say their window, as the rate plot's title says its own.
    EXPECT_EQ(lines[5].name, "  over the last");
    EXPECT_EQ(lines[5].value, "5 s");
}

TEST(GasLines, TheCollisionRatesSayTheWindowTheyAreCountedOver) {
    // "Collisions 12 200 pair/s, 424 wall/s" did not say over how long; the plot and the CSV
    // say "last 0.5 s" of theirs.
    GasReading r;
    r.kT = 0.1;
    r.window = 4.61;
    r.pressure = 12.4;
    r.pressureError = 0.257;
    r.pairRate = 12200;
    r.wallRate = 424;
    const auto lines = gasLines(r);
    ASSERT_EQ(lines.size(), 6u);
    EXPECT_EQ(lines[4].name, "Collisions");
    EXPECT_EQ(lines[5].name, "  over the last");
    EXPECT_EQ(lines[5].value, "4.6 s");
    EXPECT_EQ(lines[1].value, "12.40 \u00b1 0.26 N/m");
}

TEST(GasLines, BeforeHalfASecondThePressureSaysItIsMeasuring) {
    GasReading r;
    r.kT = 0.1;
    const auto lines = gasLines(r);
    ASSERT_EQ(lines.size(), 4u);  // no collision rates yet
    EXPECT_EQ(lines[1].value, "measuring...");
}

TEST(GasLines, APeriodicBoxsPressureIsTheCollisionsAndItHasNoWallRebounds) {
    GasReading r;
    r.periodic = true;
    r.kT = 0.1;
    r.window = 4.5;
    r.pressure = 3.0;
    r.pressureError = 0.05;
    r.pairRate = 5000;
    const auto lines = gasLines(r);
    ASSERT_EQ(lines.size(), 6u);
    EXPECT_EQ(lines[1].value, "3.000 \u00b1 0.050 N/m");
    EXPECT_NE(lines[1].help.find("no walls"), std::string::npos) << lines[1].help;
    EXPECT_EQ(lines[4].value, "5 000 pair/s");
    EXPECT_EQ(lines[4].help.find("wall"), std::string::npos) << lines[4].help;
}

}  // namespace
}  // namespace psb::app
