// Where the particles' labels go (label_places.hpp): every ball of a small scene keeps a
// label, none over another ball, another label or a panel, all inside the window.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "view/label_places.hpp"
#include "view/screen_layout.hpp"

namespace psb::app {
namespace {

/// `n` balls `radius` pixels in radius in rows across a walled box at `box`, each with a
/// `size` label.
std::vector<LabelAsk> ballsIn(const PixelRect& box, int n, int radius, PixelPoint size) {
    std::vector<LabelAsk> asks;
    const int across = 5;
    for (int k = 0; k < n; ++k) {
        const int cx = box.x + box.w * (2 * (k % across) + 1) / (2 * across);
        const int cy = box.y + box.h * (2 * (k / across) + 1) / (2 * ((n + across - 1) / across));
        const int r = radius + 2;  // the gap the renderer keeps round a disc
        asks.push_back({{cx - r, cy - r, 2 * r, 2 * r}, size, true});
    }
    return asks;
}

/// Whether the middle of `label` (ball `i`'s) is nearer its own disc's rim than any other's:
/// a label without a leader line is read as the nearest ball's.
bool nearestIsOwn(const std::vector<LabelAsk>& asks, const PixelRect& label, std::size_t i) {
    const double px = label.x + 0.5 * label.w, py = label.y + 0.5 * label.h;
    const auto rim = [&](const PixelRect& d) {
        return std::hypot(d.x + 0.5 * d.w - px, d.y + 0.5 * d.h - py) - 0.5 * d.w;
    };
    for (std::size_t j = 0; j < asks.size(); ++j) {
        if (j != i && rim(asks[j].disc) <= rim(asks[i].disc)) return false;
    }
    return true;
}

void expectReadable(const std::vector<LabelAsk>& asks, const std::vector<LabelPlace>& places,
                    const PixelRect& window, const std::vector<PixelRect>& panels) {
    ASSERT_EQ(places.size(), asks.size());
    for (std::size_t i = 0; i < places.size(); ++i) {
        const PixelRect& r = places[i].at;
        ASSERT_GT(r.w, 0) << "ball " << i << " lost its label";
        EXPECT_GE(r.x, window.x) << i;
        EXPECT_GE(r.y, window.y) << i;
        EXPECT_LE(r.x + r.w, window.x + window.w) << i;
        EXPECT_LE(r.y + r.h, window.y + window.h) << i;
        for (std::size_t j = 0; j < asks.size(); ++j)
            EXPECT_FALSE(overlaps(r, asks[j].disc)) << "label " << i << " over ball " << j;
        for (std::size_t j = i + 1; j < places.size(); ++j)
            EXPECT_FALSE(overlaps(r, places[j].at)) << "labels " << i << " and " << j;
        for (const PixelRect& p : panels)
            EXPECT_FALSE(overlaps(r, p)) << "label " << i << " under a panel";
        if (!places[i].leader) {
            EXPECT_TRUE(nearestIsOwn(asks, r, i)) << "label " << i << " nearer another ball";
            continue;
        }
        // Away from its ball, half its height clear of every other ball.
        for (std::size_t j = 0; j < asks.size(); ++j) {
            if (j == i) continue;
            const PixelRect& d = asks[j].disc;
            const double half = 0.5 * d.w, cx = d.x + half, cy = d.y + half;
            const double ex = std::max({r.x - cx, 0.0, cx - (r.x + r.w)});
            const double ey = std::max({r.y - cy, 0.0, cy - (r.y + r.h)});
            EXPECT_GE(std::hypot(ex, ey) - half, std::max(4, r.h / 2))
                << "label " << i << ", away from its ball, touches ball " << j;
        }
        // Its line, a point a pixel, over no other label nor ball (it ran through the text of
        // the mass-ratio preset's labels).
        const LeaderLine l = leaderLine(asks[i].disc, r);
        const double length = std::hypot(l.bx - l.ax, l.by - l.ay);
        for (double t = 0.0; t <= length; t += 1.0) {
            const double x = l.ax + (l.bx - l.ax) * t / std::max(length, 1.0);
            const double y = l.ay + (l.by - l.ay) * t / std::max(length, 1.0);
            const auto inside = [x, y](const PixelRect& o, int g) {
                return x > o.x + g && x < o.x + o.w - g && y > o.y + g && y < o.y + o.h - g;
            };
            for (std::size_t j = 0; j < places.size(); ++j) {
                if (j == i) continue;
                EXPECT_FALSE(inside(places[j].at, 0))
                    << "label " << i << "'s line over label " << j;
                EXPECT_FALSE(inside(asks[j].disc, 2)) << "label " << i << "'s line over ball " << j;
            }
        }
    }
}

/// A ball `radius` pixels in radius at (x, y) inside a walled box, with a `size` label.
LabelAsk ball(int x, int y, int radius, PixelPoint size) {
    const int r = radius + 2;  // the gap the renderer keeps round a disc
    return {{x - r, y - r, 2 * r, 2 * r}, size, true};
}

TEST(LabelPlaces, EveryBallOfASmallSceneInASmallBoxKeepsALabelOverNoOtherBall) {
    // Balls in a box too small for their labels beside them: they used to be left out
    // ("Labels: 1 left out") or drawn over other balls. Beside them where there is room, else
    // around them with a line to their ball, they fit: the collision lesson's two balls (at 2
    // and 7 m of its 10 m x 4 m box) at 200 % in 1600 x 1000 (labels of two lines, 300 x 53
    // pixels), the ramp's three bodies in a small box at 200 % in 1024 x 768, and ten balls in
    // a box 300 pixels square at 100 % (labels 175 x 66).
    struct Case {
        std::string name;
        PixelRect window, box;
        int panel, hud;
        std::vector<LabelAsk> balls;
    };
    const PixelPoint big{300, 53}, small{175, 66};
    std::vector<Case> cases = {
        {"lesson",
         {0, 0, 1600, 1000},
         {640, 300, 940, 376},
         620,
         200,
         {ball(828, 488, 22, big), ball(1298, 488, 22, big)}},
        {"ramp",
         {0, 0, 1024, 768},
         {330, 230, 400, 250},
         320,
         140,
         {ball(380, 280, 20, big), ball(480, 350, 20, big), ball(580, 420, 20, big)}},
        {"ten",
         {0, 0, 1024, 768},
         {330, 230, 300, 300},
         320,
         100,
         ballsIn({330, 230, 300, 300}, 10, 14, small)}};
    for (const Case& c : cases) {
        const int w = c.window.w, h = c.window.h;
        const std::vector<PixelRect> panels = {{0, 0, c.panel, h},
                                               {c.panel, 0, w - c.panel, c.hud},
                                               {c.panel, h - 60, w - c.panel, 60}};
        const std::vector<LabelPlace> places = placeLabels(c.balls, {c.window, c.box, {}, panels});
        SCOPED_TRACE(c.name);
        expectReadable(c.balls, places, c.window, panels);
    }
}

TEST(LabelPlaces, LabelsSideBySideStandApartAndInsideTheBoxClearOfItsWalls) {
    // Lesson 1 after the collision at 200 %: the balls close together near the box's left wall;
    // the two labels stood some 20 pixels apart on one line and read as one ("particle 1,
    // 1.00 kg particle 2, 3.00 kg"), and label 1 touched the left wall.
    const PixelRect window{0, 0, 1600, 1000};
    const PixelRect box{640, 300, 940, 376};
    const PixelPoint size{300, 53};
    // Centres 320 pixels apart: above each, labels 300 wide stood 20 pixels apart.
    const std::vector<LabelAsk> asks = {ball(700, 500, 22, size), ball(1020, 500, 30, size)};
    const std::vector<LabelPlace> places = placeLabels(asks, {window, box, {}, {}});
    expectReadable(asks, places, window, {});
    const PixelRect& a = places[0].at;
    const PixelRect& b = places[1].at;
    const bool sameRows = a.y < b.y + b.h && b.y < a.y + a.h;
    if (sameRows) {
        const int gap = std::max(b.x - (a.x + a.w), a.x - (b.x + b.w));
        EXPECT_GE(gap, std::min(size.y / 2, kLabelsApart)) << "side by side, they read as one";
    }
    for (const PixelRect& r : {a, b}) {
        const bool inside = r.x >= box.x && r.y >= box.y && r.x + r.w <= box.x + box.w &&
                            r.y + r.h <= box.y + box.h;
        if (!inside) continue;
        EXPECT_GE(r.x - box.x, 4) << "touches the left wall";
        EXPECT_GE(r.y - box.y, 4) << "touches the top wall";
        EXPECT_GE(box.x + box.w - (r.x + r.w), 4) << "touches the right wall";
        EXPECT_GE(box.y + box.h - (r.y + r.h), 4) << "touches the bottom wall";
    }
}

TEST(LabelPlaces, ALabelThatFitsBesideItsBallStaysThereWithoutALeader) {
    const PixelRect window{0, 0, 800, 600};
    const PixelRect box{100, 100, 600, 400};
    const std::vector<LabelAsk> asks = {ball(250, 300, 20, {140, 86}),
                                        ball(550, 300, 20, {140, 86})};
    const std::vector<LabelPlace> places = placeLabels(asks, {window, box, {}, {}});
    expectReadable(asks, places, window, {});
    for (std::size_t i = 0; i < places.size(); ++i) {
        EXPECT_FALSE(places[i].leader);
        EXPECT_EQ(places[i].at.y + places[i].at.h, asks[i].disc.y) << "above its ball";
    }
}

TEST(LabelPlaces, WhereTheValuesLeaveALabelOutEveryLabelTakesItsNameAlone) {
    // The original program's six balls at 800 x 600 (a box 405 pixels square between the
    // panel, the HUD and the messages), with labels of 170 x 71: some find no place. Their
    // names alone (90 x 18) fit, every one of them: all six take their names (labels of one
    // line beside labels of five read as different things, and were).
    const PixelRect window{0, 0, 800, 600};
    const PixelRect box{353, 122, 405, 405};
    const std::vector<PixelRect> panels = {
        {0, 0, 310, 600}, {314, 4, 464, 72}, {314, 537, 440, 55}};
    std::vector<LabelAsk> asks = {ball(437, 190, 16, {170, 71}), ball(537, 173, 7, {170, 71}),
                                  ball(652, 213, 25, {170, 71}), ball(496, 271, 11, {170, 71}),
                                  ball(600, 295, 5, {170, 71}),  ball(698, 313, 21, {170, 71})};
    const LabelRoom room{window, box, {}, panels};
    const std::vector<LabelPlace> values = placeLabels(asks, room);
    const bool valuesFit =
        std::none_of(values.begin(), values.end(), [](const LabelPlace& p) { return p.at.w == 0; });
    ASSERT_FALSE(valuesFit) << "the case no longer needs the names";
    EXPECT_FALSE(values[0].nameOnly) << "no name asked: the values stay";
    for (LabelAsk& a : asks)
        a.nameSize = {90, 18};
    const std::vector<LabelPlace> places = placeLabels(asks, room);
    expectReadable(asks, places, window, panels);
    for (const LabelPlace& p : places) {
        EXPECT_TRUE(p.nameOnly);
        EXPECT_EQ(p.at.h, 18);
    }
    // Where the values fit, every label keeps them.
    const std::vector<LabelAsk> two = {{{240, 290, 20, 20}, {140, 53}, true, {100, 29}},
                                       {{540, 290, 20, 20}, {140, 53}, true, {100, 29}}};
    for (const LabelPlace& p : placeLabels(two, {window, {100, 100, 600, 400}, {}, {}})) {
        EXPECT_GT(p.at.w, 0);
        EXPECT_FALSE(p.nameOnly);
    }
}

TEST(LabelPlaces, ALabelWithoutALineIsNeverNearerAnotherBallThanItsOwn) {
    // The original's six balls at 200 %: a label slid along its ball's side stood nearer the
    // neighbour than its own ball, and read as the neighbour's. Here the first free place
    // beside ball A (slid left above it) has its middle 46 pixels from ball B's rim and 67 from
    // A's; A's label goes where it is nearest A, or joined to A by a line.
    const PixelRect window{0, 0, 1000, 600};
    const std::vector<PixelRect> keepOut = {{600, 228, 40, 10},   // above A, right of its middle
                                            {300, 326, 400, 10},  // below A
                                            {526, 290, 10, 30},   // right of A
                                            {464, 290, 10, 30}};  // left of A
    const std::vector<LabelAsk> asks = {{{478, 278, 44, 44}, {300, 53}, false},   // A at (500, 300)
                                        {{358, 178, 44, 44}, {120, 20}, false}};  // B at (380, 200)
    const std::vector<LabelPlace> places = placeLabels(asks, {window, {}, {}, keepOut});
    ASSERT_GT(places[0].at.w, 0);
    EXPECT_TRUE(places[0].leader || nearestIsOwn(asks, places[0].at, 0))
        << "A's label at " << places[0].at.x << "," << places[0].at.y << " nearer B";
    for (std::size_t i = 0; i < places.size(); ++i) {
        if (places[i].at.w > 0 && !places[i].leader) {
            EXPECT_TRUE(nearestIsOwn(asks, places[i].at, i)) << i;
        }
    }
}

/// The funnel preset at 200 % in 1600 x 1000: its 400 balls of 4 mm (3 pixels) packed in rows
/// at the top of a 0.6 m x 0.8 m box at 744 px/m, its two slanted walls below them.
struct Funnel {
    PixelRect window{0, 0, 1600, 1000};
    PixelRect box{887, 284, 447, 596};
    std::vector<ScreenWall> walls;
    std::vector<PixelRect> panels{{0, 0, 620, 1000}, {620, 0, 980, 240}, {620, 930, 980, 70}};
    std::vector<LabelAsk> balls;

