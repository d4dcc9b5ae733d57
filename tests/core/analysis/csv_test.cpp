// Numbers and tables as spreadsheets read them (csv.hpp).

#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <string>

#include <particle_sandbox/csv.hpp>

namespace psb::csv {
namespace {

TEST(CsvNumber, PlainBetweenTenToTheMinusFourAndAMillion) {
    EXPECT_EQ(number(0.0), "0");
    EXPECT_EQ(number(-0.0), "-0");
    EXPECT_EQ(number(0.5), "0.5");
    EXPECT_EQ(number(-2.5), "-2.5");
    EXPECT_EQ(number(12.0), "12");
    EXPECT_EQ(number(999999.5), "999999.5");
    EXPECT_EQ(number(0.0001), "0.0001");
    EXPECT_EQ(number(0.1 + 0.2), "0.30000000000000004") << "a value keeps its full precision";
}

TEST(CsvNumber, ScientificPastAMillionAndBelowTenToTheMinusFour) {
    EXPECT_EQ(number(1e6), "1e+06");
    EXPECT_EQ(number(1.03e12), "1.03e+12") << "never a 13-digit integer";
    EXPECT_EQ(number(-4.2e31), "-4.2e+31");
    EXPECT_EQ(number(2.5e-5), "2.5e-05");
}

TEST(CsvNumber, NotFiniteValuesAreNamed) {
    EXPECT_EQ(number(std::numeric_limits<double>::quiet_NaN()), "nan");
    EXPECT_EQ(number(std::numeric_limits<double>::infinity()), "inf");
    EXPECT_EQ(number(-std::numeric_limits<double>::infinity()), "-inf");
}

TEST(CsvNumber, EveryDoubleReadsBackBitForBitAndIsShort) {
    std::mt19937_64 rng(5);
    std::uniform_int_distribution<std::uint64_t> bits;
    for (int k = 0; k < 100000; ++k) {
        std::uint64_t b = bits(rng);
        double v;
        std::memcpy(&v, &b, sizeof v);
        if (!std::isfinite(v)) continue;
        const std::string text = number(v);
        double back = 0.0;
        const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), back);
        ASSERT_EQ(ec, std::errc{}) << text;
        ASSERT_EQ(end, text.data() + text.size()) << text;
        ASSERT_EQ(std::memcmp(&back, &v, sizeof v), 0) << text;
        ASSERT_LE(text.size(), 24u) << text;
    }
}

TEST(CsvTime, CleanDecimalsForAClockOfAddedSteps) {
    double t = 0.0;
    for (int k = 0; k < 3; ++k)
        t += 0.1;
    EXPECT_EQ(time(t), "0.3");
    t = 0.0;
    for (int k = 0; k < 30; ++k)
        t += 1.0 / 60.0;
    EXPECT_EQ(time(t), "0.5");
    EXPECT_EQ(time(0.49999999999999994), "0.5");
    EXPECT_EQ(time(0.0), "0");
    EXPECT_EQ(time(-0.0), "0");
    EXPECT_EQ(time(2.0 / 3.0), "0.666666666667");
    EXPECT_EQ(time(1234.5), "1234.5");
}

TEST(CsvTable, HeaderThenRowsWithTheSeparator) {
    Table t(Separator::Comma, {"time_s", "x_m"});
    t.time(0.5).number(2.0);
    t.endRow();
    t.time(1.0).number(-1e7);
    t.endRow();
    EXPECT_EQ(t.str(), "time_s,x_m\n0.5,2\n1,-1e+07\n");
    EXPECT_EQ(t.rows(), 2u);
    Table tabs(Separator::Tab, {"a", "b"});
    tabs.count(3).none();
    tabs.endRow();
    EXPECT_EQ(tabs.str(), "a\tb\n3\t\n");
}

TEST(CsvTable, CellsHoldingTheSeparatorOrQuotesAreQuoted) {
    Table t(Separator::Comma, {"name"});
    t.text("a,b");
    t.endRow();
    t.text("say \"hi\"");
    t.endRow();
    t.text("a\tb");  // a tab is plain text in a CSV file
    t.endRow();
    EXPECT_EQ(t.str(), "name\n\"a,b\"\n\"say \"\"hi\"\"\"\na\tb\n");
    Table tabs(Separator::Tab, {"name"});
    tabs.text("a\tb");
    tabs.endRow();
    EXPECT_EQ(tabs.str(), "name\n\"a\tb\"\n");
}

}  // namespace
}  // namespace psb::csv
