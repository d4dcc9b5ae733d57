// Where the particles' labels go (label_places.hpp): every ball of a small scene keeps a
// label, none over another ball, another label or a panel, all inside the window.

#include <gtest/gtest.h>

#include <algorithm>
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

void expectReadable(const std::vector<LabelAsk>& asks, const std::vector<LabelPlace>& places,
                    const PixelRect& window, const std::vector<PixelRect>& panels) {
    ASSERT_EQ(places.size(), asks.size());
    for (std::size_t i = 0; i < places.size(); ++i) {
        const PixelRect& r = places[i].at;
        ASSERT_GT(r.w, 0) << "ball " << i << " lost its label";
        EXPECT_FALSE(places[i].overDiscs) << i;
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
    // and 7 m of its 10 m x 4 m box) at 200 % in 1600 x 1000 (labels 350 x 131 pixels), the
    // ramp's three bodies in a small box at 200 % in 1024 x 768, and ten balls in a box 300
    // pixels square at 100 % (labels 175 x 66).
    struct Case {
        std::string name;
        PixelRect window, box;
        int panel, hud;
        std::vector<LabelAsk> balls;
    };
    const PixelPoint big{350, 131}, small{175, 66};
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
        const std::vector<LabelPlace> places = placeLabels(c.balls, c.window, c.box, panels);
        SCOPED_TRACE(c.name);
        expectReadable(c.balls, places, c.window, panels);
    }
}

TEST(LabelPlaces, ALabelThatFitsBesideItsBallStaysThereWithoutALeader) {
    const PixelRect window{0, 0, 800, 600};
    const PixelRect box{100, 100, 600, 400};
    const std::vector<LabelAsk> asks = {ball(250, 300, 20, {140, 86}),
                                        ball(550, 300, 20, {140, 86})};
    const std::vector<LabelPlace> places = placeLabels(asks, window, box, {});
    expectReadable(asks, places, window, {});
    for (std::size_t i = 0; i < places.size(); ++i) {
        EXPECT_FALSE(places[i].leader);
        EXPECT_EQ(places[i].at.y + places[i].at.h, asks[i].disc.y) << "above its ball";
    }
}

TEST(LabelPlaces, LabelsWithNoClearPlaceTakeTheirShortFormRatherThanCrossAWall) {
    // The original program's six balls at 800 x 600 (a box 405 pixels square between the
    // panel, the HUD and the messages): their five-line labels (170 x 71) fit only across the
    // walls. Their two-line forms (150 x 29) fit inside the box, clear of every ball.
    const PixelRect window{0, 0, 800, 600};
    const PixelRect box{353, 122, 405, 405};
    const std::vector<PixelRect> panels = {
        {0, 0, 310, 600}, {314, 4, 464, 72}, {314, 537, 440, 55}};
    std::vector<LabelAsk> asks = {ball(437, 190, 16, {170, 71}), ball(537, 173, 7, {170, 71}),
                                  ball(652, 213, 25, {170, 71}), ball(496, 271, 11, {170, 71}),
                                  ball(600, 295, 5, {170, 71}),  ball(698, 313, 21, {170, 71})};
    const std::vector<LabelPlace> full = placeLabels(asks, window, box, panels);
    const bool fullIsClean = std::none_of(full.begin(), full.end(), [](const LabelPlace& p) {
        return p.at.w == 0 || p.overDiscs || p.acrossWall;
    });
    ASSERT_FALSE(fullIsClean) << "the case no longer needs the short form";
    EXPECT_FALSE(full[0].shortForm) << "no short form asked: the full labels stay";
    for (LabelAsk& a : asks)
        a.shortSize = {150, 29};
    const std::vector<LabelPlace> places = placeLabels(asks, window, box, panels);
    expectReadable(asks, places, window, panels);
    for (const LabelPlace& p : places) {
        EXPECT_TRUE(p.shortForm);
        EXPECT_FALSE(p.acrossWall);
        EXPECT_EQ(p.at.h, 29);
        EXPECT_GE(p.at.x, box.x);
        EXPECT_GE(p.at.y, box.y);
        EXPECT_LE(p.at.x + p.at.w, box.x + box.w);
        EXPECT_LE(p.at.y + p.at.h, box.y + box.h);
    }
    // Where the full labels fit, they are kept.
    const std::vector<LabelAsk> two = {{{240, 290, 20, 20}, {140, 86}, true, {100, 29}},
                                       {{540, 290, 20, 20}, {140, 86}, true, {100, 29}}};
    for (const LabelPlace& p : placeLabels(two, window, {100, 100, 600, 400}, {}))
        EXPECT_FALSE(p.shortForm);
}

TEST(LabelPlaces, WithNoFreePlaceALabelIsLeftOutAndSaysWhy) {
    // A panel over the whole window: no place is free.
    const PixelRect window{0, 0, 400, 300};
    const std::vector<LabelAsk> asks = {{{190, 140, 20, 20}, {100, 86}, false}};
    const std::vector<LabelPlace> places = placeLabels(asks, window, {}, {{0, 0, 400, 300}});
    EXPECT_EQ(places[0].at.w, 0);
    EXPECT_FALSE(places[0].offWindow);
    // A disc larger than the window: no side of it is inside.
    const std::vector<LabelAsk> huge = {{{-50, -50, 500, 400}, {100, 86}, false}};
    EXPECT_TRUE(placeLabels(huge, window, {}, {})[0].offWindow);
}

}  // namespace
}  // namespace psb::app
