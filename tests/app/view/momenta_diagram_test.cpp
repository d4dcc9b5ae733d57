// The momenta diagram (momenta_diagram.hpp): tip to tail, the total from the origin, one scale
// for before and after, and its text.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "view/head_on_card.hpp"
#include "view/label_places.hpp"
#include "view/mass_shade.hpp"
#include "view/momenta_diagram.hpp"
#include "view/projector_fixture.hpp"

namespace psb::app {
namespace {

TEST(MomentaDiagram, TheArrowsHaveFixedColoursNoTwoAlike) {
    // The arrows took their balls' colours: in lesson 1 on the light theme the 3 kg ball is
    // drawn black, and so was its arrow, like the total's. Now particle 1 is orange, particle
    // 2 blue and the total the text's colour, on either theme, whatever the balls look like.
    for (const Theme theme : {Theme::Light, Theme::Dark}) {
        const std::array<Color, 3> c = momentaColours(theme);
        EXPECT_FALSE(c[0] == c[1]);
        EXPECT_FALSE(c[0] == c[2]);
        EXPECT_FALSE(c[1] == c[2]);
        const Rgba text = palette(theme).text;
        EXPECT_EQ(c[2], (Color{text.r, text.g, text.b})) << "the total in the text's colour";
        const Rgba background = palette(theme).controls;
        for (int k = 0; k < 2; ++k) {
            // Each particle's arrow stands out from the panel it is drawn on.
            EXPECT_GE(contrastRatio(Rgba{c[k].r, c[k].g, c[k].b}, background), 2.0) << k;
            // Orange (red the most) for 1, blue (blue the most) for 2.
        }
        EXPECT_GT(c[0].r, c[0].b);
        EXPECT_GT(c[1].b, c[1].r);
    }
    EXPECT_EQ(momentaColours(Theme::Dark)[0], (Color{230, 159, 0})) << "Okabe-Ito orange";
    EXPECT_EQ(momentaColours(Theme::Dark)[1], (Color{86, 180, 233})) << "Okabe-Ito sky blue";
}

TEST(MomentaDiagram, ThePairsArrowsGoTipToTailAndTheTotalIsKept) {
    const MomentaDiagram d = momentaDiagram(headOnCard());
    ASSERT_EQ(d.before.size(), 3u);
    ASSERT_EQ(d.after.size(), 3u);
    // Before: 1's (2, 0) from the origin, 2's (-3, 0) from its tip, the total (-1, 0).
    EXPECT_EQ(d.before[0].from, Vec2(0, 0));
    EXPECT_EQ(d.before[0].to, Vec2(2, 0));
    EXPECT_EQ(d.before[0].label, "p 1");
    EXPECT_EQ(d.before[1].from, Vec2(2, 0));
    EXPECT_EQ(d.before[1].to, Vec2(-1, 0));
    EXPECT_EQ(d.before[1].label, "p 2");
    EXPECT_EQ(d.before[2].kind, MomentaDiagram::Kind::Total);
    EXPECT_EQ(d.before[2].from, Vec2(0, 0));
    EXPECT_EQ(d.before[2].to, Vec2(-1, 0));
    // After: 1's (-2.5, 0), 2's (1.5, 0) from there, the same total.
    EXPECT_EQ(d.after[1].from, Vec2(-2.5, 0));
    EXPECT_EQ(d.after[2].to, d.before[2].to);
    // One scale for both: the farthest point of either half is 2.5 kg m/s, so the square
    // reaches the next round number with room for a head, 3 kg m/s.
    EXPECT_DOUBLE_EQ(d.reach, 3.0);
}

TEST(MomentaDiagram, PixelsKeepTheBoxsDirectionsAndStayInTheSquare) {
    const MomentaDiagram d = momentaDiagram(headOnCard());
    const double side = 200.0;
    EXPECT_EQ(d.toPixels(Vec2(0, 0), side), Vec2(100, 100));
    const Vec2 right = d.toPixels(Vec2(2.5, 0), side), down = d.toPixels(Vec2(0, 2.5), side);
    EXPECT_GT(right.x(), 150.0);
    EXPECT_LT(right.x(), side);
    EXPECT_GT(down.y(), 150.0);  // y down, as in the box
    EXPECT_LT(down.y(), side);
    EXPECT_GT(d.toPixels(Vec2(-2.5, -2.5), side).minCoeff(), 0.0);
}

/// The number the caption states the square reaches, kg m/s (its digits grouped by thousands
/// with spaces, as units.hpp writes them: "1 500").
double captionReach(const MomentaDiagram& d) {
    const std::string caption = momentaDiagramScale(d);
    const std::string lead = "The square reaches ", unit = " kg m/s from its centre";
    EXPECT_EQ(caption.rfind(lead, 0), 0u) << caption;
    const std::size_t end = caption.find(unit);
    EXPECT_NE(end, std::string::npos) << caption;
    std::string number = caption.substr(lead.size(), end - lead.size());
    std::erase(number, ' ');
    std::size_t used = 0;
    const double value = std::stod(number, &used);
    EXPECT_EQ(used, number.size()) << caption;
    return value;
}

TEST(MomentaDiagram, AnArrowOfTheCaptionsValueSpansHalfTheSquare) {
    const MomentaDiagram d = momentaDiagram(headOnCard());
    const double stated = captionReach(d);
    EXPECT_EQ(stated, 3.0);
    for (const double side : {120.0, 200.0, 333.0}) {
        const Vec2 centre = d.toPixels(Vec2(0, 0), side);
        // An arrow of the stated momentum, any way it points, reaches the square's edge.
        for (const Vec2& u : {Vec2(1, 0), Vec2(0, -1), Vec2(0.6, 0.8)}) {
            EXPECT_NEAR((d.toPixels(Vec2(stated * u), side) - centre).norm(), 0.5 * side, 1e-9)
                << side;
        }
        // The card's 2.5 kg m/s (p 1 after) is 2.5 / 3 of the half-width, not more or less.
        const MomentaDiagram::Arrow& p1 = d.after[0];
        EXPECT_NEAR((d.toPixels(p1, side) - d.fromPixels(p1, side)).norm(),
                    2.5 / stated * 0.5 * side, 1e-9);
    }
}

TEST(MomentaDiagram, TheScaleIsRoundAndEveryTipKeepsItsMargin) {
    CollisionCard card = headOnCard();
    for (const double speed : {2.0, 0.0173, 7.0, 1234.0, 9.0e-5}) {
        card.collision.aBefore = Vec2(speed, 0.0);
        const MomentaDiagram d = momentaDiagram(card);
        EXPECT_EQ(captionReach(d), d.reach) << "the caption states the scale drawn";
        const double side = 200.0;
        for (const auto* half : {&d.before, &d.after}) {
            for (const MomentaDiagram::Arrow& a : *half) {
                const Vec2 tip = d.toPixels(a.to, side) - d.toPixels(Vec2(0, 0), side);
                EXPECT_LE(tip.cwiseAbs().maxCoeff(), (0.5 - MomentaDiagram::kMargin) * side + 1e-9)
                    << speed;
            }
        }
        // At most one round step above the farthest tip: the arrows fill the square.
        double farthest = 0.0;
        for (const MomentaDiagram::Arrow& a : d.before)
            farthest = std::max(farthest, a.to.cwiseAbs().maxCoeff());
        for (const MomentaDiagram::Arrow& a : d.after)
            farthest = std::max(farthest, a.to.cwiseAbs().maxCoeff());
        EXPECT_LE(d.reach, 1.5 * farthest / (1.0 - 2.0 * MomentaDiagram::kMargin)) << speed;
    }
}

TEST(MomentaDiagram, AHeadOnCollisionsArrowsGetARowEachAnOblique2DOneNone) {
    const MomentaDiagram d = momentaDiagram(headOnCard());
    // Three rows across x, in order down the square, the first above the axis, the same after.
    EXPECT_LT(d.before[0].offset.y(), 0.0);
    EXPECT_LT(d.before[0].offset.y(), d.before[1].offset.y());
    EXPECT_LT(d.before[1].offset.y(), d.before[2].offset.y());
    EXPECT_EQ(d.after[2].offset, d.before[2].offset);
    // Tip to tail along x: the second starts straight below the first's tip.
    EXPECT_EQ(d.fromPixels(d.before[1], 200.0).x(), d.toPixels(d.before[0], 200.0).x());
    // Along y (a vertical collision): the rows are across y.
    CollisionCard vertical = headOnCard();
    Collision& c = vertical.collision;
    for (Vec2* v : {&c.aBefore, &c.bBefore, &c.aAfter, &c.bAfter})
        *v = Vec2(0.0, v->x());
    const MomentaDiagram dv = momentaDiagram(vertical);
    EXPECT_LT(dv.before[0].offset.x(), 0.0);
    EXPECT_EQ(dv.before[0].offset.y(), 0.0);
    // Oblique: the tip-to-tail triangle shows by itself.
    c.aBefore = Vec2(1.0, 1.0);
    for (const MomentaDiagram::Arrow& a : momentaDiagram(vertical).before)
        EXPECT_EQ(a.offset, Vec2(0, 0));
}

TEST(MomentaDiagram, NoArrowOfAHeadOnCollisionLiesOnTheAxis) {
    // Lesson 1's card at 200 %: "p 2" before, in the middle of three rows, lay on the square's
    // horizontal axis, its line drawn over it and lost in it. Every row keeps a tenth of a
    // head-on diagram's row spacing (0.16 of the side) clear of the axis, for the pair (three
    // rows) and for a wall (two), along x and along y.
    for (const bool wall : {false, true}) {
        for (const bool vertical : {false, true}) {
            CollisionCard card = headOnCard();
            Collision& c = card.collision;
            if (wall) {
                c.with = Collision::With::Wall;
                card.massB = 0.0;
                card.numberB = 0;
                c.bBefore = c.bAfter = Vec2::Zero();
                c.aAfter = -c.aBefore;
            }
            if (vertical) {
                for (Vec2* v : {&c.aBefore, &c.bBefore, &c.aAfter, &c.bAfter})
                    *v = Vec2(0.0, v->x());
            }
            const MomentaDiagram d = momentaDiagram(card);
            for (const auto* half : {&d.before, &d.after}) {
                for (const MomentaDiagram::Arrow& a : *half) {
                    const double across = vertical ? a.offset.x() : a.offset.y();
                    EXPECT_GE(std::abs(across), 0.016)
                        << a.label << (wall ? ", wall" : ", pair")
                        << (vertical ? ", along y" : ", along x") << ": on the axis";
                }
            }
        }
    }
}

TEST(MomentaDiagram, AWallChangesTheOneParticlesMomentum) {
    CollisionCard card = headOnCard();
    card.collision.with = Collision::With::Wall;
    card.massB = 0.0;
    card.numberB = 0;
    card.collision.bBefore = card.collision.bAfter = Vec2::Zero();
    card.collision.aAfter = Vec2(-2.0, 0.0);
    const MomentaDiagram d = momentaDiagram(card);
    ASSERT_EQ(d.before.size(), 2u);
    EXPECT_EQ(d.before[1].to, Vec2(2, 0));
    EXPECT_EQ(d.after[1].to, Vec2(-2, 0));
}

TEST(MomentaDiagram, ParticlesAtRestStillGetAScaleAndNoNaN) {
    CollisionCard card = headOnCard();
    Collision& c = card.collision;
    c.aBefore = c.bBefore = c.aAfter = c.bAfter = Vec2::Zero();
    EXPECT_GT(momentaDiagram(card).reach, 0.0);
    c.aAfter = Vec2(std::numeric_limits<double>::infinity(), 0.0);
    const MomentaDiagram d = momentaDiagram(card);
    EXPECT_TRUE(std::isfinite(d.reach));
}

TEST(MomentaDiagram, ItsTextAddsTheMomentaUpToTheTotal) {
    const auto lines = momentaDiagramLines(momentaDiagram(headOnCard()));
    ASSERT_EQ(lines.size(), 2u);
    EXPECT_EQ(lines[0],
              "Momenta before: p 1 (2.00, 0) + p 2 (-3.00, 0) = total p (-1.00, 0) kg m/s");
    EXPECT_EQ(lines[1],
              "Momenta after: p 1 (-2.50, 0) + p 2 (1.50, 0) = total p (-1.00, 0) kg m/s");
}

/// A gas's collision as the card showed it at 200 %: particles 1653 and 2837 of 1 kg, their
/// momenta small and alike, so the arrows crowd one corner of the square.
CollisionCard gasCard() {
    CollisionCard card;
    Collision& c = card.collision;
    c.with = Collision::With::Particle;
    card.massA = card.massB = 1.0;
    card.numberA = 1653;
    card.numberB = 2837;
    c.aBefore = Vec2(-0.236, 0.306);  // the box's y down: the numbers read y up
    c.bBefore = Vec2(-0.182, 0.0929);
    c.aAfter = Vec2(-0.110, 0.151);
    c.bAfter = Vec2(-0.308, 0.248);
    return card;
}

TEST(MomentaDiagram, ItsLabelsStayInTheSquareClearOfEachOtherTheArrowsAndTheAxes) {
    // "p 1653" lay over "total p", "p 2837" was cut at the square's edge and the axis ran
    // through "total p": each label was centred above its arrow's middle, wherever that was.
    // Labels of DejaVu Sans at 200 % (30 pixels high, 13 a character), in the squares the
    // panel gives at 100 % and 200 %.
    for (const CollisionCard& card : {gasCard(), headOnCard(), headOnCard(0.5)}) {
        const MomentaDiagram d = momentaDiagram(card);
        for (const double side : {120.0, 200.0, 270.0}) {
            for (const auto* half : {&d.before, &d.after}) {
                std::vector<Vec2> sizes;
                for (const MomentaDiagram::Arrow& a : *half)
                    sizes.emplace_back(13.0 * static_cast<double>(a.label.size()) * side / 270.0,
                                       30.0 * side / 270.0);
                const double arrow = 0.25 * 30.0 * side / 270.0 + 1.0;
                const std::vector<Vec2> at = momentaLabelPlaces(d, *half, side, sizes, arrow);
                ASSERT_EQ(at.size(), half->size());
                std::vector<ScreenWall> lines = {{0.0, side / 2, side, side / 2, 0.5},
                                                 {side / 2, 0.0, side / 2, side, 0.5}};
                for (const MomentaDiagram::Arrow& a : *half) {
                    const Vec2 from = d.fromPixels(a, side), to = d.toPixels(a, side);
                    lines.push_back({from.x(), from.y(), to.x(), to.y(), arrow - 1.0});
                }
                for (std::size_t k = 0; k < at.size(); ++k) {
                    const std::string what = (*half)[k].label + " of " +
                                             std::to_string(card.numberA) + " in a square of " +
                                             std::to_string(side);
                    const double x0 = at[k].x(), y0 = at[k].y();
                    const double x1 = x0 + sizes[k].x(), y1 = y0 + sizes[k].y();
                    EXPECT_GE(x0, 0.0) << what;
                    EXPECT_GE(y0, 0.0) << what;
                    EXPECT_LE(x1, side) << what << ": cut at the square's edge";
                    EXPECT_LE(y1, side) << what;
                    const PixelRect r{
                        static_cast<int>(std::ceil(x0)), static_cast<int>(std::ceil(y0)),
                        static_cast<int>(x1 - std::ceil(x0)), static_cast<int>(y1 - std::ceil(y0))};
                    for (const ScreenWall& l : lines)
                        EXPECT_FALSE(crosses(r, l)) << what << ": over a line";
                    for (std::size_t j = k + 1; j < at.size(); ++j) {
                        const bool apart = x1 <= at[j].x() || at[j].x() + sizes[j].x() <= x0 ||
                                           y1 <= at[j].y() || at[j].y() + sizes[j].y() <= y0;
                        EXPECT_TRUE(apart) << what << " over " << (*half)[j].label;
                    }
                }
            }
        }
    }
}

}  // namespace
}  // namespace psb::app
