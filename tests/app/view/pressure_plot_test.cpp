// The pressure plot (pressure_plot.hpp): unit coordinates, a round top above every line, the
// measured line broken where there was no value, and its text.

#include <gtest/gtest.h>

#include <limits>

#include "view/pressure_plot.hpp"

namespace psb::app {
namespace {

std::deque<GasHistoryPoint> history() {
    std::deque<GasHistoryPoint> h;
    for (int k = 0; k <= 20; ++k) {
        GasHistoryPoint p;
        p.time = 0.25 * k;
        if (k >= 2 && k != 10) {  // none while the window was short, and after an edit at k = 10
            p.pressure = 12.0 + 0.1 * (k % 3);
            p.pressureError = 0.2;
        }
        p.idealPressure = k < 10 ? 8.36 : 16.72;
        p.hardDiskPressure = k < 10 ? 11.9 : 23.8;
        h.push_back(p);
    }
    return h;
}

TEST(PressurePlot, LinesInUnitCoordinatesUnderARoundTop) {
    const PressurePlot plot = pressurePlot(history());
    ASSERT_FALSE(plot.empty());
    EXPECT_DOUBLE_EQ(plot.t0, 0.0);
    EXPECT_DOUBLE_EQ(plot.t1, 5.0);
    EXPECT_DOUBLE_EQ(plot.top, 30.0);  // 1.15 x 23.8 = 27.4, rounded up to a ten
    ASSERT_EQ(plot.hardDisk.size(), 21u);
    EXPECT_DOUBLE_EQ(plot.hardDisk.front().x(), 0.0);
    EXPECT_DOUBLE_EQ(plot.hardDisk.back().x(), 1.0);
    EXPECT_NEAR(plot.hardDisk.back().y(), 23.8 / 30.0, 1e-12);
    EXPECT_NEAR(plot.ideal.front().y(), 8.36 / 30.0, 1e-12);
    // The measured line: k = 2..9 and 11..20, two stretches, with the band either side.
    ASSERT_EQ(plot.measured.size(), 2u);
    EXPECT_EQ(plot.measured[0].size(), 8u);
    EXPECT_EQ(plot.measured[1].size(), 10u);
    EXPECT_LT(plot.measuredLow[1][0].y(), plot.measured[1][0].y());
    EXPECT_GT(plot.measuredHigh[1][0].y(), plot.measured[1][0].y());
}

TEST(PressurePlot, OnlyTheLastSpanAndNothingFromTooLittleOrBadData) {
    const PressurePlot last = pressurePlot(history(), 2.0);
    EXPECT_DOUBLE_EQ(last.t0, 3.0);
    EXPECT_EQ(last.hardDisk.size(), 9u);
    EXPECT_TRUE(pressurePlot({}).empty());
    std::deque<GasHistoryPoint> one(1);
    EXPECT_TRUE(pressurePlot(one).empty());
    std::deque<GasHistoryPoint> bad = history();
    for (GasHistoryPoint& p : bad)
        p.hardDiskPressure = std::numeric_limits<double>::quiet_NaN();
    EXPECT_TRUE(pressurePlot(bad).empty());
}

TEST(PressurePlot, ItsLineNamesTheLatestPoint) {
    EXPECT_EQ(pressurePlotLine({}), "");
    const std::string line = pressurePlotLine(history());
    EXPECT_NE(line.find("Pressure plot: t = 0 s to 5.00 s, 21 points"), std::string::npos) << line;
    EXPECT_NE(line.find("now measured 12.20 \u00b1 0.20 N/m"), std::string::npos) << line;
    EXPECT_NE(line.find("hard discs 23.8 N/m, ideal gas 16.7 N/m"), std::string::npos) << line;
}

TEST(PressurePlot, ItsScaleLabelsStayClearOfItsFrameAtEveryScale) {
    // At 200 % the "0 N/m" stood on the frame's bottom line (1 pixel above it, whatever the
    // scale) and the top's value under its top line.
    for (const float font : {13.f, 26.f, 39.f}) {
        const float height = 6.f * font;
        const PlotScaleLabels l = plotScaleLabels(height, font);
        EXPECT_GE(l.x, 0.2f * font) << font;
        EXPECT_GE(l.top, 0.2f * font) << font;
        EXPECT_LE(l.bottom + font, height - 0.2f * font) << font;
        EXPECT_GE(l.bottom, l.top + font) << font << ": the two apart";
    }
}

}  // namespace
}  // namespace psb::app
