// The frame view: the marker pointing to a box off screen; the selected particle's panel with
// its edit prompt beside the messages.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <initializer_list>
#include <string>
#include <utility>

#include <particle_sandbox/presets.hpp>
#include <particle_sandbox/scene.hpp>

#include "session/camera.hpp"
#include "session/session.hpp"
#include "view/box_area.hpp"
#include "view/chart_text.hpp"
#include "view/fixed_measure.hpp"
#include "view/frame_view.hpp"
#include "view/lab_marks.hpp"
#include "view/label_places.hpp"
#include "view/overlays.hpp"
#include "view/particle_labels.hpp"
#include "view/plot_scale.hpp"
#include "view/projector_fixture.hpp"

namespace psb::app {
namespace {

TEST(BoxMarker, ShownOnlyWhenTheBoxIsOffScreenAndPointsToIt) {
    Camera c;
    c.setViewport(800, 600);
    c.fit(7.0, 7.0);
    EXPECT_FALSE(boxMarker(c, 7.0, 7.0).has_value());
    c.panPixels(Vec2(-5000, 0));  // the box far to the left
    const auto m = boxMarker(c, 7.0, 7.0);
    ASSERT_TRUE(m.has_value());
    EXPECT_LT(m->direction.x(), -0.99);
    EXPECT_GE(m->at.x(), 0.0);
    EXPECT_LT(m->at.x(), 50.0);  // at the left edge
    EXPECT_NE(m->label.find("F"), std::string::npos);
    // A touch screen has no F: the panel's button that fits the box.
    EXPECT_EQ(boxMarker(c, 7.0, 7.0, true)->label, "box this way (Show: Fit view)");
}

/// The default scene in a `width` x `height` window, laid out as the app lays it out beside a
/// control panel 310 pixels wide (open or folded as `controls` says), paused.
Session sessionIn(int width, int height, bool controls = true) {
    const test::FixedMeasure font;
    SessionOptions o;
    o.paused = true;
    o.viewportWidth = width;
    o.viewportHeight = height;
    o.controls = controls;
    o.layout = windowLayout(font, width, height, {310.0, 44.0});
    return Session(makeWorld(defaultScene()), SceneInfo{.name = "default", .dt = 1.0 / 60.0}, o);
}

FrameView frameOf(const Session& s, const std::vector<std::string>& messages) {
    const test::FixedMeasure font;
    FrameStats stats;
    stats.messages = messages;
    return buildFrame(s, stats, font, font, {310.0, 44.0});
}

TEST(EditPromptPanel, StaysOnScreenBesideTheMessageOfARefusedEdit) {
    // Enter on a selected particle, a mass of -1, Enter: the refusal is said in the message band
    // and in the prompt. The prompt keeps the keyboard, so it must stay on screen: it used to be
    // left out while the message was shown (the two would overlap), and the keys typed went
    // into fields nobody could see.
    for (const bool controls : {true, false}) {
        Session s = sessionIn(800, 800, controls);
        const ParticleId id = s.world().ids()[2];
        s.apply(cmd::Select{id});
        s.apply(cmd::OpenEdit{});
        s.apply(cmd::EditType{"-1"});
        s.apply(cmd::EditApply{});
        ASSERT_TRUE(s.prompt().active());
        std::vector<std::string> said;
        for (const Notice& n : s.takeNotices())
            if (n.show) said.push_back(n.text);
        ASSERT_FALSE(said.empty());
        const FrameView f = frameOf(s, said);
        EXPECT_GT(f.layout.inspector.w, 0) << "controls " << controls;
        // Beside the folded panel the message fits left of the prompt; beside the open one it
        // gives way (the prompt says the same).
        if (!controls) {
            EXPECT_GT(f.layout.messages.w, 0);
        }
        EXPECT_FALSE(overlaps(f.layout.inspector, f.layout.messages));
        ASSERT_FALSE(f.overlays.inspector.empty());
        EXPECT_NE(f.overlays.inspector.back().find("Refused: mass"), std::string::npos);
    }
}

TEST(EditPromptPanel, AnOpenPromptIsShownEvenWhereTheWholePanelWouldNotFit) {
    // A window too low for the readings and the prompt: the prompt alone, never nothing.
    Session s = sessionIn(400, 300, false);
    s.apply(cmd::Select{s.world().ids()[2]});
    s.apply(cmd::OpenEdit{});
    const FrameView f = frameOf(s, {"Editing particle 3: Tab moves, Enter applies"});
    EXPECT_GT(f.layout.inspector.w, 0);
    const auto& lines = f.overlays.inspector;
    EXPECT_TRUE(std::any_of(lines.begin(), lines.end(), [](const std::string& l) {
        return l.find("mass") != std::string::npos && l.find('>') == 0;
    }));
}

TEST(MessageBand, KeepsWholeMessagesAndDropsOlderOnesWhole) {
    // The band keeps three lines. It kept the last three wrapped lines, so a long message lost
    // its head ("/home/lessons/...mp4: 3.8 s, ..." without "Saved video") and an older one its
    // first line. Older messages now go whole; a message longer than the band takes the lines
    // it needs where the window has them, and one longer than that keeps its head.
    Session s = sessionIn(800, 600);
    const std::string older =
        "Opened 12-ramp.json: Ramp (3 particles), preset 12 of 14 (key "
        "Shift+2), paused: Space starts it";
    const std::string saved =
        "Saved video /home/lessons/particle-sandbox-20261207-031453.mp4: "
        "3.8 s, 135 frames";
    FrameView f = frameOf(s, {older, saved});
    ASSERT_FALSE(f.overlays.messages.empty());
    EXPECT_EQ(f.overlays.messages.front().rfind("Saved video", 0), 0u)
        << f.overlays.messages.front();
    std::string shown;
    for (const std::string& line : f.overlays.messages)
        shown += line;
    EXPECT_EQ(shown.find("Shift+2"), std::string::npos) << "half of the older message";
    const std::string longest = saved +
                                ", 980x1000 (36 frames a second of 60: the window drew no "
                                "faster, so the video is as smooth as the window was); every "
                                "frame is in it";
    // A message longer than the band's three lines takes the lines it needs where the window
    // has them, whole (issue 36).
    f = frameOf(s, {"Paused", longest});
    EXPECT_GT(f.overlays.messages.size(), kMessageLines);
    EXPECT_EQ(f.overlays.messages.front().rfind("Saved video", 0), 0u)
        << f.overlays.messages.front();
    shown.clear();
    for (const std::string& line : f.overlays.messages)
        shown += line;
    EXPECT_EQ(shown.find("\u2026"), std::string::npos) << shown;
    EXPECT_NE(shown.find("every frame is in it"), std::string::npos) << shown;
    EXPECT_LE(f.layout.messages.x + f.layout.messages.w, 800);
    // Only one longer than the window holds keeps the band's three lines, its head, and is
    // cut (the log has it whole).
    std::string endless = "Saved video";
    for (int k = 0; k < 40; ++k)
        endless += " (an aside) and more words";
    f = frameOf(s, {"Paused", endless});
    ASSERT_EQ(f.overlays.messages.size(), kMessageLines);
    EXPECT_EQ(f.overlays.messages.front().rfind("Saved video", 0), 0u)
        << f.overlays.messages.front();
    EXPECT_EQ(f.overlays.messages.back().substr(f.overlays.messages.back().size() - 3), "\u2026");
    EXPECT_LE(f.layout.messages.x + f.layout.messages.w, 800);
}

using test::lessonWorld;
using test::onTheProjector;

TEST(MessageBand, AMessageTooLongForTheBandDropsItsAsidesAndEndsWithAWholeWord) {
    // The lesson on the projector (200 %, 1600 x 1000): the video's message was cut mid-word
    // and ended in a '?' ("... of 60: the windo?"). Its aside in brackets goes instead, and
    // what was saved, where, and how long it is stay whole.
    const Session s = onTheProjector(lessonWorld(), {ShowOption::Momentum});
    const std::string head =
        "Saved video /home/teacher/lessons/particle-sandbox-20261207-182400.mp4: 3.4 s, 84 "
        "frames, 980x1000";
    const std::string saved = head + " (25 frames a second of 60: the window drew no faster)";
    const test::FixedMeasure font(2.0);
    FrameStats stats;
    stats.messages = {"Paused", saved};
    const FrameView f = buildFrame(s, stats, font, font, test::kProjector);
    ASSERT_LE(f.overlays.messages.size(), kMessageLines);
    std::string shown;
    for (const std::string& line : f.overlays.messages) {
        if (!shown.empty()) shown += ' ';
        shown += line;
        EXPECT_LE(font.measure(line) + 8, f.layout.messages.w) << line;
    }
    // The path may break after a '/': read back without the breaks' spaces.
    std::string joined;
    for (const std::string& line : f.overlays.messages)
        joined += line;
    // Whole where it fits; else without its aside, never cut.
    std::string whole = saved, short_ = head;
    for (std::string* t : {&whole, &short_, &joined})
        t->erase(std::remove(t->begin(), t->end(), ' '), t->end());
    EXPECT_TRUE(joined == whole || joined == short_) << shown;
    EXPECT_EQ(shown.find('?'), std::string::npos) << shown;
    EXPECT_EQ(shown.find("\u2026"), std::string::npos) << shown;
}

/// `world` in a `width` x `height` window at `scale`, laid out as the app lays it out (the
/// control panel open where it fits), the plots and the values table on.
Session tableSession(World world, int width, int height, double scale) {
    const test::FixedMeasure font(scale);
    const ControlsWidth controls{310.0 * scale, 44.0 * scale, scale};
    SessionOptions o;
    o.paused = true;
    o.viewportWidth = width;
    o.viewportHeight = height;
    o.layout = windowLayout(font, width, height, controls);
    o.controls = o.layout.controlsFit;
    Session s(std::move(world), SceneInfo{.name = "table", .dt = 1.0 / 60.0}, o);
    s.apply(cmd::SetShow{ShowOption::Plots, true});
    s.apply(cmd::SetShow{ShowOption::Values, true});
    return s;
}

TEST(ValuesTable, DocksOnScreenOffTheBoxAndThePanelsAtEveryScale) {
    // The values table (I) at 100 to 200 %, in windows from 800 x 600 up, the plots on, for
    // the default scene's square box and the lesson's wide one: inside the window, under the
    // HUD, clear of every other panel, and never over the box. As a window of its own it ran
    // off the window's right edge at 200 % and covered half the box and the plots at 125 %;
    // docked along the bottom it still covered the lesson's box at 200 % in 800 x 600.
    for (const auto& [width, height] : {std::pair{800, 600}, {1024, 768}, {1600, 1000}}) {
        for (const double scale : {1.0, 1.25, 1.5, 2.0}) {
            for (const bool lesson : {false, true}) {
                const test::FixedMeasure font(scale);
                const ControlsWidth controls{310.0 * scale, 44.0 * scale, scale};
                const Session s = tableSession(lesson ? lessonWorld() : makeWorld(defaultScene()),
                                               width, height, scale);
                const FrameView f = buildFrame(s, FrameStats{}, font, font, controls);
                const PixelRect& v = f.layout.values;
                const std::string at = std::to_string(width) + "x" + std::to_string(height) +
                                       " at " + std::to_string(scale) +
                                       (lesson ? ", the lesson" : ", the default scene");
                ASSERT_GT(v.w, 0) << at;
                EXPECT_GE(v.x, f.controlsInset + kPanelMargin) << at;
                EXPECT_LE(v.x + v.w, width - kPanelMargin) << at;
                EXPECT_LE(v.y + v.h, height - kPanelMargin) << at;
                EXPECT_GE(v.y, f.layout.hud.y + f.layout.hud.h) << at << ": under the HUD";
                EXPECT_EQ(v, valuesTableRect(s, controls)) << at << ": where the panel puts it";
                for (const PixelRect& other : {f.layout.hud, f.layout.messages, f.layout.plots,
                                               f.layout.legend, f.layout.inspector}) {
                    EXPECT_FALSE(overlaps(v, other)) << at;
                }
                const Camera::ScreenBox box =
                    s.camera().boxOnScreen(s.world().def().width, s.world().def().height);
                const PixelRect onScreen{
                    static_cast<int>(box.topLeft.x()), static_cast<int>(box.topLeft.y()),
                    static_cast<int>(box.size.x()), static_cast<int>(box.size.y())};
                EXPECT_FALSE(overlaps(v, onScreen)) << at << ": over the box";
                // Readable: a sixth of the window's height for the square box (beside the
                // panel open at 125 % in 800 x 600), 40 % of that for the wide one.
                EXPECT_GE(box.size.y(), height / 6.0 * (lesson ? 0.4 : 1.0)) << at;
            }
        }
    }
}

TEST(ValuesTable, InAShortWindowItDocksWhereTheBoxComesOutLargest) {
    // The lesson at 200 % in 800 x 600: a band along the bottom, even with one row, would
    // leave the box no height under the HUD; at the right it leaves the box most of the width.
    const Session tall = tableSession(lessonWorld(), 800, 600, 2.0);
    EXPECT_TRUE(tall.valuesDock().right);
    // (Under a HUD that keeps a line for the key to the discs' shades.)
    EXPECT_GE(tall.camera().boxOnScreen(10.0, 4.0).size.x(), 260.0);
    // At 100 % in 1600 x 1000 the band has all its rows.
    const Session big = tableSession(lessonWorld(), 1600, 1000, 1.0);
    EXPECT_FALSE(big.valuesDock().right);
    EXPECT_EQ(big.valuesDock().size,
              big.layout().area(big.controlsShown(), big.columnAsked()).valuesBand);
}

TEST(ValuesTable, OnTheProjectorItShowsEveryColumnAndTheTotalsAndThePlotsStay) {
    // The momentum lesson at 200 % in 1600 x 1000 with the plots (K) and the table (I): the
    // plots folded away and the table, in a column at the right, showed x, y and vx; its
    // totals were off to the side. The box gives up some of its size first: the table along
    // the bottom with every column and row, the plots beside the box, neither over it.
    const test::FixedMeasure font(2.0);
    const Session s = test::onTheProjector(
        test::lessonWorld(), {ShowOption::Plots, ShowOption::Values, ShowOption::Momentum});
    const FrameView f = buildFrame(s, FrameStats{}, font, font, test::kProjector);
    EXPECT_FALSE(s.valuesDock().right) << "in a column narrower than its columns";
    EXPECT_FALSE(f.layout.columnFolded) << "the plots folded away";
    ASSERT_GT(f.layout.plots.w, 0);
    ASSERT_GT(f.layout.values.w, 0);
    EXPECT_GE(f.layout.values.w, kValuesWidthPoints * 2.0) << "columns out of sight";
    const BoxArea& a = s.layout().area(s.controlsShown(), s.columnAsked());
    EXPECT_GE(s.valuesDock().size, a.valuesBand - a.valuesRow * (kValuesBandRows - 2) - 1e-9)
        << "a row of the two balls or the totals out of sight";
    const Camera::ScreenBox box = s.camera().boxOnScreen(10.0, 4.0);
    const PixelRect onScreen{static_cast<int>(box.topLeft.x()), static_cast<int>(box.topLeft.y()),
                             static_cast<int>(box.size.x()), static_cast<int>(box.size.y())};
    for (const PixelRect& r : panelRects(f.layout))
        EXPECT_FALSE(overlaps(r, onScreen)) << "a panel over the box";
    EXPECT_GE(box.size.x(), 480.0) << "the box";
}

TEST(MessageBand, ALongMessageDropsItsAsideBeforeItIsCut) {
    // The video's message in the room right of a 620-pixel panel at 200 %: four lines with its
    // aside, three without; it was cut mid-word, "... of 60: the windo?".
    const test::FixedMeasure font(2.0);
    const std::string head =
        "Saved video /home/teacher/lessons/particle-sandbox-20261207-182400.mp4: 3.4 s, 84 "
        "frames, 980x1000";
    const std::vector<std::string> lines = messageLines(
        font, {head + " (25 frames a second of 60: the window drew no faster)"}, 980 - 8, 3);
    ASSERT_EQ(lines.size(), 3u);
    std::string joined;
    for (const std::string& line : lines)
        joined += line.substr(line.find_first_not_of(' '));
    std::string want = head;
    want.erase(std::remove(want.begin(), want.end(), ' '), want.end());
    joined.erase(std::remove(joined.begin(), joined.end(), ' '), joined.end());
    EXPECT_EQ(joined, want);
}

TEST(Box, OnTheProjectorTheBoxKeepsMostOfTheWindowBesideThePanelAndTheCharts) {
    // Lesson 1 at 200 % in 1600 x 1000 with the momenta, the plots, the values table and the
    // collision card: the panel (620 pixels) and the plots' column left the box 510 pixels of
    // the window's 1600. The panel takes at most 30 % of the window now (480 pixels).
    const Session s = test::onTheProjector(
        test::lessonWorld(),
        {ShowOption::Momentum, ShowOption::Plots, ShowOption::Values, ShowOption::Collision});
    EXPECT_LE(test::kProjector.open, 0.3 * 1600);
    const Camera::ScreenBox box = s.camera().boxOnScreen(10.0, 4.0);
    EXPECT_GE(box.size.x(), 640.0) << "the box";
    EXPECT_GE(box.topLeft.x(), test::kProjector.open) << "beside the panel";
}

TEST(Plots, OnTheProjectorEachPlotHasRoomForThreeLabelledTicks) {
    // Lesson 1 at 200 % with the plots (K): two rows about 50 pixels of axis each, one tick
    // ("3.50", "-1.0"). Each row shown has room for three tick labels; the energy and px are
    // both there, and with the values table (which has the momenta) at least the energy.
    const test::FixedMeasure font(2.0);
    for (const bool table : {false, true}) {
        Session s = table ? test::onTheProjector(
                                test::lessonWorld(),
                                {ShowOption::Momentum, ShowOption::Plots, ShowOption::Values})
                          : test::onTheProjector(test::lessonWorld(),
                                                 {ShowOption::Momentum, ShowOption::Plots});
        const FrameView f = buildFrame(s, FrameStats{}, font, font, test::kProjector);
        const char* at = table ? "with the table" : "without the table";
        ASSERT_GT(f.layout.plots.w, 0) << at;
        // Beside the table's band there is room for fewer: the table has the momenta.
        EXPECT_GE(f.layout.plotRows * f.layout.plotColumns, table ? 1 : 2)
            << at << ": energy and px";
        const PlotRowsPlace p = plotRowsPlace(
            static_cast<float>(f.layout.plots.y), f.layout.plotRows,
            static_cast<float>(f.layout.plotRowHeight), static_cast<float>(font.lineHeight()));
        for (const PlotRowPlace& r : p.rows) {
            EXPECT_GE(yTickCount(r.bottom - r.top, font.lineHeight()), kPlotTicksLeast)
                << at << ": a plot " << r.bottom - r.top << " pixels high";
        }
    }
}

TEST(Plots, OnTheProjectorAThreeLineMessageMovesNoPlotNorTheLegend) {
    // Lesson 1 at 200 %: a message of three lines reached under the side column, a row of
    // plots went (py) and the momentum legend took its place, mid-video, until it went. The
    // messages wrap left of the column now: the charts are laid out alike with or without.
    const test::FixedMeasure font(2.0);
    const std::string lengthy =
        "Saved video /home/teacher/lessons/particle-sandbox-20261207-182400.mp4: 3.4 s, 84 "
        "frames, 980x1000, every frame of the clip as the window drew it at the time";
    for (const bool table : {false, true}) {
        const Session s = table ? test::onTheProjector(
                                      test::lessonWorld(),
                                      {ShowOption::Momentum, ShowOption::Plots, ShowOption::Values})
                                : test::onTheProjector(test::lessonWorld(),
                                                       {ShowOption::Momentum, ShowOption::Plots});
        FrameStats quiet, loud;
        loud.messages = {lengthy};
        const FrameView a = buildFrame(s, quiet, font, font, test::kProjector);
        const FrameView b = buildFrame(s, loud, font, font, test::kProjector);
        const char* at = table ? "with the table" : "without it";
        ASSERT_GT(a.layout.plots.w, 0) << at;
        ASSERT_GE(b.overlays.messages.size(), 2u) << at << ": the case, a long message";
        EXPECT_EQ(b.layout.plots, a.layout.plots) << at;
        EXPECT_EQ(b.layout.plotRows, a.layout.plotRows) << at;
        EXPECT_EQ(b.layout.plotColumns, a.layout.plotColumns) << at;
        EXPECT_EQ(b.layout.legend, a.layout.legend) << at;
        EXPECT_GT(b.layout.messages.w, 0) << at << ": the message is shown";
        EXPECT_FALSE(overlaps(b.layout.messages, b.layout.plots)) << at;
    }
}

TEST(Plots, OnTheProjectorLessonOneShowsAllFourAndAThreeLineMessageMovesNone) {
    // Lesson 1 at 200 % in 1600 x 1000 with the momenta (V) and the plots (K), recording a
    // video: Ctrl+R's message of three lines took the momentum legend's place below the box,
    // the legend went into the plots' band, and py went with the rate ("No room for py,
    // rate"), on the screen and in the video, for as long as the message showed. The rate
    // never fitted at all. All four stand side by side under the box now, the legend below
    // them, and the message wraps left of it.
    const test::FixedMeasure font(2.0);
    const Session s =
        test::onTheProjector(test::lessonWorld(), {ShowOption::Momentum, ShowOption::Plots});
    FrameStats quiet, loud;
    quiet.video.recording = loud.video.recording = true;
    loud.messages = {
        "Recording video (MP4, 1120x1000, 60 frames/s) to "
        "/home/teacher/lessons/particle-sandbox-20261207-182400.mp4: Ctrl+R stops "
        "(the panel's Video section has the format and the panel's part in it)"};
    const FrameView a = buildFrame(s, quiet, font, font, test::kProjector);
    const FrameView b = buildFrame(s, loud, font, font, test::kProjector);
    ASSERT_EQ(b.overlays.messages.size(), kMessageLines) << "the case, a message of three lines";
    for (const FrameView* f : {&a, &b}) {
        const char* when = f == &a ? "without the message" : "with it";
        EXPECT_EQ(plotsShown(f->layout), 4)
            << when << ": " << plotsLeftOutNote(plotsShown(f->layout));
        EXPECT_EQ(f->layout.plotsNote, 0) << when;
        PanelLayout shown = f->layout;
        shown.recording = {};  // not in the video: it keeps clear of the HUD as the screen shows it
        const std::vector<PixelRect> all = panelRects(shown);
        for (std::size_t i = 0; i < all.size(); ++i)
            for (std::size_t j = i + 1; j < all.size(); ++j)
                EXPECT_FALSE(overlaps(all[i], all[j])) << when << ": panels " << i << ", " << j;
        // Each plot's brief title, at least, within its frame.
        for (int k = 0; k < f->layout.plotColumns; ++k) {
            const PixelRect c = plotColumn(f->layout, k);
            EXPECT_LE(font.measure(plotTitle(k, s.rateWindow(), true)) + 2 * kChartPad, c.w)
                << when << ": plot " << k;
        }
    }
    EXPECT_EQ(b.layout.plots, a.layout.plots);
    EXPECT_EQ(b.layout.plotRows, a.layout.plotRows);
    EXPECT_EQ(b.layout.plotColumns, a.layout.plotColumns);
    EXPECT_EQ(b.layout.legend, a.layout.legend);
    EXPECT_GT(b.layout.messages.w, 0) << "the message is shown";
}

TEST(MessageBand, InLessonOneEveryVideoMessageShowsWholeAndMovesNoChart) {
    // Lesson 1 at 200 % in 1600 x 1000 (and at 100 % in 800 x 600) with the momenta (V), with
    // and without the plots (K): wrapped left of the momentum legend, Ctrl+R's message lost
    // "Ctrl+R stops" and ended in "…", and the saved video's message with two asides kept the
    // first and was cut. Each shows whole now; the plots and the legend stand where they stand
    // without it, and the message covers none of them.
    const std::string path = "/home/teacher/lessons/particle-sandbox-20261207-182400.mp4";
    const std::string recording =
        "Recording video (MP4, 1120x1000, 60 frames/s) to " + path + ": " + videoStopHint(false);
    const std::string saved = "Saved video " + path +
                              ": 3.4 s, 84 frames, 1120x1000 (25 frames a second of 60: the "
                              "window drew no faster), 3 frames left out (the encoder fell "
                              "behind; each held the one before)";
    const auto squeezed = [](std::string t) {
        t.erase(std::remove(t.begin(), t.end(), ' '), t.end());
        return t;
    };
    struct Window {
        int width, height;
        ControlsWidth controls;
    };
    for (const Window& w : {Window{1600, 1000, test::kProjector}, Window{800, 600, test::kDesk}}) {
        const test::FixedMeasure font(w.controls.pointPixels);
        for (const bool plots : {true, false}) {
            const Session s = plots ? test::inWindow(test::lessonWorld(),
                                                     {ShowOption::Momentum, ShowOption::Plots},
                                                     w.width, w.height, w.controls)
                                    : test::inWindow(test::lessonWorld(), {ShowOption::Momentum},
                                                     w.width, w.height, w.controls);
            for (const std::string& message : {recording, saved}) {
                const std::string at = std::to_string(w.width) + "x" + std::to_string(w.height) +
                                       (plots ? ", the plots" : ", no plots") + ": " +
                                       message.substr(0, 14);
                FrameStats quiet, loud;
                quiet.video.recording = loud.video.recording = message == recording;
                loud.messages = {"Paused", message};
                const FrameView a = buildFrame(s, quiet, font, font, w.controls);
                const FrameView b = buildFrame(s, loud, font, font, w.controls);
                ASSERT_GT(b.layout.messages.w, 0) << at << ": the message is shown";
                std::string shown;
                for (const std::string& line : b.overlays.messages) {
                    shown += line + '|';
                    EXPECT_LE(font.measure(line) + 8, b.layout.messages.w) << at << ": " << line;
                }
                EXPECT_EQ(shown.find("\u2026"), std::string::npos) << at << ": " << shown;
                if (message == recording) {
                    EXPECT_NE(shown.find("Ctrl+R stops"), std::string::npos) << at << ": " << shown;
                }
                // The newest message whole (a path may break after a '/'): the older may go.
                std::string joined;
                for (const std::string& line : b.overlays.messages)
                    joined += line;
                const std::string whole = squeezed(message), got = squeezed(joined);
                EXPECT_TRUE(got.size() >= whole.size() &&
                            got.compare(got.size() - whole.size(), whole.size(), whole) == 0)
                    << at << ": " << shown;
                // Inside the window, right of the control panel.
                EXPECT_GE(b.layout.messages.x, 0) << at;
                EXPECT_LE(b.layout.messages.x + b.layout.messages.w, w.width) << at;
                EXPECT_GE(b.layout.messages.y, 0) << at;
                EXPECT_LE(b.layout.messages.y + b.layout.messages.h, w.height) << at;
                // Nothing moves, nothing is covered.
                EXPECT_EQ(b.layout.plots, a.layout.plots) << at;
                EXPECT_EQ(b.layout.plotRows, a.layout.plotRows) << at;
                EXPECT_EQ(b.layout.plotColumns, a.layout.plotColumns) << at;
                EXPECT_EQ(b.layout.plotsNote, a.layout.plotsNote) << at;
                EXPECT_EQ(b.layout.legend, a.layout.legend) << at;
                EXPECT_EQ(b.layout.hud, a.layout.hud) << at;
                EXPECT_FALSE(overlaps(b.layout.messages, b.layout.plots)) << at;
                EXPECT_FALSE(overlaps(b.layout.messages, b.layout.legend)) << at;
                EXPECT_FALSE(overlaps(b.layout.messages, b.layout.hud)) << at;
                if (plots) {
                    EXPECT_GT(b.layout.plots.w, 0) << at;
                }
                EXPECT_GT(b.layout.legend.w, 0) << at;
            }
        }
    }
}

TEST(Plots, OnTheProjectorThePlotsLeftOutForWantOfRoomAreNamed) {
    // Lesson 1 at 200 % with the values table and the plots: only the energy's chart showed,
    // px, py and the rate were gone without a word (the gas says when its charts fold away).
    // The one that fits is px, the lesson's (plotsChosen).
    const test::FixedMeasure font(2.0);
    for (const bool table : {true}) {
        const Session s = table ? test::onTheProjector(
                                      test::lessonWorld(),
                                      {ShowOption::Momentum, ShowOption::Plots, ShowOption::Values})
                                : test::onTheProjector(test::lessonWorld(),
                                                       {ShowOption::Momentum, ShowOption::Plots});
        const FrameView f = buildFrame(s, FrameStats{}, font, font, test::kProjector);
        const char* at = table ? "with the table" : "without it";
        ASSERT_GT(f.layout.plots.w, 0) << at;
        const int shown = plotsShown(f.layout);
        ASSERT_LT(shown, 4) << at << ": the case, not all four fit";
        EXPECT_GT(f.layout.plotsNote, 0) << at << ": a line under the plots names the others";
        const std::string note = plotsLeftOutNote(shown);
        EXPECT_NE(note.find("rate"), std::string::npos) << note;
        EXPECT_EQ(plotsChosen(shown).front(), 1) << at << ": px first";
        EXPECT_LE(font.measure(note) + 2 * kChartPad, f.layout.plots.w)
            << at << ": " << note << ": cut";
        // The rows and the note within the panel's box.
        EXPECT_LE(f.layout.plotRows * f.layout.plotRowHeight + 8 + f.layout.plotsNote,
                  f.layout.plots.h)
            << at;
    }
}

TEST(Help, WhileAVideoRecordsTheRecordingMarkStandsClearOfTheHelpsLines) {
    // Lesson 1 on the projector with the plots and the legend, recording, the help open: the
    // mark went under the legend and the plots, as it does without the help, and was drawn
    // over the help's text there.
    const test::FixedMeasure font(2.0);
    Session s =
        test::onTheProjector(test::lessonWorld(), {ShowOption::Momentum, ShowOption::Plots});
    s.apply(cmd::ToggleHelp{});
    ASSERT_TRUE(s.helpShown());
    FrameStats stats;
    stats.video.recording = true;
    const FrameView f = buildFrame(s, stats, font, font, test::kProjector);
    ASSERT_TRUE(f.recordingMark.has_value());
    const PixelRect mark = f.recordingMark->at;
    ASSERT_GT(mark.w, 0);
    EXPECT_LE(mark.x + mark.w, 1600);
    EXPECT_LE(mark.y + mark.h, 1000);
    for (const PixelRect& line : helpLineRects(font, f.overlays.help, f.overlays.helpAt))
        EXPECT_FALSE(overlaps(line, mark)) << "the mark over a line of the help";
}

TEST(LabelKeepOut, NoLabelStandsOnTheTotalMomentumsArrow) {
    // Lesson 1 after its collision with the momenta (V) and labels (S): ball 2's label stood
    // centred over the centre of mass's arrow, and read as the arrow's.
    const test::FixedMeasure font(2.0);
    Session s =
        test::onTheProjector(test::lessonWorld(), {ShowOption::Momentum, ShowOption::Labels});
    const FrameView f = buildFrame(s, FrameStats{}, font, font, test::kProjector);
    const LabelKeepOut out = labelKeepOut(f, font);
    const Vec2 centre = s.camera().worldToScreen(s.observables().centreOfMass);
    const PixelRect onIt{static_cast<int>(centre.x()) - 1, static_cast<int>(centre.y()) - 1, 3, 3};
    EXPECT_TRUE(std::any_of(out.walls.begin(), out.walls.end(), [&](const ScreenWall& w) {
        return crosses(onIt, w);
    })) << "a label may stand on the centre of mass and its arrow";
}

TEST(MomentumLegend, StaysWhileSteppingBackAndInAVideoOfTheBox) {
    // Lesson 1 on the projector with the momenta (V) and the plots (K), the plots in their band
    // under the box: a step back in time grew the HUD by its "Viewing ... back" lines, the
    // legend moved below the box under the plots' band and was drawn over by it; a video keeps
    // the room for those lines all along, and had no legend at all.
    const test::FixedMeasure font(2.0);
    Session s =
        test::onTheProjector(test::lessonWorld(), {ShowOption::Momentum, ShowOption::Plots});
    s.apply(cmd::TogglePause{});
    for (int k = 1; k <= 60; ++k)
        s.update(1.0 / 60.0, k / 60.0);
    s.apply(cmd::TogglePause{});
    const auto check = [&](const FrameView& f, const char* when) {
        ASSERT_GT(f.layout.legend.w, 0) << when << ": no legend";
        const Camera::ScreenBox box = s.camera().boxOnScreen(10.0, 4.0);
        const PixelRect onScreen{static_cast<int>(box.topLeft.x()),
                                 static_cast<int>(box.topLeft.y()), static_cast<int>(box.size.x()),
                                 static_cast<int>(box.size.y())};
        EXPECT_FALSE(overlaps(f.layout.legend, onScreen)) << when << ": over the box";
        EXPECT_GE(f.layout.legend.x, f.controlsInset) << when;
        EXPECT_LE(f.layout.legend.x + f.layout.legend.w, 1600) << when;
        EXPECT_LE(f.layout.legend.y + f.layout.legend.h, 1000) << when;
        const std::vector<PixelRect> all = panelRects(f.layout);
        for (const PixelRect& r : all) {
            if (r.x == f.layout.legend.x && r.y == f.layout.legend.y) continue;
            EXPECT_FALSE(overlaps(r, f.layout.legend))
                << when << ": a panel at " << r.x << ", " << r.y << " over the legend";
        }
        // The plots are still there.
        EXPECT_GT(f.layout.plots.w, 0) << when;
    };
    check(buildFrame(s, FrameStats{}, font, font, test::kProjector), "now");
    s.apply(cmd::StepBack{});
    ASSERT_TRUE(s.timeline().viewingPast);
    check(buildFrame(s, FrameStats{}, font, font, test::kProjector), "a step back");
    FrameStats recording;
    recording.video.recording = true;
    check(buildFrame(s, recording, font, font, test::kProjector), "a step back, recording");
    s.apply(cmd::StepForward{});
    check(buildFrame(s, recording, font, font, test::kProjector), "recording");
}

/// A 7 m box with two rows of balls just below and just above its middle, where the ruler
/// lies, at 200 % in a 1600 x 1000 window, the ruler on.
Session rulerAmongBalls() {
    const test::FixedMeasure font(2.0);
    const ControlsWidth controls{620.0, 88.0, 2.0};
    WorldDef def;
    def.width = def.height = 7.0;
    World w(def);
    for (int k = 0; k < 7; ++k) {
        for (const double y : {3.15, 3.85})
            w.add({.position = Vec2(0.5 + k, y), .mass = 1.0, .radius = 0.25});
    }
    SessionOptions o;
    o.paused = true;
    o.viewportWidth = 1600;
    o.viewportHeight = 1000;
    o.layout = windowLayout(font, 1600, 1000, controls);
    Session s(std::move(w), SceneInfo{.name = "rows", .dt = 1.0 / 60.0}, o);
    s.apply(cmd::SetShow{ShowOption::Ruler, true});
    return s;
}

TEST(RulerReading, ItCoversNoBallWhereTheWindowHasAFreePlace) {
    // The ruler across a small box's middle at 200 %: its reading went below the ruler's
    // middle over the balls there (and the particles' labels over it), though the box had room
    // a little further down.
    const test::FixedMeasure font(2.0);
    const ControlsWidth controls{620.0, 88.0, 2.0};
    const Session s = rulerAmongBalls();
    const FrameView f = buildFrame(s, FrameStats{}, font, font, controls);
    ASSERT_TRUE(f.ruler.has_value());
    const PixelRect r = labelRect(f.ruler->label, font, kReadingPad);
    EXPECT_GE(r.x, f.controlsInset) << "whole, right of the control panel";
    EXPECT_LE(r.x + r.w, 1600);
    EXPECT_GE(r.y, 0);
    EXPECT_LE(r.y + r.h, 1000);
    for (const PixelRect& panel : panelRects(f.layout))
        EXPECT_FALSE(overlaps(r, panel)) << "under a panel";
    const ParticleArrays& p = s.world().particles();
    for (std::size_t i = 0; i < p.size(); ++i) {
        const Vec2 c = s.camera().worldToScreen(Vec2(p.x[i], p.y[i]));
        const double radius = s.camera().toScreen(p.radius[i]);
        const PixelRect disc{static_cast<int>(c.x() - radius), static_cast<int>(c.y() - radius),
                             static_cast<int>(2.0 * radius), static_cast<int>(2.0 * radius)};
        EXPECT_FALSE(overlaps(r, disc)) << "over ball " << i + 1;
    }
}

TEST(RulerReading, ItIsReadWholeBesideTheOpenPanelAt200Percent) {
    // 1280 x 800 at 200 % with the control panel open: 660 pixels right of it, and the reading
    // in one line is 760 (8 pixels a character at 200 %): it was cut at the panel. In two
    // lines it fits.
    const test::FixedMeasure font(2.0);
    const ControlsWidth controls{620.0, 88.0, 2.0};
    SessionOptions o;
    o.paused = true;
    o.viewportWidth = 1280;
    o.viewportHeight = 800;
    o.layout = windowLayout(font, 1280, 800, controls);
    ASSERT_TRUE(o.layout.controlsFit);
    Session s(makeWorld(defaultScene()), SceneInfo{.name = "default", .dt = 1.0 / 60.0}, o);
    s.apply(cmd::SetShow{ShowOption::Ruler, true});
    const FrameView f = buildFrame(s, FrameStats{}, font, font, controls);
    ASSERT_EQ(f.controlsInset, 620);
    const PixelRect r = labelRect(f.ruler->label, font, kReadingPad);
    EXPECT_GE(r.x, 620) << "cut at the panel";
    EXPECT_LE(r.x + r.w, 1280);
    EXPECT_GE(r.y, 0);
    EXPECT_LE(r.y + r.h, 800);
    for (const PixelRect& panel : panelRects(f.layout))
        EXPECT_FALSE(overlaps(r, panel)) << "under a panel";
}

TEST(RulerReading, TheParticlesLabelsGoRoundIt) {
    const test::FixedMeasure font(2.0);
    const Session s = rulerAmongBalls();
    const FrameView f = buildFrame(s, FrameStats{}, font, font, {620.0, 88.0, 2.0});
    const LabelKeepOut keep = labelKeepOut(f, font);
    const auto has = [&keep](const PixelRect& r) {
        return std::find(keep.rects.begin(), keep.rects.end(), r) != keep.rects.end();
    };
    EXPECT_TRUE(has(labelRect(f.ruler->label, font, kReadingPad))) << "the reading";
    for (const PixelRect& panel : panelRects(f.layout))
        EXPECT_TRUE(has(panel)) << "a panel";
    ASSERT_EQ(keep.walls.size(), 1u) << "the ruler";
    const PixelRect onTheEdge{static_cast<int>(f.ruler->a.x() + 20.0),
                              static_cast<int>(f.ruler->a.y()) - 2, 10, 4};
    EXPECT_TRUE(crosses(onTheEdge, keep.walls[0]));
}

TEST(LabelsLeftOut, TheHudSaysWhatKeptThemOut) {
    // Labels left out because others were in the way, and because no side of the disc was in
    // the window: two reasons, two different lines (a label only running off the window's
    // edge used to be counted as "where they would overlap").
    Session s = sessionIn(800, 800);
    s.apply(cmd::SetShow{ShowOption::Labels, true});
    const test::FixedMeasure font;
    FrameStats stats;
    stats.labelsCrowded = 2;
    stats.labelsOffWindow = 1;
    const auto hud = buildFrame(s, stats, font, font, {310.0, 44.0}).overlays.hud;
    const auto has = [&hud](const std::string& text) {
        return std::any_of(hud.begin(), hud.end(),
                           [&](const std::string& l) { return l.find(text) != std::string::npos; });
    };
    EXPECT_TRUE(has("Labels: 2 left out where they would overlap"));
    EXPECT_TRUE(has("Labels: 1 left out: no room beside the disc in the window"));
}

TEST(LabelsLeftOut, TheHudsNoteWrapsWithinTheWindowAtTwiceTheScale) {
    // At 200 % in 800 x 600 the note ran past the window's right edge ("...would overla").
    const test::FixedMeasure font(2.0);
    const ControlsWidth controls{620.0, 88.0, 2.0};
    SessionOptions o;
    o.paused = true;
    o.viewportWidth = 800;
    o.viewportHeight = 600;
    o.layout = windowLayout(font, 800, 600, controls);
    o.controls = false;
    Session s(makeWorld(defaultScene()), SceneInfo{.name = "default", .dt = 1.0 / 60.0}, o);
    s.apply(cmd::SetShow{ShowOption::Labels, true});
    FrameStats stats;
    stats.labelsCrowded = 2;
    const FrameView f = buildFrame(s, stats, font, font, controls);
    std::string said;
    for (const std::string& line : f.overlays.hud) {
        EXPECT_LE(f.layout.hud.x + font.measure(line) + 8, 800) << line;
        said += line;
    }
    EXPECT_NE(said.find("Labels: 2 left out"), std::string::npos);
    EXPECT_NE(said.find("(zoom in)"), std::string::npos);
}

TEST(RecordingMark, ShownOnlyWhileRecordingInTheTopRightCornerWithTheTime) {
    const Session s = sessionIn(1600, 800, true);
    const test::FixedMeasure font;
    FrameStats stats;
    EXPECT_FALSE(buildFrame(s, stats, font, font, {310.0, 44.0}).recordingMark.has_value());
    stats.video.recording = true;
    stats.video.format = VideoFormat::WebM;
    stats.video.seconds = 65.7;
    const FrameView f = buildFrame(s, stats, font, font, {310.0, 44.0});
    ASSERT_TRUE(f.recordingMark.has_value());
    EXPECT_EQ(f.recordingMark->label, "REC 1:05 WebM - Ctrl+R stops");
    const PixelRect& r = f.recordingMark->at;
    EXPECT_LE(r.x + r.w, 1600);
    EXPECT_GT(r.x, 800);  // the right half, away from the HUD at the left
    EXPECT_GE(r.y, 0);
    EXPECT_LT(r.y, 40);
}

TEST(RecordingMark, OnATouchScreenTheFramesHintsNameThePanelsControls) {
    // A laptop's touch screen: the mark, the HUD and the inspector name the panel's buttons.
    Session s = sessionIn(1600, 800, false);
    s.apply(cmd::SetTouch{true});
    s.apply(cmd::Select{s.world().ids()[0]});
    s.apply(cmd::SetRecording{true, 1});
    const test::FixedMeasure font;
    FrameStats stats;
    stats.video.recording = true;
    stats.video.format = VideoFormat::WebM;
    stats.video.seconds = 65.7;
    const FrameView f = buildFrame(s, stats, font, font, {310.0, 44.0});
    ASSERT_TRUE(f.recordingMark.has_value());
    EXPECT_EQ(f.recordingMark->label, "REC 1:05 WebM - Video: Stop video");
    std::string hud;
    for (const std::string& l : f.overlays.hud)
        hud += l + "\n";
    EXPECT_NE(hud.find("REC (Data: Stop recording)"), std::string::npos) << hud;
    ASSERT_FALSE(f.overlays.inspector.empty());
    EXPECT_EQ(f.overlays.inspector.back(), "Edit: the panel's Selected particle");
}

TEST(RecordingMark, TheMomentumLegendAndTheProfileGoUnderItNotUnderIt) {
    // The mark was put in the window's top-right corner after the layout, where the momentum
    // legend (V) already was: "REC" covered the legend's first line.
    Session s = sessionIn(1280, 800, true);
    s.apply(cmd::SetShow{ShowOption::Momentum, true});
    s.apply(cmd::SetShow{ShowOption::Profile, true});
    const test::FixedMeasure font;
    FrameStats stats;
    stats.video.recording = true;
    const FrameView f = buildFrame(s, stats, font, font, {310.0, 44.0});
    ASSERT_TRUE(f.recordingMark.has_value());
    const PixelRect& mark = f.recordingMark->at;
    ASSERT_GT(f.layout.legend.w, 0);
    ASSERT_GT(f.layout.profile.w, 0);
    EXPECT_FALSE(overlaps(mark, f.layout.legend));
    EXPECT_FALSE(overlaps(mark, f.layout.profile));
    EXPECT_FALSE(overlaps(mark, f.layout.hud));
    EXPECT_EQ(mark.x + mark.w, 1280 - kPanelMargin) << "still in the top-right corner";
}

TEST(Video, ItHoldsTheReadingsNotTheKeyHintsAndThePlotsKeepTheirRowsThroughTheClip) {
    // A teacher's clip: "H: help" and "Viewing 0.98 s back: Space continues from here,
    // Shift+Left/Right step" were in it, and the plots went from four rows to three when the
    // clip stepped into the past (the HUD's extra line pushed the side column down).
    Session s = sessionIn(1000, 760, true);
    s.apply(cmd::SetShow{ShowOption::Plots, true});
    s.apply(cmd::SetShow{ShowOption::Momentum, true});
    s.apply(cmd::TogglePause{});
    for (int k = 1; k <= 60; ++k)
        s.update(1.0 / 60.0, k / 60.0);
    s.apply(cmd::TogglePause{});
    const test::FixedMeasure font;
    FrameStats stats;
    const auto joined = [](const std::vector<std::string>& lines) {
        std::string all;
        for (const std::string& l : lines)
            all += l + "\n";
        return all;
    };
    const FrameView screen = buildFrame(s, stats, font, font, {310.0, 44.0});
    EXPECT_TRUE(screen.overlays.hudRecorded.empty()) << "nothing records";
    stats.video.recording = true;
    const FrameView now = buildFrame(s, stats, font, font, {310.0, 44.0});
    s.apply(cmd::StepBack{});
    s.apply(cmd::StepBack{});
    const FrameView past = buildFrame(s, stats, font, font, {310.0, 44.0});
    const std::string shown = joined(past.overlays.hud), video = joined(past.overlays.hudRecorded);
    EXPECT_NE(shown.find("H: help"), std::string::npos) << "the screen keeps its hints";
    EXPECT_NE(shown.find("Shift+Left/Right"), std::string::npos);
    EXPECT_NE(video.find("(0.03 s back) | x1"), std::string::npos) << video;
    EXPECT_NE(video.find("Kinetic energy"), std::string::npos);
    EXPECT_NE(video.find("Arrows: 0.333 s of motion"), std::string::npos) << video;
    for (const char* hint : {"H: help", "Space continues", "Shift+", "New:", "(X stops)"})
        EXPECT_EQ(video.find(hint), std::string::npos) << hint << " in the video: " << video;
    ASSERT_GT(now.layout.plots.w, 0);
    EXPECT_EQ(past.layout.plotRows, now.layout.plotRows) << "no row gone mid-clip";
    EXPECT_EQ(past.layout.plots.y, now.layout.plots.y);
    EXPECT_EQ(past.layout.legend.y, now.layout.legend.y);
}

TEST(RecordingMark, InANarrowWindowItGoesBelowTheHudNotOverIt) {
    const Session s = sessionIn(420, 700, false);
    const test::FixedMeasure font;
    FrameStats stats;
    stats.video.recording = true;
    const FrameView f = buildFrame(s, stats, font, font, {310.0, 44.0});
    ASSERT_TRUE(f.recordingMark.has_value());
    const PixelRect& m = f.recordingMark->at;
    // The HUD as the screen shows it: the video's, and the screen's drawn over it (the layout
    // keeps it more room, for the lines that come and go through the clip; the mark, which is
    // not in the video, goes under what is there).
    const PixelPoint screen = textBoxSize(font, f.overlays.hud),
                     video = textBoxSize(font, f.overlays.hudRecorded);
    const PixelRect hud{f.layout.hud.x, f.layout.hud.y, std::max(screen.x, video.x),
                        std::max(screen.y, video.y)};
    ASSERT_GT(hud.w, 0);
    const bool overlap =
        m.x < hud.x + hud.w && hud.x < m.x + m.w && m.y < hud.y + hud.h && hud.y < m.y + m.h;
    EXPECT_FALSE(overlap) << "mark " << m.x << "," << m.y << " " << m.w << "x" << m.h << ", HUD "
                          << hud.x << "," << hud.y << " " << hud.w << "x" << hud.h;
}

/// A preset scene's world, from the source tree's assets/scenes/`name`.
World presetWorld(const char* name) {
    return makeWorld(loadScene(std::filesystem::path(PSB_ASSETS_DIR) / "scenes" / name));
}

TEST(BoxShare, OnTheProjectorTheLessonsBoxesKeepAReasonableShareOfTheWindow) {
    // 200 % in 1600 x 1000: the ramp with the values table (I) and the ruler (Q) was fitted
    // into 200 x 190 pixels under the table's three rows, its bodies dots under the ruler; the
    // momentum lesson with the plots (K), the momentum view (V) and labels (S) into 510 x 205
    // beside the plots, its balls 7 pixels across; then its plots folded away (the trial of
    // the lessons at 200 %): they go under its box. Something else gives way first
    // (docs/app-instruments.md, Values table): the box keeps at least 60 % of the size it has with
    // neither the side column nor the values table beside it.
    const test::FixedMeasure font(2.0);
    const ControlsWidth controls = test::kProjector;
    {
        const Session bare = onTheProjector(presetWorld("12-ramp.json"), {});
        const Session s =
            onTheProjector(presetWorld("12-ramp.json"), {ShowOption::Values, ShowOption::Ruler});
        const Camera::ScreenBox free = bare.camera().boxOnScreen(4.0, 3.9);
        const Camera::ScreenBox box = s.camera().boxOnScreen(4.0, 3.9);
        EXPECT_GE(box.size.y(), 0.6 * free.size.y()) << "the ramp's box";
        EXPECT_GE(box.size.y(), 360.0) << "the ramp's box";
        // The table is on screen and off the box.
        const FrameView f = buildFrame(s, FrameStats{}, font, font, controls);
        const PixelRect onScreen{static_cast<int>(box.topLeft.x()),
                                 static_cast<int>(box.topLeft.y()), static_cast<int>(box.size.x()),
                                 static_cast<int>(box.size.y())};
        ASSERT_GT(f.layout.values.w, 0);
        EXPECT_FALSE(overlaps(f.layout.values, onScreen));
    }
    {
        const Session bare = onTheProjector(lessonWorld(), {});
        const Session s = onTheProjector(
            lessonWorld(), {ShowOption::Plots, ShowOption::Momentum, ShowOption::Labels});
        const Camera::ScreenBox free = bare.camera().boxOnScreen(10.0, 4.0);
        const Camera::ScreenBox box = s.camera().boxOnScreen(10.0, 4.0);
        EXPECT_GE(box.size.x(), 0.6 * free.size.x()) << "the lesson's box";
        EXPECT_GE(box.size.x(), 760.0) << "the lesson's box";
        const FrameView f = buildFrame(s, FrameStats{}, font, font, controls);
        // The plots neither fold away nor squeeze the box: a column beside this wide, low box
        // would leave it less than its share, so they go in a band under it, two plots or more
        // (side by side in a band one row high).
        EXPECT_FALSE(f.layout.columnFolded) << "the lesson's plots folded away";
        EXPECT_TRUE(s.chartsBelow());
        ASSERT_GT(f.layout.plots.w, 0);
        EXPECT_GE(f.layout.plotRows * f.layout.plotColumns, 2);
        EXPECT_GE(f.layout.plotRowHeight, 2 * kPlotRowMinHeight);
        EXPECT_GE(f.layout.plots.w, 2 * kPanelMinWidth);
        const PixelRect onScreen{static_cast<int>(box.topLeft.x()),
                                 static_cast<int>(box.topLeft.y()), static_cast<int>(box.size.x()),
                                 static_cast<int>(box.size.y())};
        EXPECT_GE(f.layout.plots.y, onScreen.y + onScreen.h) << "under the box";
        for (const PixelRect& r : panelRects(f.layout)) {
            if (r == f.layout.plots) continue;
            EXPECT_FALSE(overlaps(r, f.layout.plots));
        }
        for (const std::string& line : f.overlays.hud)
            EXPECT_EQ(line.find("folded"), std::string::npos) << line;
    }
}

/// Whether the segments a-b and c-d cross, pixels.
bool segmentsCross(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
    const auto side = [](Vec2 p, Vec2 q, Vec2 r) {
        return (q.x() - p.x()) * (r.y() - p.y()) - (q.y() - p.y()) * (r.x() - p.x());
    };
    return (side(a, b, c) > 0.0) != (side(a, b, d) > 0.0) &&
           (side(c, d, a) > 0.0) != (side(c, d, b) > 0.0);
}

TEST(LabelPlaces, OnTheRampNoLabelNorItsLineCrossesARampNorTouchesTheBoxsWalls) {
    // The ramp at 200 % with labels (S): the top body's label stood on the box's top wall, and
    // the middle one's was joined to its body by a line across the top ramp (its label on the
    // wrong side of the ramp), though docs/app.md says a label never crosses a wall. Labels
    // are placed as the drawing layer places them (render/renderer.cpp, view/particle_labels.hpp):
    // between the two ramps only a name fits, so every body's label is its name alone.
    const test::FixedMeasure font(2.0);
    const Session s = onTheProjector(presetWorld("12-ramp.json"), {ShowOption::Labels});
    const FrameView f = buildFrame(s, FrameStats{}, font, font, test::kProjector);
    const LabelKeepOut keep = labelKeepOut(f, font);
    const Camera& camera = s.camera();
    LabelRoom room = labelRoom(s.world(), camera, {0, 0, 1600, 1000}, keep.rects);
    room.walls.insert(room.walls.end(), keep.walls.begin(), keep.walls.end());
    const ParticleArrays& p = s.world().particles();
    std::vector<LabelAsk> asks;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const Vec2 c = camera.worldToScreen(Vec2(p.x[i], p.y[i]));
        const int r = static_cast<int>(std::ceil(camera.toScreen(p.radius[i]))) + kLabelGap;
        const int cx = static_cast<int>(std::lround(c.x())),
                  cy = static_cast<int>(std::lround(c.y()));
        const ParticleLabelText text =
            particleLabelText(particleNumber(p.id[i]), p.mass[i], p.vx[i], p.vy[i]);
        asks.push_back(particleLabelAsk(text, {cx - r, cy - r, 2 * r, 2 * r}, font, true));
    }
    const std::vector<LabelPlace> places = placeLabels(asks, room);
    const Camera::ScreenBox b = camera.boxOnScreen(4.0, 3.9);
    const double wall = boxWallPixels(4.0, 3.9, camera.zoom());
    for (std::size_t i = 0; i < places.size(); ++i) {
        const PixelRect& r = places[i].at;
        ASSERT_GT(r.w, 0) << "body " << i + 1 << " lost its label";
        const double x0 = r.x, y0 = r.y, x1 = r.x + r.w, y1 = r.y + r.h;
        const double bx0 = std::floor(b.topLeft.x()), by0 = std::floor(b.topLeft.y());
        const double bx1 = bx0 + b.size.x(), by1 = by0 + b.size.y();
        const bool inside = x0 >= bx0 && y0 >= by0 && x1 <= bx1 && y1 <= by1;
        const bool outside =
            x1 <= bx0 - wall || x0 >= bx1 + wall || y1 <= by0 - wall || y0 >= by1 + wall;
        EXPECT_TRUE(inside || outside)
            << "label " << i + 1 << " at " << r.x << "," << r.y << " " << r.w << "x" << r.h
            << " on the box's walls (top at " << by0 << ", " << wall << " thick)";
        for (const Obstacle& o : s.world().obstacles()) {
            const ScreenWall ramp{camera.worldToScreen(o.a).x(), camera.worldToScreen(o.a).y(),
                                  camera.worldToScreen(o.b).x(), camera.worldToScreen(o.b).y(),
                                  camera.toScreen(o.radius)};
            EXPECT_FALSE(crosses(r, ramp)) << "label " << i + 1 << " across a ramp";
            if (!places[i].leader) continue;
            const LeaderLine l = leaderLine(asks[i].disc, r);
            EXPECT_FALSE(segmentsCross(Vec2(l.ax, l.ay), Vec2(l.bx, l.by), Vec2(ramp.ax, ramp.ay),
                                       Vec2(ramp.bx, ramp.by)))
                << "label " << i + 1 << "'s line across a ramp";
        }
    }
}

TEST(MarkLabels, OnTheRampTheRulersReadingNeverCoversABallAsTheyRoll) {
    // The ramp lesson at 200 % with the grid and the plots (what lesson 1 left shown): as the
    // bodies rolled, the room beside the ruler left no place clear of the balls, the ramps and
    // the grid's distances, and the reading was drawn over the bottom body. With the labels
    // (S) and the values table (I) too. Each frame of 2.5 s, the reading covers no ball.
    const test::FixedMeasure font(2.0);
    for (const bool more : {false, true}) {
        Session s = test::onTheProjector(presetWorld("12-ramp.json"),
                                         {ShowOption::Ruler, ShowOption::Grid, ShowOption::Plots});
        if (more) {
            s.apply(cmd::SetShow{ShowOption::Labels, true});
            s.apply(cmd::SetShow{ShowOption::Values, true});
        }
        s.apply(cmd::TogglePause{});
        for (int k = 0; k <= 150; ++k) {
            if (k > 0) s.update(1.0 / 60.0, k / 60.0);
            const FrameView f = buildFrame(s, FrameStats{}, font, font, test::kProjector);
            ASSERT_TRUE(f.ruler.has_value());
            const PixelRect reading = labelRect(f.ruler->label, font, kReadingPad);
            const std::vector<PixelRect> balls =
                discsOnScreen(s.world(), s.camera(), {0, 0, 1600, 1000});
            for (std::size_t i = 0; i < balls.size(); ++i) {
                ASSERT_FALSE(overlaps(reading, balls[i]))
                    << (more ? "with labels and the table, " : "") << "at " << s.world().time()
                    << " s the reading at " << reading.x << "," << reading.y << " " << reading.w
                    << "x" << reading.h << " covers body " << i + 1;
            }
            for (const PixelRect& panel : panelRects(f.layout))
                ASSERT_FALSE(overlaps(reading, panel)) << "under a panel at " << s.world().time();
        }
    }
}

TEST(GridView, OnTheProjectorItsLabelsStandInsideTheBoxClearOfItsTopWall) {
    // The grid (Shift+G) on the ramp at 200 %: its labels along the top straddled the top
    // wall, and a ruler's reading placed above the box took their place (the 1, 2, 3 m went
    // away once the ruler moved). Each stands inside the box, clear of the wall, and none is
    // left out.
    const test::FixedMeasure font(2.0);
    const Session s =
        onTheProjector(presetWorld("12-ramp.json"), {ShowOption::Grid, ShowOption::Ruler});
    const FrameView f = buildFrame(s, FrameStats{}, font, font, test::kProjector);
    ASSERT_TRUE(f.grid.has_value());
    const Camera::ScreenBox b = s.camera().boxOnScreen(4.0, 3.9);
    const GridView all = gridView(s.camera(), 4.0, 3.9, true, 2.0 * kGridMinPixels, 34.0);
    EXPECT_EQ(f.grid->labels.size(), all.labels.size()) << "grid labels left out";
    int along = 0, up = 0;
    for (const MarkLabel& l : f.grid->labels) {
        const PixelRect r = labelRect(l, font);
        (l.left ? up : along) += 1;
        EXPECT_GE(r.y, b.topLeft.y() + boxWallPixels(4.0, 3.9, s.camera().zoom())) << l.text;
        EXPECT_GE(r.x, b.topLeft.x()) << l.text;
        EXPECT_LE(r.y + r.h, b.topLeft.y() + b.size.y()) << l.text;
    }
    EXPECT_GE(along, 3);
    EXPECT_GE(up, 3);
}

}  // namespace
}  // namespace psb::app
