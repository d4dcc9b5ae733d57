// Where a tooltip goes (gui/tooltips.hpp): beside the pointer as ImGui puts it, on the display,
// and never over the message band.

#include "gui/tooltips.hpp"

#include <gtest/gtest.h>

namespace psb::app {
namespace {

// A display of 800 × 500 points with the message band along its bottom right of the panel,
// the band 60 points high: what the projector layout gives at 200 %.
constexpr float kW = 800.f, kH = 500.f;
const TipRect kBand{300.f, 440.f, 500.f, 60.f};

TEST(TooltipPosition, BesideThePointerWhereNothingIsInTheWay) {
    const TipRect r = tooltipPosition(100.f, 100.f, 200.f, 80.f, kW, kH, kBand);
    EXPECT_FLOAT_EQ(r.x, 116.f);
    EXPECT_FLOAT_EQ(r.y, 110.f);
    EXPECT_FALSE(r.overlaps(kBand));
}

TEST(TooltipPosition, ATooltipThatWouldCoverTheMessageBandGoesAboveIt) {
    // A control near the panel's foot: below the pointer the tooltip would reach into the band.
    const TipRect r = tooltipPosition(250.f, 380.f, 300.f, 90.f, kW, kH, kBand);
    EXPECT_FALSE(r.overlaps(kBand));
    EXPECT_LE(r.y + r.h, kBand.y);
    EXPECT_GE(r.y, 0.f);
    // Without a band to avoid it would have covered it.
    EXPECT_TRUE(tooltipPosition(250.f, 380.f, 300.f, 90.f, kW, kH, TipRect{}).overlaps(kBand));
}

TEST(TooltipPosition, StaysOnTheDisplay) {
    const TipRect r = tooltipPosition(780.f, 490.f, 200.f, 80.f, kW, kH, TipRect{});
    EXPECT_GE(r.x, 0.f);
    EXPECT_LE(r.x + r.w, kW);
    EXPECT_GE(r.y, 0.f);
    EXPECT_LE(r.y + r.h, kH);
}

TEST(TooltipPosition, ATooltipTallerThanTheRoomAboveTheBandGoesBelowIt) {
    // A band at the top (the window too short for it below the box) and a tall tooltip.
    const TipRect band{0.f, 20.f, 800.f, 40.f};
    const TipRect r = tooltipPosition(100.f, 10.f, 300.f, 200.f, kW, kH, band);
    EXPECT_FALSE(r.overlaps(band));
    EXPECT_GE(r.y, band.y + band.h);
}

}  // namespace
}  // namespace psb::app
