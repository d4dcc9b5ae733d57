// The panel layout: a pure function from the window size and the panels' needs to rectangles,
// checked for overlaps without drawing.

#include <gtest/gtest.h>

#include <array>

#include "view/screen_layout.hpp"

namespace psb::app {
namespace {

// Sizes the app asks for with its 12 px fonts: a six-line HUD about 75 characters wide, the
// discrete mode's profile (13 lines), the three-line momentum legend, one message.
LayoutRequest everythingOn(int width, int height) {
    LayoutRequest r;
    r.width = width;
    r.height = height;
    r.hud = {540, 104};
    r.profile = {230, 214};
    r.legend = {260, 52};
    r.messages = {300, 20};
    r.inspector = {290, 140};
    r.plots = true;
    r.speeds = true;
    return r;
}

std::array<PixelRect, 7> boxes(const PanelLayout& l) {
    return {l.hud, l.profile, l.legend, l.messages, l.plots, l.speeds, l.inspector};
}

void expectNoOverlapAndInside(const LayoutRequest& r, const PanelLayout& l) {
    const auto all = boxes(l);
    for (std::size_t i = 0; i < all.size(); ++i) {
        const PixelRect& a = all[i];
        if (a.w <= 0) continue;
        EXPECT_GE(a.x, 0) << "box " << i << " at " << r.width << "x" << r.height;
        EXPECT_GE(a.y, 0) << "box " << i;
        EXPECT_LE(a.x + a.w, r.width) << "box " << i << " at " << r.width << "x" << r.height;
        EXPECT_LE(a.y + a.h, r.height) << "box " << i << " at " << r.width << "x" << r.height;
        for (std::size_t j = i + 1; j < all.size(); ++j) {
            EXPECT_FALSE(overlaps(a, all[j]))
                << "boxes " << i << " and " << j << " at " << r.width << "x" << r.height;
        }
    }
}

TEST(PanelLayout, At600x600EveryPanelFitsBelowTheHudWithoutOverlap) {
    LayoutRequest r = everythingOn(600, 600);
    r.messages = {0, 0};  // a message takes the bottom row: then the histogram gives way
    r.profile = {0, 0};   // and so does it to the profile
    const PanelLayout l = layoutPanels(r);
    expectNoOverlapAndInside(r, l);
    // The HUD is 540 px wide: the right column cannot sit beside it, so it starts below it.
    EXPECT_GE(l.legend.y, l.hud.y + l.hud.h);
    EXPECT_GT(l.plots.w, 0);
    EXPECT_GT(l.speeds.w, 0);
    EXPECT_GE(l.plotRows, 1);  // the least important rows dropped for room
    EXPECT_LT(l.plotRows, 4);
    EXPECT_GE(l.speeds.h, kSpeedsMinHeight);
}

TEST(PanelLayout, At1280x720TheColumnSitsBesideTheHud) {
    LayoutRequest r = everythingOn(1280, 720);
    r.inspector = {0, 0};  // nothing selected
    const PanelLayout l = layoutPanels(r);
    expectNoOverlapAndInside(r, l);
    EXPECT_EQ(l.profile.y, 4);  // top-right, level with the HUD
    EXPECT_EQ(l.profile.x + l.profile.w, 1280 - kPanelMargin);
    EXPECT_EQ(l.plots.w, kPanelMaxWidth);
    EXPECT_EQ(l.speeds.h, kSpeedsMaxHeight);
    EXPECT_GE(l.plotRows, 2);  // rows with room for three tick labels each
}

TEST(PanelLayout, At800x800WithoutProfileThePlotsGetAllFourFullRows) {
    LayoutRequest r = everythingOn(800, 800);
    r.profile = {0, 0};
    r.legend = {0, 0};
    r.messages = {0, 0};
    r.inspector = {0, 0};
    const PanelLayout l = layoutPanels(r);
    expectNoOverlapAndInside(r, l);
    EXPECT_EQ(l.plotRows, 4);
    EXPECT_EQ(l.plotRowHeight, kPlotRowMaxHeight);
    EXPECT_EQ(l.speeds.h, kSpeedsMaxHeight);
}

TEST(PanelLayout, AtTwiceTheScaleTheChartsAreTwiceTheSizeAndStillDoNotOverlap) {
    // 2560x1600 at 200 %: the 800x800 case's panels, every size doubled.
    LayoutRequest r = everythingOn(2560, 1600);
    r.hud = {1080, 208};
    r.profile = {0, 0};
    r.legend = {0, 0};
    r.messages = {0, 0};
    r.inspector = {0, 0};
    r.left = 620;
    r.scale = 2.0;
    const PanelLayout l = layoutPanels(r);
    expectNoOverlapAndInside(r, l);
    EXPECT_EQ(l.plotRows, 4);
    EXPECT_EQ(l.plotRowHeight, 2 * kPlotRowMaxHeight);
    EXPECT_EQ(l.speeds.h, 2 * kSpeedsMaxHeight);
    EXPECT_EQ(l.plots.w, 2 * kPanelMaxWidth);
    // Any window at any scale: still no overlap, still inside.
    for (const double scale : {0.75, 1.5, 3.0}) {
        for (int w = 611; w <= 2400; w += 211) {
            LayoutRequest q = everythingOn(w, w * 3 / 4);
            q.scale = scale;
            expectNoOverlapAndInside(q, layoutPanels(q));
        }
    }
}

TEST(PanelLayout, NoWindowSizeOrPanelChoiceMakesBoxesOverlap) {
    for (int w = 200; w <= 1600; w += 37) {
        for (int h = 200; h <= 1200; h += 41) {
            for (int mask = 0; mask < 64; ++mask) {
                LayoutRequest r = everythingOn(w, h);
                r.hud.x = std::min(r.hud.x, w - 8);
                r.messages.x = std::min(r.messages.x, w - 8);
                if (!(mask & 1)) r.profile = {0, 0};
                if (!(mask & 2)) r.legend = {0, 0};
                if (!(mask & 4)) r.messages = {0, 0};
                r.plots = (mask & 8) != 0;
                r.speeds = (mask & 16) != 0;
                if (!(mask & 32)) r.inspector = {0, 0};
                const PanelLayout l = layoutPanels(r);
                expectNoOverlapAndInside(r, l);
                if (::testing::Test::HasFailure()) return;
            }
        }
    }
}

TEST(PanelLayout, TheInspectorTakesTheBottomRightAndThePanelsStackAboveIt) {
    LayoutRequest r = everythingOn(800, 800);
    r.messages = {0, 0};
    r.profile = {0, 0};
    const PanelLayout l = layoutPanels(r);
    ASSERT_GT(l.inspector.w, 0);
    EXPECT_EQ(l.inspector.x + l.inspector.w, 800 - kPanelMargin);
    EXPECT_EQ(l.inspector.y + l.inspector.h, 800 - kPanelMargin);
    ASSERT_GT(l.speeds.w, 0);
    EXPECT_LE(l.speeds.y + l.speeds.h, l.inspector.y - kPanelGap);
    ASSERT_GT(l.plots.w, 0);
    EXPECT_LE(l.plots.y + l.plots.h, l.speeds.y - kPanelGap);
}

TEST(PanelLayout, AWindowTooNarrowForTheColumnBesideTheBoxFoldsItsPanelsAway) {
    // 600x600 with the control panel open (300 px): the bins' histogram and the plots would
    // leave the box 72 px; they fold away, and the layout says so.
    LayoutRequest r = everythingOn(600, 600);
    r.left = 300;
    r.bins = true;
    const PanelLayout folded = layoutPanels(r);
    EXPECT_TRUE(folded.columnFolded);
    EXPECT_EQ(folded.bins.w, 0);
    EXPECT_EQ(folded.plots.w, 0);
    EXPECT_EQ(folded.speeds.w, 0);
    EXPECT_EQ(folded.profile.w, 0);
    EXPECT_GT(folded.hud.w, 0);
    // With the control panel folded to its strip the column fits again (the bins alone).
    r.left = 40;
    r.plots = r.speeds = false;
    r.profile = r.inspector = {0, 0};
    const PanelLayout shown = layoutPanels(r);
    EXPECT_FALSE(shown.columnFolded);
    EXPECT_GT(shown.bins.w, 0);
    // Nothing asked for, nothing folded.
    LayoutRequest none;
    none.width = none.height = 600;
    none.left = 300;
    EXPECT_FALSE(layoutPanels(none).columnFolded);
}

TEST(PanelLayout, InABandUnderTheBoxTheChartsStandSideBySideLeftOfTheInspector) {
    // The momentum lesson at 200 %: a band 260 pixels high under its wide, low box, above the
    // messages' band; the inspector (a click with the panel folded) stands at its right.
    LayoutRequest r = everythingOn(1600, 1000);
    r.left = 88;
    r.scale = 2.0;
    r.profile = {0, 0};
    r.chartsBand = chartsBandRect(1600, 1000, 88, 114, chartsBandHeight(2.0));
    const PanelLayout l = layoutPanels(r);
    expectNoOverlapAndInside(r, l);
    EXPECT_FALSE(l.columnFolded);
    ASSERT_GT(l.plots.w, 0);
    ASSERT_GT(l.speeds.w, 0);
    EXPECT_EQ(l.plots.y, r.chartsBand.y);
    EXPECT_LE(l.plots.y + l.plots.h, r.chartsBand.y + r.chartsBand.h);
    // One row as high as a plot's least at 200 %: three tick labels (two rows of 128 pixels
    // had one each).
    EXPECT_EQ(l.plotRows, 1);
    EXPECT_GE(l.plotRowHeight, 2 * kPlotRowMinHeight);
    EXPECT_GE(l.plots.w, 2 * kPanelMinWidth);
    for (int k = 0; k < l.plotColumns; ++k)
        EXPECT_GE(plotColumn(l, k).w, 2 * kPlotColumnMinWidth);
    EXPECT_LT(l.plots.x + l.plots.w, l.speeds.x) << "side by side";
    EXPECT_LE(l.speeds.y + l.speeds.h, r.chartsBand.y + r.chartsBand.h);
    if (l.inspector.w > 0 && l.inspector.y < r.chartsBand.y + r.chartsBand.h) {
        EXPECT_LE(l.speeds.x + l.speeds.w, l.inspector.x - kPanelGap);
    }
}

TEST(PanelLayout, PanelsThatAreOffGetNoBox) {
    LayoutRequest r;
    r.width = 800;
    r.height = 800;
    r.hud = {400, 100};
    const PanelLayout l = layoutPanels(r);
    EXPECT_EQ(l.plots.w, 0);
    EXPECT_EQ(l.speeds.w, 0);
    EXPECT_EQ(l.profile.w, 0);
    EXPECT_EQ(l.legend.w, 0);
    EXPECT_EQ(l.inspector.w, 0);
    EXPECT_EQ(l.hud.w, 400);
}

TEST(PanelLayout, TheLegendKeepsOffTheBoxTakingTheHighestFreePlace) {
    // A HUD across the window pushes the legend below it, where the box's top-right corner
    // is: it goes to the highest free place, the rightmost there, clear of the box and the HUD.
    LayoutRequest r;
    r.width = 1200;
    r.height = 800;
    r.hud = {1100, 200};
    r.legend = {300, 80};
    r.box = {100, 230, 1000, 400};  // right of it 92 pixels, below it 170
    const PanelLayout l = layoutPanels(r);
    ASSERT_GT(l.legend.w, 0);
    EXPECT_FALSE(overlaps(l.legend, r.box));
    EXPECT_FALSE(overlaps(l.legend, l.hud));
    // Below the box, at the right.
    EXPECT_EQ(l.legend.y, r.box.y + r.box.h + kPanelGap);
    EXPECT_EQ(l.legend.x + l.legend.w, r.width - kPanelMargin);
    // Room right of the HUD: the corner, as without a box.
    r.hud = {700, 200};
    const PanelLayout beside = layoutPanels(r);
    EXPECT_EQ(beside.legend.y, 4);
    EXPECT_EQ(beside.legend.x + beside.legend.w, r.width - kPanelMargin);
}

}  // namespace
}  // namespace psb::app

