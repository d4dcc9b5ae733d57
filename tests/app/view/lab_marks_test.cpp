// The grid and the ruler as drawn (lab_marks.hpp): round steps at least so many pixels apart,
// lines within the box's visible part, labels in metres, the ruler's ticks and reading.

#include <gtest/gtest.h>

#include <algorithm>

#include "view/fixed_measure.hpp"
#include "view/lab_marks.hpp"
#include "view/screen_layout.hpp"

namespace psb::app {
namespace {

Camera camera(double zoom, Vec2 offset = Vec2::Zero()) {
    Camera c;
    c.setViewport(800, 600);
    c.set(zoom, offset);
    return c;
}

bool hasLabel(const std::vector<MarkLabel>& labels, const std::string& text) {
    return std::any_of(labels.begin(), labels.end(),
                       [&](const MarkLabel& l) { return l.text == text; });
}

TEST(GridView, RoundStepsOfAtLeastSixtyPixelsAcrossTheBox) {
    // 7 m at 80 pixels a metre: 60 pixels is 0.75 m, so lines every metre, 0 to 7 each way
    // (the 600-pixel viewport shows 7.5 m).
    const GridView g = gridView(camera(80.0), 7.0, 7.0);
    EXPECT_DOUBLE_EQ(g.step, 1.0);
    EXPECT_EQ(g.lines.size(), 8u + 8u);
    EXPECT_TRUE(hasLabel(g.labels, "1 m"));
    EXPECT_TRUE(hasLabel(g.labels, "6 m"));
    EXPECT_FALSE(hasLabel(g.labels, "7 m"));  // the far edges and the corner are left bare
    EXPECT_FALSE(hasLabel(g.labels, "0"));
    EXPECT_EQ(g.legend, "Grid: 1.00 m squares, from the top-left corner (y down)");
    // Every fifth line strong: x = 0 and 5.
    EXPECT_EQ(std::count_if(g.lines.begin(), g.lines.end(),
                            [](const MarkLine& l) { return l.strong && l.a.x() == l.b.x(); }),
              2);
    // At 200 % the lines keep 120 pixels apart, so their larger labels do not run together.
    EXPECT_DOUBLE_EQ(gridView(camera(80.0), 7.0, 7.0, false, 2.0 * kGridMinPixels).step, 2.0);
    // At 0.1 pixel a metre, 60 pixels is 600 m: a 7 km box gets a line every kilometre.
    const GridView far = gridView(camera(0.1), 7000.0, 7000.0);
    EXPECT_DOUBLE_EQ(far.step, 1000.0);
    EXPECT_TRUE(hasLabel(far.labels, "1000 m"));
    // Small boxes get decimals: 5 cm steps at 1000 pixels a metre.
    const GridView small = gridView(camera(1000.0), 0.4, 0.3);
    EXPECT_DOUBLE_EQ(small.step, 0.1);
    EXPECT_TRUE(hasLabel(small.labels, "0.1 m"));
    EXPECT_TRUE(hasLabel(small.labels, "0.3 m"));
}

TEST(GridView, ASmallBoxKeepsALineAndALabelEachWay) {
    // The ramp's 4 m x 3.9 m box 220 pixels wide at 200 %: lines 120 pixels apart would be
    // 5 m apart, wider than the box, and it had no line nor label at all. The next finer
    // round step, 2 m, is 110 pixels apart.
    const GridView g = gridView(camera(55.0), 4.0, 3.9, true, 2.0 * kGridMinPixels, 34.0);
    EXPECT_DOUBLE_EQ(g.step, 2.0);
    EXPECT_TRUE(std::any_of(g.labels.begin(), g.labels.end(),
                            [](const MarkLabel& l) { return !l.left && l.text == "2 m"; }));
    EXPECT_TRUE(std::any_of(g.labels.begin(), g.labels.end(),
                            [](const MarkLabel& l) { return l.left && l.text == "2 m"; }));
    // A box of 20 pixels keeps none rather than lines 4 pixels apart.
    EXPECT_TRUE(gridView(camera(5.0), 4.0, 3.9).labels.empty());
}

TEST(GridView, WithYUpTheHeightsCountFromTheFloor) {
    // A 6.5 m high box at 80 pixels a metre: lines every metre up from the floor, so the
    // label "1 m" is on the line 5.5 m below the top edge, and a line 0.5 m below the top edge
    // (6 m up) is where y down would have none.
    const Camera cam = camera(80.0);
    const GridView g = gridView(cam, 7.0, 6.5, true);
    EXPECT_EQ(g.legend, "Grid: 1.00 m squares, from the bottom-left corner (y up)");
    const auto labelAt = [&](const std::string& text) {
        for (const MarkLabel& l : g.labels)
            if (l.text == text && l.left) {
                return cam.screenToWorld(l.at).y();
            }
        return -1.0;
    };
    EXPECT_NEAR(labelAt("1 m"), 5.5, 1e-9);
    EXPECT_NEAR(labelAt("6 m"), 0.5, 1e-9);
    const GridView down = gridView(cam, 7.0, 6.5, false);
    EXPECT_NEAR(
        cam.screenToWorld(std::find_if(down.labels.begin(), down.labels.end(),
                                       [](const MarkLabel& l) { return l.left && l.text == "1 m"; })
                              ->at)
            .y(),
        1.0, 1e-9);
}

TEST(GridView, OnlyTheVisiblePartAndNothingForABoxOffScreen) {
    // Looking at x from 3 m on: no line left of it.
    const GridView g = gridView(camera(100.0, Vec2(3.0, 0.0)), 20.0, 5.0);
    for (const MarkLine& l : g.lines)
        EXPECT_GE(l.a.x(), -1e-9);
    EXPECT_TRUE(gridView(camera(100.0, Vec2(50.0, 0.0)), 7.0, 7.0).lines.empty());
    EXPECT_TRUE(gridView(camera(100.0), 0.0, 7.0).lines.empty());
}

TEST(RulerView, TicksAtRoundStepsAndItsReadingBesideIt) {
    LabRuler r;
    r.place(4.0, 2.0);  // (1, 1) to (3, 1): 2 m
    const RulerView v = rulerView(r, camera(100.0));
    EXPECT_EQ(v.a, Vec2(100.0, 100.0));
    EXPECT_EQ(v.b, Vec2(300.0, 100.0));
    EXPECT_DOUBLE_EQ(v.tickStep, 0.1);  // 8 pixels is 0.08 m
    EXPECT_EQ(v.ticks.size(), 21u);
    EXPECT_TRUE(v.ticks[0].strong);
    EXPECT_FALSE(v.ticks[1].strong);
    EXPECT_TRUE(v.ticks[5].strong);
    EXPECT_EQ(v.label.text, "2.00 m, 0.0\u00b0 (horizontal 2.00 m, vertical 0 m)");
    EXPECT_GT(v.label.at.y(), 100.0);  // below a level ruler
    r.take(LabRuler::Part::EndB, r.b());
    r.moveTo(Vec2(4.0, 5.0));  // a 3-4-5 triangle
    EXPECT_EQ(rulerLine(r), "5.00 m, 53.1\u00b0 (horizontal 3.00 m, vertical 4.00 m)");
    // Zoomed far out, the ticks stay countable.
    EXPECT_LE(rulerView(r, camera(1e-3)).ticks.size(), 2001u);
}

TEST(MarkLabels, TheRulersReadingIsReadWholeBesideThePanelAndNoGridLabelCrossesIt) {
    // The ramp lesson's ruler on the top ramp, near the left wall, beside the control panel
    // (310 pixels): its reading, centred on the ruler's middle, ran under the panel and lost its
    // first digit (".55 m"), and a grid label along the top edge was drawn across it.
    const test::FixedMeasure font;
    const Camera c = camera(100.0, Vec2(-3.3, -0.2));  // the box's top-left at (330, 20)
    LabRuler r;
    r.place(8.0, 5.0);
    r.take(LabRuler::Part::EndA, r.a());
    r.moveTo(Vec2(0.2, 0.75));
    r.take(LabRuler::Part::EndB, r.b());
    r.moveTo(Vec2(0.9, 1.0));
    RulerView ruler = rulerView(r, c);
    GridView grid = gridView(c, 8.0, 5.0);
    const PixelRect room{310, 0, 490, 600};
    ASSERT_LT(labelRect(ruler.label, font, kReadingPad).x, room.x) << "the case: under the panel";
    const std::size_t labels = grid.labels.size();
    const PixelRect hud{320, 0, 400, 12};
    keepMarkLabelsClear(&grid, &ruler, font, {room, {}, {}, {hud}});
    const PixelRect reading = labelRect(ruler.label, font, kReadingPad);
    EXPECT_GE(reading.x, room.x);
    EXPECT_LE(reading.x + reading.w, room.x + room.w);
    EXPECT_FALSE(overlaps(reading, hud));
    for (const MarkLabel& l : grid.labels) {
        EXPECT_FALSE(overlaps(labelRect(l, font), reading)) << l.text;
        EXPECT_FALSE(overlaps(labelRect(l, font), hud)) << l.text;
        EXPECT_GE(labelRect(l, font).x, room.x) << l.text;
    }
    EXPECT_GT(grid.labels.size(), labels / 2) << "those not under the reading stay";
}

TEST(MarkLabels, TheRulersReadingGoesWhereItCoversNoGridLabel) {
    // The ruler laid along a ramp at 200 % with the grid: the reading's first place, below the
    // ruler's middle, lay over a grid distance, which was left out. It avoids the grid's
    // labels as it avoids the balls, where a place is clear of them.
    const test::FixedMeasure font(2.0);
    const Camera c = camera(200.0, Vec2(-1.65, -0.1));  // the box's top-left at (330, 20)
    LabRuler r;
    r.place(4.0, 3.9);
    r.take(LabRuler::Part::EndA, r.a());
    r.moveTo(Vec2(1.0, 2.0));
    r.take(LabRuler::Part::EndB, r.b());
    r.moveTo(Vec2(2.5, 2.0));
    RulerView ruler = rulerView(r, c);
    GridView grid;
    // A distance right under the ruler's middle, where the reading goes first.
    const Vec2 middle = 0.5 * (ruler.a + ruler.b);
    grid.labels.push_back({middle + Vec2(0.0, 40.0), "2 m"});
    grid.labels.push_back({Vec2(middle.x() + 300.0, 60.0), "3 m"});
    const PixelRect room{310, 0, 1290, 1000};
    keepMarkLabelsClear(&grid, &ruler, font, {room, {}, {}, {}});
    const PixelRect reading = labelRect(ruler.label, font, kReadingPad);
    EXPECT_EQ(grid.labels.size(), 2u) << "every grid label kept";
    for (const MarkLabel& l : grid.labels)
        EXPECT_FALSE(overlaps(labelRect(l, font), reading)) << l.text;
}

TEST(MarkLabels, TheRulersReadingCoversNoBallWhereAPlaceFartherOutIsClear) {
    // The ramp at 200 % as its bodies rolled: every place within 200 pixels of the ruler's
    // middle covered a ball, and the reading took the one that covered fewest (one ball) while
    // the room above the box was clear. It goes there; and where a place is clear of the balls
    // only over a grid label, it covers the label (left out), not a ball.
    const test::FixedMeasure font(2.0);
    const Camera c = camera(200.0, Vec2(-1.65, -1.0));  // the box's top-left at (330, 200)
    LabRuler r;
    r.place(4.0, 3.9);
    r.take(LabRuler::Part::EndA, r.a());
    r.moveTo(Vec2(1.0, 2.0));
    r.take(LabRuler::Part::EndB, r.b());
    r.moveTo(Vec2(2.5, 2.0));
    const RulerView fresh = rulerView(r, c);
    const Vec2 middle = 0.5 * (fresh.a + fresh.b);
    // Balls 30 pixels across, 40 apart, over the 520 pixels square round the middle.
    std::vector<PixelRect> balls;
    for (int y = -260; y <= 260; y += 40) {
        for (int x = -260; x <= 260; x += 40) {
            balls.push_back({static_cast<int>(middle.x()) + x - 15,
                             static_cast<int>(middle.y()) + y - 15, 30, 30});
        }
    }
    const PixelRect room{310, 0, 1290, 1000};
    RulerView ruler = fresh;
    keepMarkLabelsClear(nullptr, &ruler, font, {room, {}, {}, {}}, balls);
    PixelRect reading = labelRect(ruler.label, font, kReadingPad);
    for (const PixelRect& b : balls)
        ASSERT_FALSE(overlaps(reading, b)) << "at " << reading.x << "," << reading.y;
    EXPECT_GE(reading.x, room.x);
    EXPECT_LE(reading.y + reading.h, room.y + room.h);
    // Now the room ends where the balls do, but for a row below them 90 pixels high (the two-line
    // reading's 72 fit, the three-line's 106 do not), with a grid label in its middle.
    const PixelRect tight{static_cast<int>(middle.x()) - 275, static_cast<int>(middle.y()) - 275,
                          560, 640};
    GridView grid;
    grid.labels.push_back({Vec2(middle.x(), middle.y() + 320.0), "2 m"});
    ruler = fresh;
    keepMarkLabelsClear(&grid, &ruler, font, {tight, {}, {}, {}}, balls);
    reading = labelRect(ruler.label, font, kReadingPad);
    for (const PixelRect& b : balls)
        EXPECT_FALSE(overlaps(reading, b)) << "at " << reading.x << "," << reading.y;
    EXPECT_TRUE(grid.labels.empty()) << "the label under it is left out";
}

TEST(WallAngleLabel, TheWallBeingDrawnReadsItsLengthAndSlopeBeyondItsEnd) {
    const Camera c = camera(100.0);
    const MarkLabel l = wallAngleLabel(Vec2(0.0, 0.45), Vec2(2.6, 1.3963), c);
    EXPECT_EQ(l.text, "2.77 m, 20.0\u00b0");
    EXPECT_GT(l.at.x(), 260.0);  // beyond the end at x = 260 pixels
    EXPECT_EQ(wallAngleLabel(Vec2(1, 1), Vec2(1, 3), c).text, "2.00 m, 90.0\u00b0");
    EXPECT_EQ(wallAngleLabel(Vec2(1, 1), Vec2(1, 1), c).text, "0 m, 0.0\u00b0");
}

}  // namespace
}  // namespace psb::app
