#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "view/hud.hpp"

namespace psb::app {
namespace {

TEST(Hud, TitleShowsTheCountAndPaused) {
    EXPECT_EQ(windowTitle(6, false), "Particle Sandbox - 6 particles");
    EXPECT_EQ(windowTitle(1, true), "Particle Sandbox - 1 particle - PAUSED");
    EXPECT_EQ(windowTitle(2, false, "Gas"), "Particle Sandbox - 2 particles - Gas");
    // Unsaved changes: marked first (where a cut-off title keeps it) and said in words.
    EXPECT_EQ(windowTitle(2, true, "Gas", true),
              "* Particle Sandbox - 2 particles - PAUSED - Gas (unsaved changes)");
}

TEST(Hud, LinesShowTimeCountEnergyAndMomentumInHumanUnits) {
    HudData d;
    d.simTime = 12.345;
    d.particles = 42;
    d.kineticEnergy = 4.039e6;
    d.momentum = Vec2(3.0, -40390.0);
    d.spawnMass = 10.0;
    d.spawnRadius = 0.3;
    d.paused = true;
    const auto lines = hudLines(d);
    const auto has = [&](const std::string& s) {
        return std::any_of(lines.begin(), lines.end(),
                           [&](const std::string& l) { return l.find(s) != std::string::npos; });
    };
    EXPECT_TRUE(has("Time 12.3 s"));
    EXPECT_TRUE(has("PAUSED"));
    EXPECT_TRUE(has("42 particles"));
    EXPECT_TRUE(has("Kinetic energy 4.04 MJ"));
    EXPECT_TRUE(has("momentum (3.00, -40 400) kg m/s"));
    EXPECT_TRUE(has("New: 10.0 kg, 0.300 m"));
    EXPECT_TRUE(has("H: help"));
    // No engine jargon and no exponent notation on the box.
    for (const char* jargon : {"FPS", "thread", "all-pairs", "Overlap max", "drift", "e+", "e-0"}) {
        EXPECT_FALSE(has(jargon)) << jargon;
    }
}

TEST(Hud, OnATouchScreenTheRecordingAndTheFoldedChartsNameThePanelsButtons) {
    HudData d;
    d.recording = true;
    EXPECT_NE(hudLines(d)[0].find("| REC (X stops)"), std::string::npos) << hudLines(d)[0];
    d.touch = true;
    EXPECT_NE(hudLines(d)[0].find("| REC (Data: Stop recording)"), std::string::npos)
        << hudLines(d)[0];
    EXPECT_EQ(foldedChartsNote(true, true),
              "Charts folded away: no room beside the box (<< folds the controls)");
    EXPECT_EQ(foldedChartsNote(true),
              "Charts folded away: no room beside the box (C folds the "
              "controls)");
    EXPECT_EQ(foldedChartsNote(false, true), foldedChartsNote(false));
}

TEST(Hud, ATimeSpeedTheStepsCannotReachShowsTheSpeedReached) {
    HudData d;
    d.timeScale = 8.0;
    d.reachedTimeScale = 3.1;
    EXPECT_NE(hudLines(d)[0].find("x3.1 of x8 asked"), std::string::npos) << hudLines(d)[0];
    d.reachedTimeScale = 7.9;  // within 5 %: what was asked is what is seen
    EXPECT_NE(hudLines(d)[0].find("x8 |"), std::string::npos) << hudLines(d)[0];
    EXPECT_EQ(hudLines(d)[0].find("asked"), std::string::npos);
}

TEST(Hud, TheArrowScaleIsShownWhileArrowsAreOn) {
    HudData d;
    d.arrowSeconds = 0.25;
    EXPECT_NE(hudLines(d).back().find("arrow: 0.25 s of motion"), std::string::npos);
    d.arrowSeconds = 0.0;
    EXPECT_EQ(hudLines(d).back().find("arrow"), std::string::npos);
}

TEST(Hud, HelpListsEveryControl) {
    const auto lines = helpLines();
    EXPECT_EQ(lines.size(), controls().size() + 2);
    for (const char* key :
         {"M", "S", "A", "Space", "Wheel", "Ctrl+S / Ctrl+Shift+S", "Ctrl+N", "Esc", "H"}) {
        EXPECT_TRUE(std::any_of(controls().begin(), controls().end(), [&](const auto& c) {
            return c.first == key;
        })) << key;
    }
}

TEST(Hud, TheHelpNamesEachControlByItsSectionAndItsOwnWords) {
    // The help said Ctrl+R was under "(Data: Video)", but Video is a section of its own, and
    // Ctrl+T under "(Show: Theme)", where the box reads "Light".
    const std::vector<std::string> sections = {
        "Time",          "Scene",    "Physics", "Show",  "Last collision",
        "Tools",         "Readouts", "Data",    "Video", "Selected particle",
        "All particles", "Engine"};
    for (const auto& [keys, what] : controls()) {
        const std::size_t open = what.rfind('('), colon = what.find(':', open);
        if (open == std::string::npos || colon == std::string::npos || keys == "Enter") continue;
        const std::string section = what.substr(open + 1, colon - open - 1);
        // Not a section: "(panel: Tools)", the edit prompt's "(Tab: next field...)", "(Delete
        // removes it; Select tool: drag)".
        if (section == "Tab" || section == "panel" || section.find(';') != std::string::npos)
            continue;
        EXPECT_NE(std::find(sections.begin(), sections.end(), section), sections.end())
            << keys << ": " << what;
    }
    const auto line = [](const std::string& keys) {
        for (const auto& [k, what] : controls())
            if (k == keys) return what;
        return std::string();
    };
    EXPECT_NE(line("Ctrl+R").find("(Video: Record video)"), std::string::npos) << line("Ctrl+R");
    EXPECT_NE(line("Ctrl+T").find("(Show: Light)"), std::string::npos) << line("Ctrl+T");
}

bool anyContains(const std::vector<std::string>& lines, const std::string& s) {
    return std::any_of(lines.begin(), lines.end(),
                       [&](const std::string& l) { return l.find(s) != std::string::npos; });
}

// The page's help lists the page's keys: none that the browser keeps (Ctrl+N, Ctrl+T, its zoom's
// Ctrl+plus, minus and 0), whose actions it names by their panel controls; no video (Ctrl+R:
// desktop-only), and Esc that closes things but never quits.
TEST(Hud, ThePagesHelpListsOnlyWhatWorksInAPage) {
    const auto window = helpLines(false);
    const auto page = helpLines(true);
    EXPECT_TRUE(anyContains(window, "Ctrl+N"));
    EXPECT_TRUE(anyContains(window, "Ctrl+R"));
    EXPECT_TRUE(anyContains(window, "quit"));
    for (const char* kept : {"Ctrl+N", "Ctrl+T", "Ctrl+plus"}) {
        EXPECT_TRUE(anyContains(window, kept)) << kept;
        EXPECT_FALSE(anyContains(page, kept)) << kept;
    }
    EXPECT_FALSE(anyContains(page, "Ctrl+0"));
    EXPECT_TRUE(anyContains(page, "Show: UI scale, Auto"));
    EXPECT_TRUE(anyContains(page, "Show: Light"));
    EXPECT_FALSE(anyContains(page, "Ctrl+R"));
    EXPECT_FALSE(anyContains(page, "quit"));
    EXPECT_TRUE(anyContains(page, "New scene..."));
    EXPECT_TRUE(anyContains(page, "close a dialog, the help or the edit prompt"));
    EXPECT_EQ(page.size(), window.size() - 1);
}

TEST(Hud, ProfileListsEveryStageAndTheFrameTimes) {
    ProfileData d;
    for (const char* stage :
         {"reorder", "gravity", "move", "find pairs", "resolve", "separate", "walls"})
        d.profile.stage(stage);
    d.profile.stage("gravity") = 0.125;
    d.profile.stage("find pairs") = 1.5;
    d.profile.stage("reorder") = 0.25;
    d.profile.total = 3.0;
    d.profile.pairs = 1234;
    d.frameStepMs = 6.0;
    d.frameDrawMs = 4.5;
    const auto lines = profileLines(d);
    for (const char* stage : {"gravity", "move", "find pairs", "resolve", "separate", "walls",
                              "reorder", "total", "frame: step", "frame: draw"}) {
        EXPECT_TRUE(anyContains(lines, stage)) << stage;
    }
    EXPECT_TRUE(anyContains(lines, "1.500"));
    EXPECT_TRUE(anyContains(lines, "1234"));
    EXPECT_TRUE(anyContains(lines, "4.500"));
}

TEST(Hud, ProfileInExactModeNamesTheEventStages) {
    ProfileData d;
    d.mode = StepMode::Exact;
    d.eventsPerStep = 420;
    for (const char* stage : {"rebuild", "events", "sync"})
        d.profile.stage(stage);
    const auto lines = profileLines(d);
    EXPECT_TRUE(anyContains(lines, "rebuild"));
    EXPECT_TRUE(anyContains(lines, "events"));
    EXPECT_TRUE(anyContains(lines, "sync"));
    EXPECT_TRUE(anyContains(lines, "events per step"));
    EXPECT_TRUE(anyContains(lines, "420"));
    EXPECT_FALSE(anyContains(lines, "separate"));
}

TEST(Hud, HelpListsTheModeAndProfileKeys) {
    for (const char* key : {"T", "O / F3"}) {
        EXPECT_TRUE(std::any_of(controls().begin(), controls().end(), [&](const auto& c) {
            return c.first == key;
        })) << key;
    }
}

TEST(Hud, ADeepOverlapIsShownOnTheBoxAndNoneIsNotMentioned) {
    HudData d;
    for (const std::string& line : hudLines(d))
        EXPECT_EQ(line.find("overlap"), std::string::npos);
    d.overlap = 0.453;
    const auto lines = hudLines(d);
    EXPECT_EQ(lines.back(), "Particles overlap by up to 453 mm (real ones would not)");
}

TEST(Hud, MassesThatDifferAreKeyedToTheirShadeAndEqualOnesAreNotMentioned) {
    HudData d;
    for (const std::string& line : hudLines(d))
        EXPECT_EQ(line.find("Shade"), std::string::npos);
    d.lightestMass = 1.0;
    d.heaviestMass = 3.0;
    const auto lines = hudLines(d);
    EXPECT_EQ(lines.back(), "Darker discs are heavier (1.00 to 3.00 kg)");
}

}  // namespace
}  // namespace psb::app