namespace psb::app {
namespace {

TEST(PanelLayout, APlotsColumnTooShortForAllFourNamesTheOthersUnderThem) {
    LayoutRequest r;
    r.width = 1280;
    r.height = 300;
    r.left = 310;
    r.plots = true;
    r.plotsNote = 20;
    const PanelLayout l = layoutPanels(r);
    ASSERT_GT(l.plots.w, 0);
    ASSERT_LT(plotsShown(l), 4) << "the case: a short window";
    EXPECT_EQ(l.plotsNote, 20);
    EXPECT_GE(l.plots.h, l.plotRows * l.plotRowHeight + 8 + l.plotsNote);
    EXPECT_EQ(plotsLeftOutNote(plotsShown(l)).rfind("No room: ", 0), 0u);
    // Tall enough for the four: no note.
    r.height = 1000;
    const PanelLayout tall = layoutPanels(r);
    EXPECT_EQ(plotsShown(tall), 4);
    EXPECT_EQ(tall.plotsNote, 0);
    EXPECT_EQ(plotsLeftOutNote(4), "");
    EXPECT_EQ(plotsLeftOutNote(1), "No room: energy, py, rate");
    EXPECT_EQ(plotsLeftOutNote(2), "No room: py, rate");
    EXPECT_EQ(plotsLeftOutNote(3), "No room: rate");
}

TEST(PanelLayout, TheMomentumPlotsAreTheLastLeftOut) {
    // Lesson 1 at 200 % with the values table: only the energy's chart fitted, and the lesson
    // is about the momentum px (py is 0 there). Fewer plots keep px, then the energy, then
    // py, in their order on screen.
    EXPECT_EQ(plotsChosen(1), (std::vector<int>{1}));
    EXPECT_EQ(plotsChosen(2), (std::vector<int>{0, 1}));
    EXPECT_EQ(plotsChosen(3), (std::vector<int>{0, 1, 2}));
    EXPECT_EQ(plotsChosen(4), (std::vector<int>{0, 1, 2, 3}));
    EXPECT_TRUE(plotsChosen(0).empty());
}

TEST(PanelLayout, TheSideColumnsLeftEdgeIsWhereItsChartsStand) {
    LayoutRequest r;
    r.width = 1280;
    r.height = 800;
    r.left = 310;
    EXPECT_EQ(sideColumnLeft(r), r.width) << "no charts asked for";
    r.plots = true;
    const PanelLayout l = layoutPanels(r);
    ASSERT_GT(l.plots.w, 0);
    EXPECT_EQ(sideColumnLeft(r), l.plots.x);
    r.foldColumn = true;
    EXPECT_EQ(sideColumnLeft(r), r.width) << "folded away";
}

}  // namespace
}  // namespace psb::app
