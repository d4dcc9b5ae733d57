// The frame view: the marker pointing to a box off screen; the selected particle's panel with
// its edit prompt beside the messages.

#include <gtest/gtest.h>

#include <algorithm>

#include <particle_sandbox/presets.hpp>
#include <particle_sandbox/scene.hpp>

#include "session/camera.hpp"
#include "session/session.hpp"
#include "view/box_area.hpp"
#include "view/fixed_measure.hpp"
#include "view/frame_view.hpp"

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
    return Session(makeWorld(defaultScene()), SceneMeta{"default"}, o);
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

TEST(RecordingMark, InANarrowWindowItGoesBelowTheHudNotOverIt) {
    const Session s = sessionIn(420, 700, false);
    const test::FixedMeasure font;
    FrameStats stats;
    stats.video.recording = true;
    const FrameView f = buildFrame(s, stats, font, font, {310.0, 44.0});
    ASSERT_TRUE(f.recordingMark.has_value());
    const PixelRect& m = f.recordingMark->at;
    const PixelRect& hud = f.layout.hud;
    ASSERT_GT(hud.w, 0);
    const bool overlap =
        m.x < hud.x + hud.w && hud.x < m.x + m.w && m.y < hud.y + hud.h && hud.y < m.y + m.h;
    EXPECT_FALSE(overlap) << "mark " << m.x << "," << m.y << " " << m.w << "x" << m.h << ", HUD "
                          << hud.x << "," << hud.y << " " << hud.w << "x" << hud.h;
}

}  // namespace
}  // namespace psb::app
