// A periodic box as the frame lists it (view/periodic_box.hpp): the discs over an edge again at
// the opposite edge (over a corner at the three others), the edges as dashes from each corner,
// and nothing of it for a box with walls.

#include "view/periodic_box.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <particle_sandbox/presets.hpp>
#include <particle_sandbox/scene.hpp>

#include "session/session.hpp"
#include "view/fixed_measure.hpp"
#include "view/frame_view.hpp"

namespace psb::app {
namespace {

/// A periodic 10 m × 8 m box with a disc of radius 0.5 m in the middle, one over the left edge,
/// one over the bottom edge and one over the top-right corner.
World periodicWorld() {
    WorldDef def;
    def.width = 10.0;
    def.height = 8.0;
    def.walls = false;
    def.periodic = true;
    World w(def);
    w.add({.position = Vec2(5.0, 4.0), .velocity = Vec2(1.0, 0.0), .radius = 0.5});
    w.add({.position = Vec2(0.2, 4.0), .velocity = Vec2(-1.0, 0.0), .radius = 0.5});
    w.add({.position = Vec2(5.0, 7.8), .velocity = Vec2(0.0, 1.0), .radius = 0.5});
    w.add({.position = Vec2(9.7, 0.3), .velocity = Vec2(1.0, -1.0), .radius = 0.5});
    return w;
}

bool hasImage(const std::vector<PeriodicImage>& images, std::size_t index, Vec2 offset) {
    return std::any_of(images.begin(), images.end(), [&](const PeriodicImage& m) {
        return m.index == index && (m.offset - offset).norm() < 1e-12;
    });
}

TEST(PeriodicBox, ADiscOverAnEdgeIsDrawnAgainAtTheOppositeEdgeAndOverACornerAtAllThree) {
    const World w = periodicWorld();
    const ParticleArrays& p = w.particles();
    ASSERT_EQ(p.size(), 4u);
    const std::vector<PeriodicImage> images = periodicImages(w);
    ASSERT_EQ(images.size(), 5u);  // none for the middle one, 1 + 1 + 3
    // Storage order is the order added here (4 particles: no reordering).
    EXPECT_TRUE(hasImage(images, 1, Vec2(10.0, 0.0)));  // at x = 10.2: over the right edge
    EXPECT_TRUE(hasImage(images, 2, Vec2(0.0, -8.0)));  // at y = -0.2
    EXPECT_TRUE(hasImage(images, 3, Vec2(-10.0, 0.0)));
    EXPECT_TRUE(hasImage(images, 3, Vec2(0.0, 8.0)));
    EXPECT_TRUE(hasImage(images, 3, Vec2(-10.0, 8.0)));
    // Each image's centre is within a radius outside the box: the part over the edge.
    for (const PeriodicImage& m : images) {
        const Vec2 c = Vec2(p.x[m.index], p.y[m.index]) + m.offset;
        EXPECT_TRUE(c.x() > -0.5 && c.x() < 10.5 && c.y() > -0.5 && c.y() < 8.5) << c.transpose();
        EXPECT_FALSE(c.x() >= 0.5 && c.x() <= 9.5 && c.y() >= 0.5 && c.y() <= 7.5);
    }
}

TEST(PeriodicBox, ABoxWithWallsHasNoImagesAndNoDashes) {
    WorldDef def;
    def.width = 10.0;
    def.height = 8.0;
    World w(def);
    w.add({.position = Vec2(0.5, 4.0), .radius = 0.5});
    EXPECT_TRUE(periodicImages(w).empty());
    Camera c;
    c.setViewport(800, 600);
    c.fit(10.0, 8.0);
    EXPECT_FALSE(periodicBoxView(w, c).has_value());
}

TEST(PeriodicBox, TheEdgesAreDashesOfTenPixelsSixApartFromEachCorner) {
    Camera c;
    c.setViewport(800, 600);
    c.fit(10.0, 8.0);
    const Vec2 a = c.worldToScreen(Vec2::Zero()), b = c.worldToScreen(Vec2(10.0, 8.0));
    const std::vector<BoxDash> dashes = boxDashes(c, 10.0, 8.0);
    const double period = PeriodicBoxView::kDashPixels + PeriodicBoxView::kGapPixels;
    const double across = b.x() - a.x(), down = b.y() - a.y();
    const auto count = [&](double length) {
        return static_cast<std::size_t>(std::ceil(length / period));
    };
    EXPECT_EQ(dashes.size(), 2 * count(across) + 2 * count(down));
    double drawn = 0.0;
    for (const BoxDash& d : dashes) {
        const double length = (d.to - d.from).norm();
        EXPECT_GT(length, 0.0);
        EXPECT_LE(length, PeriodicBoxView::kDashPixels + 1e-9);
        drawn += length;
        // On one of the four edges' lines, within the box's extent.
        const bool horizontal = std::abs(d.from.y() - d.to.y()) < 1e-9;
        const bool vertical = std::abs(d.from.x() - d.to.x()) < 1e-9;
        ASSERT_TRUE(horizontal || vertical);
        if (horizontal) {
            EXPECT_TRUE(std::abs(d.from.y() - a.y()) < 1e-9 || std::abs(d.from.y() - b.y()) < 1e-9);
        } else {
            EXPECT_TRUE(std::abs(d.from.x() - a.x()) < 1e-9 || std::abs(d.from.x() - b.x()) < 1e-9);
        }
    }
    // Dashed, not solid: about 10/16 of the perimeter is drawn.
    const double perimeter = 2.0 * (across + down);
    EXPECT_NEAR(drawn / perimeter, PeriodicBoxView::kDashPixels / period, 0.02);
    // Each corner starts a dash.
    for (const Vec2& corner : {a, b, Vec2(a.x(), b.y()), Vec2(b.x(), a.y())}) {
        EXPECT_TRUE(std::any_of(dashes.begin(), dashes.end(), [&](const BoxDash& d) {
            return (d.from - corner).norm() < 1e-9;
        })) << corner.transpose();
    }
}

TEST(PeriodicBox, ZoomedInOnlyTheDashesInTheWindowAreListed) {
    Camera c;
    c.setViewport(800, 600);
    c.fit(10.0, 8.0);
    c.set(1000.0, Vec2(-0.1, 3.0));  // 1000 px/m: the box 10 000 px wide, its left edge shown
    const std::vector<BoxDash> dashes = boxDashes(c, 10.0, 8.0);
    ASSERT_FALSE(dashes.empty());
    EXPECT_LT(dashes.size(), 60u);  // the 600 px of the left edge in the window, not 40 000 px
    for (const BoxDash& d : dashes) {
        EXPECT_NEAR(d.from.x(), c.worldToScreen(Vec2::Zero()).x(), 1e-9);
        EXPECT_GE(std::max(d.from.y(), d.to.y()), 0.0);
        EXPECT_LE(std::min(d.from.y(), d.to.y()), 600.0);
    }
}

TEST(PeriodicBox, TheFrameListsTheImagesAndTheDashesOfAPeriodicScene) {
    SessionOptions o;
    o.paused = true;
    o.viewportWidth = 800;
    o.viewportHeight = 800;
    Session s(periodicWorld(), SceneInfo{.name = "periodic", .dt = 1.0 / 60.0}, o);
    const test::FixedMeasure font;
    const FrameView f = buildFrame(s, FrameStats{}, font, font, {310.0, 44.0});
    ASSERT_TRUE(f.periodic.has_value());
    EXPECT_EQ(f.periodic->images.size(), 5u);
    EXPECT_FALSE(f.periodic->dashes.empty());
    EXPECT_GE(f.periodic->thickness, 2.0);
    // The default scene has walls: none of it.
    Session walled(makeWorld(defaultScene()), SceneInfo{.name = "default", .dt = 1.0 / 60.0}, o);
    EXPECT_FALSE(buildFrame(walled, FrameStats{}, font, font, {310.0, 44.0}).periodic);
}

TEST(PeriodicBox, TheSelectedDiscIsOutlinedAtItsImagesToo) {
    // The disc over the top-right corner is drawn four times; selected, each of its three
    // images is outlined as it is. The disc in the middle has no image to outline.
    SessionOptions o;
    o.paused = true;
    o.viewportWidth = 800;
    o.viewportHeight = 800;
    Session s(periodicWorld(), SceneInfo{.name = "periodic", .dt = 1.0 / 60.0}, o);
    const test::FixedMeasure font;
    s.apply(cmd::Select{s.world().ids()[3]});
    FrameView f = buildFrame(s, FrameStats{}, font, font, {310.0, 44.0});
    ASSERT_TRUE(f.selected.has_value());
    ASSERT_EQ(f.selectedImages.size(), 3u);
    for (const Vec2& offset : {Vec2(-10.0, 0.0), Vec2(0.0, 8.0), Vec2(-10.0, 8.0)}) {
        EXPECT_TRUE(std::any_of(f.selectedImages.begin(), f.selectedImages.end(),
                                [&](const Vec2& m) { return (m - offset).norm() < 1e-12; }))
            << offset.transpose();
    }
    s.apply(cmd::Select{s.world().ids()[0]});
    f = buildFrame(s, FrameStats{}, font, font, {310.0, 44.0});
    ASSERT_TRUE(f.selected.has_value());
    EXPECT_TRUE(f.selectedImages.empty());
}

}  // namespace
}  // namespace psb::app
