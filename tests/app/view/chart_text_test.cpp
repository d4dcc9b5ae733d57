// The charts' text (view/chart_text.hpp): where a time axis's labels stand.

#include <gtest/gtest.h>

#include "view/chart_text.hpp"

namespace psb::app {
namespace {

TEST(TimeLabel, CentredOnItsTickButClearOfTheFramesRightEdge) {
    // A frame from 0 to 300 pixels, its axis ending at 292: the last label, "1.0", 30 pixels
    // wide, centred on 292 ran to 307, past the frame's edge.
    EXPECT_FLOAT_EQ(timeLabelLeft(150.f, 30.f, 300.f), 135.f) << "centred on its tick";
    const float last = timeLabelLeft(292.f, 30.f, 300.f);
    EXPECT_LE(last + 30.f, 300.f - kChartPad / 2.f) << "the last label inside the frame";
    EXPECT_GT(last + 30.f, 292.f) << "still under its tick";
}

}  // namespace
}  // namespace psb::app
