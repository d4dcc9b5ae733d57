#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "session/units.hpp"

namespace psb::app {
namespace {

TEST(Units, SimpleUnitsTakeAnSiPrefixAndThreeFigures) {
    EXPECT_EQ(quantity(4.039e6, "J"), "4.04 MJ");
    EXPECT_EQ(quantity(173.9, "J"), "174 J");
    EXPECT_EQ(quantity(0.3, "m"), "300 mm");
    EXPECT_EQ(quantity(0.00123, "m"), "1.23 mm");
    EXPECT_EQ(quantity(12.345, "s"), "12.3 s");
    EXPECT_EQ(quantity(-2.5e-7, "m"), "-250 nm");
    EXPECT_EQ(quantity(999.7e3, "J"), "1.00 MJ");  // rounding carries to the next prefix
    EXPECT_EQ(quantity(0.0, "J"), "0 J");
}

TEST(Units, AFieldReadsAsEveryReadoutOfItsQuantity) {
    // Lesson 1 at 200 %: vx read "-2.5" in the values table's field and the Selected
    // particle's, "-2.50" on the collision card, the labels and the px column; a mass "1" in
    // its field, "4.00" in the total; the table's fields kept four figures ("3.325") where the
    // panel's kept six. One rule: the readouts' three figures.
    for (const double v : {-2.5, 1.0, 4.0, 0.5, 0.375, -1.0, 3.325, 2.0 / 3.0, 12.5, 987.6})
        EXPECT_EQ(fieldNumber(v), quantity(v, "", false)) << v;
    EXPECT_EQ(fieldNumber(-2.5), "-2.50");
    EXPECT_EQ(fieldNumber(1.0), "1.00");
    EXPECT_EQ(fieldNumber(0.0), "0");
    EXPECT_EQ(fieldNumber(-0.0), "0");
    // Read back as typed: no thousands' spaces, no "× 10^".
    EXPECT_EQ(fieldNumber(1234.0), "1230");
    EXPECT_EQ(fieldNumber(2.5e-7), "2.5e-07");
    EXPECT_EQ(fieldNumber(3e9), "3e+09");
}

TEST(Units, CompoundUnitsGroupDigitsInstead) {
    EXPECT_EQ(quantity(40390.0, "kg m/s", false), "40 400 kg m/s");
    EXPECT_EQ(quantity(-1234567.0, "kg m/s", false), "-1 230 000 kg m/s");
    EXPECT_EQ(quantity(54.06, "kg m/s", false), "54.1 kg m/s");
    EXPECT_EQ(quantity(0.00123, "kg m/s", false), "0.00123 kg m/s");
}

TEST(Units, NoExponentNotationAndNonFiniteValuesInWords) {
    for (const double v : {4.039e6, 1e12, 3e-9, -7.7e8}) {
        EXPECT_EQ(quantity(v, "J").find('e'), std::string::npos) << quantity(v, "J");
        EXPECT_EQ(quantity(v, "kg m/s", false).find("e+"), std::string::npos);
    }
    EXPECT_EQ(quantity(std::numeric_limits<double>::quiet_NaN(), "J"), "n/a");
    EXPECT_EQ(quantity(-std::numeric_limits<double>::infinity(), "J"), "-infinite");
}

TEST(Units, PastThePrefixesAPowerOfTenNotARowOfDigits) {
    // A teacher saw "1030000000000 EJ" and a 31-digit momentum.
    EXPECT_EQ(quantity(1.03e30, "J"), "1.03 \u00d7 10\u00b3\u2070 J");
    EXPECT_EQ(quantity(999.9e18, "J"), "1.00 \u00d7 10\u00b2\u00b9 J");
    EXPECT_EQ(quantity(998e18, "J"), "998 EJ");
    EXPECT_EQ(quantity(1.2e-20, "m"), "1.20 \u00d7 10\u207b\u00b2\u2070 m");
    EXPECT_EQ(quantity(-1.234e31, "kg m/s", false), "-1.23 \u00d7 10\u00b3\u00b9 kg m/s");
    EXPECT_EQ(quantity(9.996e30, "kg m/s", false), "1.00 \u00d7 10\u00b3\u00b9 kg m/s");
    EXPECT_EQ(quantity(999e6, "kg m/s", false), "999 000 000 kg m/s");
    EXPECT_EQ(quantity(2.5e-7, "kg m/s", false), "2.50 \u00d7 10\u207b\u2077 kg m/s");
    EXPECT_EQ(quantity(2.3e-308, "J"),
              "2.30 \u00d7 10\u207b\u00b3\u2070\u2078 J");  // just above underflow
    // Underflow is not a value: a momentum of -3.46e-323 (a velocity decayed to nothing) is 0.
    EXPECT_EQ(quantity(5e-324, "J"), "0 J");  // the smallest double
    EXPECT_EQ(quantity(-3.46e-323, "kg m/s", false), "0 kg m/s");
    EXPECT_EQ(quantity(-1.7976931348623157e308, "kg m/s", false),
              "-1.80 \u00d7 10\u00b3\u2070\u2078 kg m/s");
}

TEST(Units, AccuracyInWords) {
    EXPECT_EQ(keptWords(3e-14), "kept to 1 part in 10\u00b9\u00b3");
    EXPECT_EQ(keptWords(-2.5e-4), "kept to 1 part in 10\u00b3");
    EXPECT_EQ(keptWords(0.0), "kept exactly (to rounding)");
    EXPECT_EQ(keptWords(0.023), "changed by 2.30 %");
    EXPECT_EQ(keptWords(std::numeric_limits<double>::quiet_NaN()), "not measured");
}

TEST(Units, AnErrorHasTwoFiguresAndTheValueItsDecimalPlace) {
    // The gas's pressure read "12.4 \u00b1 0.257 N/m": an error written to more digits than the
    // value.
    EXPECT_EQ(withError(12.4, 0.257, "N/m"), "12.40 \u00b1 0.26 N/m");
    EXPECT_EQ(withError(12.21, 0.208, "N/m"), "12.21 \u00b1 0.21 N/m");
    EXPECT_EQ(withError(3.0, 0.05, "N/m"), "3.000 \u00b1 0.050 N/m");
    EXPECT_EQ(withError(2.5, 0.996, "N/m"), "2.5 \u00b1 1.0 N/m") << "0.996 rounds to 1.0";
    EXPECT_EQ(withError(12194.0, 345.0, ""), "12 190 \u00b1 350");
    EXPECT_EQ(withError(1234.56, 1.2, "m"), "1 234.6 \u00b1 1.2 m");
    EXPECT_EQ(withError(-0.001, 0.25, "N/m"), "0.00 \u00b1 0.25 N/m") << "never -0.00";
    EXPECT_EQ(withError(3.0, 0.0, "N/m"), "3.00 \u00b1 0 N/m");
}

TEST(Units, APowerOfTenIsWrittenRaised) {
    // "10^14" was written with a caret.
    EXPECT_EQ(keptWords(1.5e-15 * 1.5), "kept to 1 part in 10\u00b9\u2074");
    EXPECT_EQ(quantity(2.5e-7, "kg m/s", false).find('^'), std::string::npos);
}

TEST(Units, OverlapInWords) {
    EXPECT_EQ(overlapWords(0.0012, 0.004), "Particles overlap by up to 1.20 mm");
    EXPECT_EQ(overlapWords(0.0, 0.004), "No particles overlap");
    // The exact mode's touching discs: rounding, not an overlap of 65.9 am.
    EXPECT_EQ(overlapWords(65.9e-18, 0.004), "No particles overlap (beyond rounding)");
    EXPECT_EQ(overlapWords(5e-12, 0.004), "Particles overlap by up to 5.00 pm");
}

TEST(Units, APlainNumberReadsBackAsTyped) {
    // The figures asked for, trailing zeros dropped, an exponent where %g puts one: what a
    // person types back into a field.
    EXPECT_EQ(plainNumber(12.5), "12.5");
    EXPECT_EQ(plainNumber(0.1 + 0.2), "0.3");
    EXPECT_EQ(plainNumber(1e-7), "1e-07");
    EXPECT_EQ(plainNumber(123456789.0), "1.23457e+08");
    EXPECT_EQ(plainNumber(2.0 / 3.0, 3), "0.667");
    EXPECT_EQ(plainNumber(1234.56, 4), "1235");
    EXPECT_EQ(plainNumber(-0.0), "0");
    EXPECT_EQ(plainNumber(-1e-9, 3), "-1e-09");
}

}  // namespace
}  // namespace psb::app
