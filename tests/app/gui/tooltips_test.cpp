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

TEST(TooltipState, AControlBroughtUnderAStillPointerByAKeyShowsNoTooltip) {
    // A trial at 200 %: the keyboard on the panel, Space (Play) brought the Play button's
    // tooltip up at the pointer, which rested over the values table's totals (ImGui counts the
    // control the keyboard is on as hovered). A tooltip waits for a real hover: the pointer
    // moved onto the control and resting there kDelaySeconds.
    TooltipState t;
    double now = 0.0;
    const auto frame = [&](float x, float y) {
        now += 0.1;
        t.startFrame(now, true, x, y);
    };
    // The pointer comes to rest on the values table: no tooltip there.
    frame(500.f, 450.f);
    frame(520.f, 460.f);
    for (int k = 0; k < 10; ++k)
        frame(520.f, 460.f);
    // A key: the keyboard on Play, which ImGui now calls hovered, the pointer still.
    for (int k = 0; k < 20; ++k) {
        frame(520.f, 460.f);
        EXPECT_FALSE(t.show("Start or stop the clock (key Space)")) << "after " << now << " s";
    }
    // The pointer moves (onto Play, say): after the delay, its tooltip.
    frame(60.f, 80.f);
    EXPECT_FALSE(t.show("Start or stop the clock (key Space)")) << "not at once";
    bool shown = false;
    for (int k = 0; k < 10 && !shown; ++k) {
        frame(60.f, 80.f);
        shown = t.show("Start or stop the clock (key Space)");
    }
    EXPECT_TRUE(shown) << "a real hover";
    EXPECT_GE(now, 0.1 * 21 + TooltipState::kDelaySeconds);
    // Resting there, a key moves the layout: another control under the still pointer waits.
    frame(60.f, 80.f);
    EXPECT_FALSE(t.show("Step one frame"));
    for (int k = 0; k < 10; ++k) {
        frame(60.f, 80.f);
        EXPECT_FALSE(t.show("Step one frame"));
    }
}

TEST(TooltipState, AMouseRestingOnAControlItMovedOntoShowsItsTooltipAfterTheDelay) {
    TooltipState t;
    t.startFrame(0.0, true, 10.f, 10.f);
    t.startFrame(0.1, true, 60.f, 80.f);
    EXPECT_FALSE(t.show("Play"));
    t.startFrame(0.4, true, 60.f, 80.f);
    EXPECT_FALSE(t.show("Play"));
    t.startFrame(0.7, true, 60.f, 80.f);
    EXPECT_TRUE(t.show("Play"));
    // Never for a finger.
    t.startFrame(0.8, false, 61.f, 80.f);
    EXPECT_FALSE(t.show("Play"));
}

}  // namespace
}  // namespace psb::app
