// Nothing of the app's own covers a reading (frame_view.hpp): on the projector (200 % in a
// 1600 x 1000 window) the recording mark and the panels stand clear of the HUD as the screen
// shows it, and the particles' labels of the grid's distances and a dropper's words.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

#include <particle_sandbox/scene.hpp>

#include "session/session.hpp"
#include "session/test_assets.hpp"
#include "view/bin_numbers.hpp"
#include "view/fixed_measure.hpp"
#include "view/frame_view.hpp"
#include "view/lab_marks.hpp"
#include "view/label_places.hpp"
#include "view/overlays.hpp"
#include "view/particle_labels.hpp"
#include "view/projector_fixture.hpp"

namespace psb::app {
namespace {

using test::inWindow;
using test::kDesk;
using test::kProjector;
using test::lessonWorld;
using test::onTheProjector;

std::string text(const PixelRect& r) {
    return std::to_string(r.x) + "," + std::to_string(r.y) + " " + std::to_string(r.w) + "x" +
           std::to_string(r.h);
}

TEST(RecordingMark, OnTheProjectorNeitherItNorAPanelIsUnderTheScreensHud) {
    // Lesson 1 recorded at 200 %: the screen's HUD, drawn over the frame once the video has
    // taken it, has lines the video's has not (its hints, the note that the charts are folded,
    // the line of a step into the past), and the layout kept room for the video's only: the
    // HUD's last line ran under "REC 0:02 MP4" and over the momentum legend.
    for (const bool controls : {true, false}) {
        Session s = onTheProjector(lessonWorld(), {ShowOption::Momentum, ShowOption::Plots,
                                                   ShowOption::Labels, ShowOption::Collision});
        if (!controls) s.apply(cmd::ToggleControls{});
        const test::FixedMeasure font(2.0);
        FrameStats stats;
        stats.video.recording = true;
        stats.video.seconds = 2.0;
        s.apply(cmd::TogglePause{});
        for (int k = 1; k <= 30; ++k)
            s.update(1.0 / 60.0, k / 60.0);
        s.apply(cmd::TogglePause{});
        for (const bool past : {false, true}) {
            if (past) s.apply(cmd::StepBack{});
            const FrameView f = buildFrame(s, stats, font, font, kProjector);
            ASSERT_TRUE(f.recordingMark.has_value());
            const PixelPoint size = textBoxSize(font, f.overlays.hud);
            const PixelRect hud{f.layout.hud.x, f.layout.hud.y, size.x, size.y};
            const std::string at = std::string(controls ? "panel open" : "panel folded") +
                                   (past ? ", in the past" : "") + ", HUD " + text(hud);
            EXPECT_FALSE(overlaps(f.recordingMark->at, hud))
                << at << ", mark " << text(f.recordingMark->at);
            for (const PixelRect& r : panelRects(f.layout)) {
                if (r == f.layout.hud) continue;
                EXPECT_FALSE(overlaps(r, hud)) << at << ", a panel at " << text(r);
            }
        }
    }
}

/// The labels of `s`'s particles as the drawing layer asks for them (render/renderer.cpp,
/// without the arrows), in `font`.
std::vector<LabelAsk> labelAsksOf(const Session& s, const TextMeasure& font) {
    const Camera& camera = s.camera();
    const ParticleArrays& p = s.world().particles();
    const Axes axes = s.axes();
    std::vector<LabelAsk> asks;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const Vec2 c = camera.worldToScreen(Vec2(p.x[i], p.y[i]));
        const int r = static_cast<int>(std::ceil(camera.toScreen(p.radius[i]))) + kLabelGap;
        const int cx = static_cast<int>(std::lround(c.x())),
                  cy = static_cast<int>(std::lround(c.y()));
        const ParticleLabelText text =
            particleLabelText(particleNumber(p.id[i]), p.mass[i], p.vx[i], axes.up(p.vy[i]));
        asks.push_back(particleLabelAsk(text, {cx - r, cy - r, 2 * r, 2 * r}, font, true));
    }
    return asks;
}

/// The labels of `s`'s particles placed as the drawing layer places them
/// (render/renderer.cpp), in the 200 % labels' sizes.
std::vector<LabelPlace> labelsOf(const Session& s, const FrameView& f,
                                 const test::FixedMeasure& font) {
    const LabelKeepOut keep = labelKeepOut(f, font);
    const Camera& camera = s.camera();
    LabelRoom room = labelRoom(s.world(), camera, {0, 0, 1600, 1000}, keep.rects);
    room.walls.insert(room.walls.end(), keep.walls.begin(), keep.walls.end());
    return placeLabels(labelAsksOf(s, font), room);
}

TEST(LabelPlaces, NoParticleLabelCoversTheGridsDistances) {
    // The grid (Shift+G) and labels (S) at 200 %: a ball half-way down the box had its label
    // drawn above it, over the grid's distances along the box's top edge.
    WorldDef def;
    def.width = 10.0;
    def.height = 4.0;
    World w(def);
    w.add({.position = Vec2(3.0, 2.2), .mass = 1.0, .radius = 0.2});
    w.add({.position = Vec2(8.0, 2.2), .mass = 3.0, .radius = 0.2});
    const Session s = onTheProjector(std::move(w), {ShowOption::Grid, ShowOption::Labels});
    const test::FixedMeasure font(2.0);
    const FrameView f = buildFrame(s, FrameStats{}, font, font, kProjector);
    ASSERT_TRUE(f.grid.has_value());
    ASSERT_FALSE(f.grid->labels.empty());
    const std::vector<LabelPlace> places = labelsOf(s, f, font);
    std::size_t placed = 0;
    for (const LabelPlace& place : places) {
        if (place.at.w == 0) continue;
        ++placed;
        for (const MarkLabel& l : f.grid->labels) {
            EXPECT_FALSE(overlaps(place.at, labelRect(l, font)))
                << "a label at " << text(place.at) << " over the grid's \"" << l.text << "\"";
        }
    }
    EXPECT_EQ(placed, places.size()) << "each label found a place clear of the grid's";
}

TEST(GridLabels, EachStandsWholeOnAPlateInsideTheWindowThatNoParticleLabelCovers) {
    // A crowded box with the grid (Shift+G) at 200 %: the grid's numbers stood bare on the
    // particles. Each has a plate now (the labels' box colour, drawn by the drawing layer): its
    // text within it, all of it inside the window and off the panels, and the particles'
    // labels keep off it.
    WorldDef def;
    def.width = 10.0;
    def.height = 4.0;
    World w(def);
    for (int i = 0; i < 9; ++i)
        for (int j = 0; j < 3; ++j)
            w.add({.position = Vec2(0.6 + 1.1 * i, 0.5 + 1.4 * j), .mass = 1.0, .radius = 0.3});
    const Session s = onTheProjector(std::move(w), {ShowOption::Grid, ShowOption::Labels});
    const test::FixedMeasure font(2.0);
    const FrameView f = buildFrame(s, FrameStats{}, font, font, kProjector);
    ASSERT_TRUE(f.grid.has_value());
    ASSERT_FALSE(f.grid->labels.empty());
    const std::vector<PixelRect> plates = gridLabelPlates(*f.grid, font);
    ASSERT_EQ(plates.size(), f.grid->labels.size());
    const LabelKeepOut keepOut = labelKeepOut(f, font);
    for (std::size_t k = 0; k < plates.size(); ++k) {
        const PixelRect text = labelRect(f.grid->labels[k], font);
        const PixelRect& p = plates[k];
        EXPECT_LE(p.x + kGridLabelPad, text.x);
        EXPECT_GE(p.x + p.w - kGridLabelPad, text.x + text.w);
        EXPECT_LT(p.y, text.y);
        EXPECT_GT(p.y + p.h, text.y + text.h);
        EXPECT_GE(p.x, f.controlsInset);
        EXPECT_LE(p.x + p.w, 1600);
        EXPECT_GE(p.y, 0);
        EXPECT_LE(p.y + p.h, 1000);
        for (const PixelRect& panel : panelRects(f.layout))
            EXPECT_FALSE(overlaps(p, panel)) << "\"" << f.grid->labels[k].text << "\"'s plate";
        EXPECT_NE(std::find(keepOut.rects.begin(), keepOut.rects.end(), p), keepOut.rects.end())
            << "the particles' labels keep off \"" << f.grid->labels[k].text << "\"'s plate";
    }
    for (const LabelPlace& place : labelsOf(s, f, font)) {
        if (place.at.w == 0) continue;
        for (const PixelRect& p : plates)
            EXPECT_FALSE(overlaps(place.at, p)) << "a label at " << text(place.at);
    }
}

TEST(LabelPlaces, NoParticleLabelCoversADroppersWords) {
    // A dropper's "dropper: 5 balls left" under the label of the ball just dropped.
    WorldDef def;
    def.width = 10.0;
    def.height = 4.0;
    def.gravity = Vec2(0.0, 9.81);
    World w(def);
    Dropper d;
    d.position = Vec2(3.0, 1.0);
    d.balls = 5;
    d.radius = 0.2;
    d.mass = 1.0;
    w.setDroppers({d});
    w.add({.position = Vec2(3.0, 1.5), .mass = 1.0, .radius = 0.2});
    w.add({.position = Vec2(5.0, 1.6), .mass = 1.0, .radius = 0.2});
    const Session s = onTheProjector(std::move(w), {ShowOption::Labels, ShowOption::Grid});
    const test::FixedMeasure font(2.0);
    const FrameView f = buildFrame(s, FrameStats{}, font, font, kProjector);
    ASSERT_EQ(f.droppers.size(), 1u);
    const PixelRect words = f.droppers[0].words.at;
    ASSERT_GT(words.w, 0);
    // Nor does a grid's label (they straddled each other along the box's top).
    ASSERT_TRUE(f.grid.has_value());
    for (const MarkLabel& l : f.grid->labels) {
        EXPECT_FALSE(overlaps(labelRect(l, font), words))
            << "the grid's \"" << l.text << "\" over the dropper's words";
    }
    for (const LabelPlace& place : labelsOf(s, f, font)) {
        ASSERT_GT(place.at.w, 0);
        EXPECT_FALSE(overlaps(place.at, words))
            << "a label at " << text(place.at) << " over the dropper's words at " << text(words);
    }
}

TEST(DropperWords, AreReadWholeInsideTheBoxClearOfThePanelsFrom100To200Percent) {
    // The Galton board at 200 % with its plots and the values table: "dropper: 1000 balls
    // left" ran out of the narrow box and under the bins' chart. Beside the spout where a side
    // has room, wrapped where one line does not fit, never over the pegs.
    struct Window {
        int width, height;
        ControlsWidth controls;
    };
    for (const Window& win : {Window{1600, 1000, kProjector}, Window{800, 600, kDesk},
                              Window{1920, 1080, kProjector}, Window{1200, 800, kDesk}}) {
        for (const bool panel : {true, false}) {
            for (const bool more : {true, false}) {
                Session s = more ? inWindow(lessonWorld(),
                                            {ShowOption::Plots, ShowOption::Values,
                                             ShowOption::Grid, ShowOption::Speeds},
                                            win.width, win.height, win.controls)
                                 : inWindow(lessonWorld(), {}, win.width, win.height, win.controls);
                s.apply(cmd::OpenFile{testAsset("scenes/09-galton-board.json")});
                if (!panel) s.apply(cmd::ToggleControls{});
                const test::FixedMeasure font(win.controls.pointPixels);
                const FrameView f = buildFrame(s, FrameStats{}, font, font, win.controls);
                ASSERT_EQ(f.droppers.size(), 1u);
                const DropperView::Words& words = f.droppers[0].words;
                const std::string at =
                    std::to_string(win.width) + "x" + std::to_string(win.height) + " at " +
                    std::to_string(win.controls.pointPixels) +
                    (panel ? ", panel open" : ", panel folded") +
                    (more ? ", charts and table" : "") + ": words at " + text(words.at);
                const LabelRoom room =
                    labelRoom(s.world(), s.camera(), {0, 0, win.width, win.height}, {});
                // Inside the box; or, where no side of the spout has room clear of the pegs,
                // above its top wall.
                const bool inBox = words.at.x >= room.box.x && words.at.y >= room.box.y &&
                                   words.at.x + words.at.w <= room.box.x + room.box.w &&
                                   words.at.y + words.at.h <= room.box.y + room.box.h;
                const bool above = words.at.y + words.at.h <= room.box.y - room.boxWall &&
                                   words.at.y >= 0 && words.at.x >= f.controlsInset &&
                                   words.at.x + words.at.w <= win.width;
                EXPECT_TRUE(inBox || above) << at << ", box " << text(room.box);
                for (const PixelRect& r : panelRects(f.layout))
                    EXPECT_FALSE(overlaps(words.at, r)) << at << ", a panel at " << text(r);
                for (const PixelRect& r : pegsOnScreen(s.world(), s.camera()))
                    EXPECT_FALSE(overlaps(words.at, r)) << at << ", a peg at " << text(r);
                std::string said;
                int widest = 0;
                for (const std::string& line : words.lines) {
                    said += (said.empty() ? "" : " ") + line;
                    widest = std::max(widest, font.measure(line));
                }
                EXPECT_EQ(said, f.droppers[0].label) << at;
                EXPECT_LE(widest, words.at.w) << at;
                EXPECT_GE(words.at.h, static_cast<int>(words.lines.size()) * font.lineHeight())
                    << at;
            }
        }
    }
}

TEST(GridLabels, KeepOffTheBinsNumbersOnTheBoard) {
    // The Galton board with the grid (Shift+G) at 200 %: the grid's "0.4 m" along the box's
    // left edge touched the bins' "0" just under their top line. Each keeps two pixels of air.
    struct Window {
        int width, height;
        ControlsWidth controls;
    };
    int numbered = 0;
    for (const Window& win : {Window{1600, 1000, kProjector}, Window{800, 600, kDesk},
                              Window{1920, 1080, kProjector}, Window{1200, 800, kDesk}}) {
        for (const bool panel : {true, false}) {
            for (const bool plots : {true, false}) {
                Session s = plots ? inWindow(lessonWorld(), {ShowOption::Grid, ShowOption::Plots},
                                             win.width, win.height, win.controls)
                                  : inWindow(lessonWorld(), {ShowOption::Grid}, win.width,
                                             win.height, win.controls);
                s.apply(cmd::OpenFile{testAsset("scenes/09-galton-board.json")});
                if (!panel) s.apply(cmd::ToggleControls{});
                const test::FixedMeasure font(win.controls.pointPixels);
                const FrameView f = buildFrame(s, FrameStats{}, font, font, win.controls);
                ASSERT_TRUE(f.grid.has_value());
                ASSERT_TRUE(f.bins.has_value());
                const std::vector<BinNumber> numbers =
                    binNumbers(s.camera(), f.bins->bins, s.world().def().height, font);
                numbered += !numbers.empty();  // narrow bins have none
                for (const MarkLabel& l : f.grid->labels) {
                    const PixelRect r = labelRect(l, font);
                    const PixelRect air{r.x - 2, r.y - 2, r.w + 4, r.h + 4};
                    for (const BinNumber& n : numbers) {
                        EXPECT_FALSE(overlaps(air, n.at))
                            << win.width << "x" << win.height << (panel ? "" : ", panel folded")
                            << (plots ? ", plots" : "") << ": the grid's \"" << l.text << "\" at "
                            << text(r) << " by bin " << n.text << " at " << text(n.at);
                    }
                }
            }
        }
    }
    EXPECT_GT(numbered, 4);
}

TEST(MomentumLegend, KeepsOffTheBoxWhenTheHudGrows) {
    // Lesson 1 with the momentum (V) at 200 %: the HUD's notes (labels left out, the charts
    // folded) grew its lines across the legend's column, and the legend, placed below them,
    // dropped onto the box's top-right corner, on the screen and in the video.
    struct Window {
        int width, height;
        ControlsWidth controls;
    };
    for (const Window& win : {Window{1600, 1000, kProjector}, Window{800, 600, kDesk},
                              Window{1920, 1080, kProjector}, Window{1024, 768, kDesk}}) {
        for (const bool panel : {true, false}) {
            for (const bool recording : {false, true}) {
                Session s = inWindow(lessonWorld(), {ShowOption::Momentum, ShowOption::Labels},
                                     win.width, win.height, win.controls);
                if (!panel) s.apply(cmd::ToggleControls{});
                const test::FixedMeasure font(win.controls.pointPixels);
                FrameStats stats;
                stats.labelsCrowded = 2;
                stats.labelsOffWindow = 1;
                stats.video.recording = recording;
                const FrameView f = buildFrame(s, stats, font, font, win.controls);
                const Camera::ScreenBox b = s.camera().boxOnScreen(10.0, 4.0);
                const PixelRect box{static_cast<int>(std::floor(b.topLeft.x())),
                                    static_cast<int>(std::floor(b.topLeft.y())),
                                    static_cast<int>(std::ceil(b.size.x())),
                                    static_cast<int>(std::ceil(b.size.y()))};
                const std::string at =
                    std::to_string(win.width) + "x" + std::to_string(win.height) +
                    (panel ? "" : ", panel folded") + (recording ? ", recording" : "") +
                    ": legend at " + text(f.layout.legend) + ", box " + text(box);
                ASSERT_GT(f.layout.legend.w, 0) << at;
                EXPECT_FALSE(overlaps(f.layout.legend, box)) << at;
                for (const PixelRect& r : panelRects(f.layout)) {
                    if (r == f.layout.legend) continue;
                    EXPECT_FALSE(overlaps(f.layout.legend, r)) << at << ", a panel at " << text(r);
                }
            }
        }
    }
}

TEST(LabelPlaces, InTheOriginalsSixBallsEveryLabelIsTiedToItsOwnBallInOneForm) {
    // The original's six balls (preset 1) at 200 % with labels (S): labels slid along their
    // ball's side stood nearer a neighbour (particle 3's between balls 1 and 3 read as 1's),
    // and some had five lines while others had one. Each label is nearest its own ball or
    // joined to it by a line, never over a ball, all in one form of at most two lines, and,
    // paused or as they move, none is left out.
    for (const bool panel : {true, false}) {
        Session s = onTheProjector(makeWorld(loadScene(std::filesystem::path(PSB_ASSETS_DIR) /
                                                       "scenes" / "01-original.json")),
                                   {ShowOption::Labels});
        if (!panel) s.apply(cmd::ToggleControls{});
        const test::FixedMeasure font(2.0);
        for (int k = 0; k <= 120; k += 10) {
            if (k > 0) {
                s.apply(cmd::TogglePause{});
                for (int j = 1; j <= 10; ++j)
                    s.update(1.0 / 60.0, (k - 10 + j) / 60.0);
                s.apply(cmd::TogglePause{});
            }
            const FrameView f = buildFrame(s, FrameStats{}, font, font, kProjector);
            const std::vector<LabelAsk> asks = labelAsksOf(s, font);
            const std::vector<LabelPlace> places = labelsOf(s, f, font);
            ASSERT_EQ(places.size(), 6u);
            const std::string at = std::string(panel ? "panel open" : "panel folded") +
                                   ", t = " + std::to_string(s.world().time());
            for (std::size_t i = 0; i < places.size(); ++i) {
                const PixelRect& r = places[i].at;
                ASSERT_GT(r.w, 0) << at << ": label " << i + 1 << " left out";
                EXPECT_EQ(places[i].nameOnly, places[0].nameOnly) << at << ": two forms";
                EXPECT_LE(r.h, 2 * font.lineHeight() + 1) << at << ": more than two lines";
                for (std::size_t j = 0; j < asks.size(); ++j)
                    EXPECT_FALSE(overlaps(r, asks[j].disc)) << at << ": label over a ball";
                const double px = r.x + 0.5 * r.w, py = r.y + 0.5 * r.h;
                const auto rim = [&](const PixelRect& d) {
                    return std::hypot(d.x + 0.5 * d.w - px, d.y + 0.5 * d.h - py) - 0.5 * d.w;
                };
                for (std::size_t j = 0; j < asks.size(); ++j) {
                    if (j == i) continue;
                    if (!places[i].leader) {
                        EXPECT_GT(rim(asks[j].disc), rim(asks[i].disc))
                            << at << ": label " << i + 1 << " at " << text(r) << " nearer ball "
                            << j + 1 << " than its own, with no line to it";
                        continue;
                    }
                    // Joined by a line, away from its ball: clear of the others by half its
                    // height (one touching another ball read as that one's).
                    const PixelRect& d = asks[j].disc;
                    const double half = 0.5 * d.w, cx = d.x + half, cy = d.y + half;
                    const double ex = std::max({r.x - cx, 0.0, cx - (r.x + r.w)});
                    const double ey = std::max({r.y - cy, 0.0, cy - (r.y + r.h)});
                    EXPECT_GE(std::hypot(ex, ey) - half, r.h / 2)
                        << at << ": label " << i + 1 << " at " << text(r) << " touches ball "
                        << j + 1;
                }
            }
        }
    }
}

TEST(LabelPlaces, AtTheImpactBothLabelsKeepTheirValues) {
    // Lesson 1 at the moment of impact on the projector, with what the lesson shows: the two
    // balls touch, and their labels shrank to "particle 1" and "particle 2".
    for (const bool panel : {true, false}) {
        for (const bool table : {false, true}) {
            World w = lessonWorld();
            Session s =
                table ? onTheProjector(std::move(w), {ShowOption::Labels, ShowOption::Momentum,
                                                      ShowOption::Plots, ShowOption::Grid,
                                                      ShowOption::Values, ShowOption::Collision})
                      : onTheProjector(std::move(w), {ShowOption::Labels, ShowOption::Momentum,
                                                      ShowOption::Plots, ShowOption::Grid});
            if (!panel) s.apply(cmd::ToggleControls{});
            s.apply(cmd::TogglePause{});
            // They touch at t = 4.4 m / 3 m/s = 1.467 s.
            for (int k = 1; k <= 88; ++k)
                s.update(1.0 / 60.0, k / 60.0);
            s.apply(cmd::TogglePause{});
            const test::FixedMeasure font(2.0);
            const FrameView f = buildFrame(s, FrameStats{}, font, font, kProjector);
            const std::vector<LabelPlace> places = labelsOf(s, f, font);
            ASSERT_EQ(places.size(), 2u);
            for (const LabelPlace& p : places) {
                EXPECT_GT(p.at.w, 0);
                EXPECT_FALSE(p.nameOnly) << (panel ? "panel open" : "panel folded")
                                         << (table ? ", table" : "") << ": at " << text(p.at);
            }
        }
    }
}

}  // namespace
}  // namespace psb::app
