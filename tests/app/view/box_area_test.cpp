// The areas the view gives the session for the box (view/box_area.hpp): beside the control panel
// open or folded, below the HUD's band (taller when its lines wrap or the folded-charts note is
// shown), above the messages, left of the side column where it fits, and the help's pages.

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "view/box_area.hpp"
#include "view/fixed_measure.hpp"
#include "view/hud.hpp"
#include "view/overlays.hpp"
#include "view/screen_layout.hpp"

namespace psb::app {
namespace {

const test::FixedMeasure kFont;
const ControlsWidth kControls{310.0, 44.0};

TEST(WindowLayout, TheBoxKeepsClearOfTheControlPanelTheHudAndTheMessages) {
    const WindowLayout l = windowLayout(kFont, 1280, 800, kControls);
    EXPECT_EQ(l.controlsOpen.left, 310.0);
    EXPECT_EQ(l.controlsFolded.left, 44.0);
    EXPECT_EQ(l.controlsOpenColumn.left, 310.0);
    EXPECT_EQ(l.controlsFoldedColumn.left, 44.0);
    for (const BoxArea& a :
         {l.controlsOpen, l.controlsFolded, l.controlsOpenColumn, l.controlsFoldedColumn}) {
        EXPECT_GT(a.top, 4.0 * kFont.lineHeight());  // the HUD's lines
        EXPECT_EQ(a.bottom,
                  static_cast<double>(kMessageLines) * kFont.lineHeight() + 4.0 + kPanelMargin);
    }
    // No side column asked for: nothing at the right but the inspector's column, when the box
    // can spare it.
    EXPECT_EQ(l.controlsOpen.right, 0.0);
    EXPECT_GT(l.controlsOpen.spareColumn, 0.0);
    EXPECT_EQ(l.controlsFolded.spareColumn, l.controlsOpen.spareColumn);
}

TEST(WindowLayout, TheSideColumnIsKeptFreeWhereItFitsAndFoldedWithANoteWhereNot) {
    const WindowLayout wide = windowLayout(kFont, 1280, 800, kControls);
    ASSERT_TRUE(sideColumnFits(1280, 310));
    EXPECT_EQ(wide.controlsOpenColumn.right, sideColumnWidth(1280, 310) + kPanelMargin);
    EXPECT_EQ(wide.controlsOpenColumn.spareColumn, 0.0);
    EXPECT_EQ(wide.controlsOpenColumn.top, wide.controlsOpen.top);

    // 600 pixels wide: no room for the column beside the open control panel, room beside the
    // folded one.
    const WindowLayout narrow = windowLayout(kFont, 600, 600, kControls);
    ASSERT_FALSE(sideColumnFits(600, 310));
    ASSERT_TRUE(sideColumnFits(600, 44));
    EXPECT_EQ(narrow.controlsOpenColumn.right, 0.0);
    EXPECT_EQ(narrow.controlsOpenColumn.spareColumn, narrow.controlsOpen.spareColumn);
    EXPECT_GT(narrow.controlsOpenColumn.top, narrow.controlsOpen.top) << "the folded note";
    EXPECT_EQ(narrow.controlsFoldedColumn.right, sideColumnWidth(600, 44) + kPanelMargin);
    EXPECT_EQ(narrow.controlsFoldedColumn.top, narrow.controlsFolded.top);
}

TEST(WindowLayout, AtTwiceTheScaleTheBandsAndTheColumnGrowWithTheText) {
    // The UI at 200 %: fonts twice the size, the control panel twice as wide (controlsWidth of
    // the pixel ratio × the scale), the side column's limits doubled.
    const test::FixedMeasure big(2);
    const ControlsWidth controls{620.0, 88.0, 2.0};
    const WindowLayout one = windowLayout(kFont, 1920, 1080, kControls);
    const WindowLayout two = windowLayout(big, 1920, 1080, controls);
    EXPECT_EQ(two.controlsOpen.left, 620.0);
    EXPECT_EQ(two.controlsOpen.bottom - kPanelMargin - 4.0,
              2.0 * (one.controlsOpen.bottom - kPanelMargin - 4.0));
    EXPECT_GT(two.controlsOpen.top, 1.8 * one.controlsOpen.top);
    // The inspector's column: its text twice as wide (its few pixels of padding are not).
    EXPECT_NEAR(two.controlsOpen.spareColumn, 2.0 * one.controlsOpen.spareColumn, 24.0);
    ASSERT_TRUE(sideColumnFits(1920, 620, 2.0));
    EXPECT_EQ(two.controlsOpenColumn.right, sideColumnWidth(1920, 620, 2.0) + kPanelMargin);
    EXPECT_EQ(sideColumnWidth(1920, 620, 2.0), 520) << "two fifths of the room, within 440-660";
    EXPECT_EQ(sideColumnWidth(1920, 310, 1.0), 330) << "the same window at 100 %: at most 330";
    // A window the column fits beside at 100 % but not at 300 %.
    EXPECT_TRUE(sideColumnFits(1280, 310, 1.0));
    EXPECT_FALSE(sideColumnFits(1280, 930, 3.0));
}

// A phone upright, 390 CSS pixels at 3 pixels a point: the panel's 930 pixels would leave the box
// 240 pixels, 80 points, a sliver. The box's room is counted in points.
TEST(WindowLayout, ThePanelFitsBesideTheBoxByPointsNotPixels) {
    EXPECT_TRUE(controlsFit(550, kControls));
    EXPECT_FALSE(controlsFit(549, kControls));
    const ControlsWidth phone{930.0, 132.0, 3.0};
    EXPECT_FALSE(controlsFit(1170, phone));
    EXPECT_FALSE(windowLayout(kFont, 1170, 2532, phone).controlsFit);
    EXPECT_TRUE(controlsFit(1650, phone));
}

TEST(WindowLayout, TheHudsBandGrowsWhenItsLinesWrap) {
    const WindowLayout wide = windowLayout(kFont, 1600, 1000, kControls);
    // (Not so narrow that the HUD takes its short lines: hudIsNarrow.)
    const WindowLayout narrow = windowLayout(kFont, 800, 1000, kControls);
    EXPECT_GT(narrow.controlsOpen.top, wide.controlsOpen.top);
    // Beside the folded strip the HUD has more room than beside the open panel.
    EXPECT_LE(narrow.controlsFolded.top, narrow.controlsOpen.top);
}

TEST(WindowLayout, TheHudsBandHoldsItsWrappedLinesAndTheLabelsNoteAtEveryScale) {
    // The HUD as the ramp and the lesson show it, with the note about labels left out, wrapped
    // to the room right of the control panel: the box's area starts below all of it. At 200 %
    // in 1024 x 768 beside the open panel the ramp's lines wrapped to more lines than the band
    // counted ("momentum (0, 0) kg" and "m/s"), and the box's top ran under them.
    HudData ramp;
    ramp.particles = 3;
    ramp.spawnMass = 1.0;
    ramp.spawnRadius = 0.12;
    ramp.arrowSeconds = 1.0 / 3.0;
    ramp.paused = true;
    HudData lesson = ramp;
    lesson.particles = 2;
    lesson.kineticEnergy = 3.5;
    lesson.momentum = Vec2(-1.0, 0.0);
    lesson.spawnMass = 3.0;
    lesson.spawnRadius = 0.35;
    HudData running = lesson;
    running.simTime = 2.47;
    running.paused = false;
    running.momentum = Vec2(12.3, -4.56);
    for (const double scale : {1.0, 1.25, 2.0}) {
        const test::FixedMeasure font(scale);
        const ControlsWidth controls{310.0 * scale, 44.0 * scale, scale};
        for (const auto& [width, height] : {std::pair{800, 600}, {1024, 768}, {1600, 1000}}) {
            const WindowLayout l = windowLayout(font, width, height, controls);
            for (const BoxArea& a : {l.controlsOpen, l.controlsFolded}) {
                const int room = width - static_cast<int>(a.left);
                // In a narrow window the HUD's short lines (hudIsNarrow), as frame_view.cpp.
                const bool narrow = hudIsNarrow(font, room);
                for (HudData d : {ramp, lesson, running}) {
                    d.narrow = narrow;
                    std::vector<std::string> hud = wrapHudLines(font, hudLines(d), room - 8);
                    for (const std::string& line :
                         wrapLines(font, {labelsLeftOutNote(2, false, narrow)}, room - 8)) {
                        hud.push_back(line);
                    }
                    const PixelPoint box = textBoxSize(font, hud);
                    EXPECT_GE(a.top, 4 + box.y) << width << "x" << height << " at " << scale << ", "
                                                << room << " pixels beside the panel";
                    EXPECT_LE(box.x, room) << "no line runs past the window's edge";
                }
            }
        }
    }
}

TEST(WindowLayout, TheHelpsPagesAreCountedForTheWindow) {
    const auto pages = [](int width, int height) {
        const PixelRect room = helpRoom(width, height);
        return static_cast<int>(helpPages(kFont, helpLines(), {room.w, room.h}).size());
    };
    const WindowLayout small = windowLayout(kFont, 500, 400, kControls);
    EXPECT_EQ(small.helpPages, pages(500, 400));
    EXPECT_GT(small.helpPages, 1);
    EXPECT_EQ(windowLayout(kFont, 1600, 1000, kControls).helpPages, pages(1600, 1000));
}

}  // namespace
}  // namespace psb::app