    Funnel() {
        const double zoom = 743.75;
        const auto x = [&](double m) { return box.x + m * zoom; };
        const auto y = [&](double m) { return box.y + m * zoom; };
        walls.push_back({x(0.0), y(0.3), x(0.289), y(0.5), 0.003 * zoom});
        walls.push_back({x(0.6), y(0.3), x(0.311), y(0.5), 0.003 * zoom});
        for (int row = 0; row < 20; ++row) {
            for (int column = 0; column < 20; ++column) {
                const int cx =
                    static_cast<int>(std::lround(x(0.02 + 0.028 * column + 0.014 * (row % 2))));
                const int cy = static_cast<int>(std::lround(y(0.01 + 0.012 * row)));
                LabelAsk a = ball(cx, cy, 3, {300, 53});
                a.nameSize = {148, 29};
                balls.push_back(a);
            }
        }
    }
};

TEST(LabelPlaces, InACrowdLabelsCoverNoBallNorCrossAWallAndTheRestAreLeftOut) {
    // The funnel's labels were drawn over its balls (without their background, outlined) and
    // across its walls, the box's and the slanted ones. Every label drawn is clear of every
    // ball and wall; those with no such place are left out (the HUD counts them).
    const Funnel f;
    const std::vector<LabelPlace> places =
        placeLabels(f.balls, {f.window, f.box, f.walls, f.panels});
    ASSERT_EQ(places.size(), f.balls.size());
    std::size_t drawn = 0;
    for (std::size_t i = 0; i < places.size(); ++i) {
        const PixelRect& r = places[i].at;
        if (r.w == 0) continue;
        ++drawn;
        EXPECT_GE(r.x, f.window.x) << i;
        EXPECT_LE(r.x + r.w, f.window.x + f.window.w) << i;
        EXPECT_GE(r.y, f.window.y) << i;
        EXPECT_LE(r.y + r.h, f.window.y + f.window.h) << i;
        for (std::size_t j = 0; j < f.balls.size(); ++j)
            ASSERT_FALSE(overlaps(r, f.balls[j].disc)) << "label " << i << " over ball " << j;
        const bool inside = r.x >= f.box.x && r.y >= f.box.y && r.x + r.w <= f.box.x + f.box.w &&
                            r.y + r.h <= f.box.y + f.box.h;
        EXPECT_TRUE(inside || !overlaps(r, f.box)) << "label " << i << " across the box's wall";
        for (const ScreenWall& w : f.walls)
            EXPECT_FALSE(crosses(r, w)) << "label " << i << " across the funnel's wall";
        for (const PixelRect& p : f.panels)
            EXPECT_FALSE(overlaps(r, p)) << "label " << i << " under a panel";
        for (std::size_t j = i + 1; j < places.size(); ++j)
            EXPECT_FALSE(overlaps(r, places[j].at)) << "labels " << i << " and " << j;
    }
    EXPECT_GT(drawn, 0u) << "the balls at the edge of the crowd have room beside them";
    EXPECT_LT(drawn, f.balls.size()) << "most are left out";
}

TEST(LabelPlaces, AWallAtAnAngleIsCrossedByTheRectanglesItTouches) {
    const ScreenWall w{100.0, 100.0, 300.0, 200.0, 3.0};
    EXPECT_TRUE(crosses({190, 140, 20, 20}, w)) << "the line through the middle";
    EXPECT_TRUE(crosses({295, 200, 20, 20}, w)) << "over the rounded end";
    EXPECT_TRUE(crosses({202, 153, 10, 10}, w)) << "within its half-width";
    EXPECT_FALSE(crosses({100, 140, 40, 40}, w)) << "below the line";
    EXPECT_FALSE(crosses({310, 100, 40, 40}, w)) << "past its end";
    EXPECT_FALSE(crosses({0, 0, 0, 0}, w)) << "nothing";
}

TEST(LabelPlaces, WithNoFreePlaceALabelIsLeftOutAndSaysWhy) {
    // A panel over the whole window: no place is free.
    const PixelRect window{0, 0, 400, 300};
    const std::vector<LabelAsk> asks = {{{190, 140, 20, 20}, {100, 86}, false}};
    const std::vector<LabelPlace> places = placeLabels(asks, {window, {}, {}, {{0, 0, 400, 300}}});
    EXPECT_EQ(places[0].at.w, 0);
    EXPECT_FALSE(places[0].offWindow);
    // A disc larger than the window: no side of it is inside.
    const std::vector<LabelAsk> huge = {{{-50, -50, 500, 400}, {100, 86}, false}};
    EXPECT_TRUE(placeLabels(huge, {window, {}, {}, {}})[0].offWindow);
}

TEST(LabelPlaces, ALabelIsNotDrawnOverItsOwnBallsArrow) {
    // A ball moving up: the place above it, the first tried, is on its arrow.
    const PixelRect window{0, 0, 800, 600};
    LabelAsk a = ball(400, 300, 10, {160, 70});
    a.arrow = {400.0, 290.0, 400.0, 200.0, 8.0};
    const std::vector<LabelPlace> places = placeLabels({a}, {window, {}, {}, {}});
    ASSERT_EQ(places.size(), 1u);
    ASSERT_GT(places[0].at.w, 0);
    EXPECT_FALSE(crosses(places[0].at, a.arrow));
    EXPECT_FALSE(places[0].leader) << "beside its ball, below it";
}

TEST(LabelPlaces, ALeaderLineCrossesNothingTheRoomKeepsOut) {
    // A ball in a box too small for its label, with room only in a strip above the box
    // (panels all round), and a grid's distance straight above the ball: its values fit only
    // above the distance, on a line through it (it crossed the grid's "2 m"); its name fits
    // under it.
    const PixelRect window{0, 0, 800, 600};
    const PixelRect box{380, 380, 40, 40};
    const PixelRect distance{392, 300, 16, 10};
    const std::vector<PixelRect> keepOut = {distance,
                                            {0, 0, 340, 600},
                                            {460, 0, 340, 600},
                                            {340, 378, 40, 222},
                                            {420, 378, 40, 222},
                                            {380, 422, 40, 178}};
    LabelAsk a = ball(400, 400, 8, {100, 60});
    a.nameSize = {100, 30};
    const std::vector<LabelPlace> places = placeLabels({a}, {window, box, {}, keepOut, 2});
    ASSERT_EQ(places.size(), 1u);
    ASSERT_GT(places[0].at.w, 0);
    EXPECT_FALSE(overlaps(places[0].at, distance));
    if (!places[0].leader) return;
    const LeaderLine l = leaderLine(a.disc, places[0].at);
    const double length = std::hypot(l.bx - l.ax, l.by - l.ay);
    for (double t = 0.0; t <= length; t += 0.5) {
        const double x = l.ax + (l.bx - l.ax) * t / std::max(length, 1.0);
        const double y = l.ay + (l.by - l.ay) * t / std::max(length, 1.0);
        EXPECT_FALSE(x >= distance.x && x <= distance.x + distance.w && y >= distance.y &&
                     y <= distance.y + distance.h)
            << "the line runs through the distance at " << x << ", " << y;
    }
}

}  // namespace
}  // namespace psb::app
