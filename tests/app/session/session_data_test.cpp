// Data out through commands: each table exported to a CSV file and copied as tab-separated
// text, recording trajectories and collisions, and bad file names refused (session_data.cpp,
// data_recorder.hpp).

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "session/session_fixture.hpp"

namespace psb::app {
namespace {

using Rows = std::vector<std::vector<std::string>>;

Rows parse(const std::string& text, char separator) {
    Rows rows;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        std::vector<std::string> cells;
        std::istringstream fields(line);
        for (std::string cell; std::getline(fields, cell, separator);)
            cells.push_back(cell);
        if (!line.empty() && line.back() == separator) cells.emplace_back();
        rows.push_back(cells);
    }
    return rows;
}

std::string readFile(const std::filesystem::path& p) {
    std::ifstream in(p);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

constexpr double kFrame = 1.0 / 60.0;

/// Two balls heading for each other in a 10 m box without walls: 1 kg at 2 m/s from x = 3 and
/// 3 kg at -1 m/s from x = 6, radii 0.5 m; they meet at t = 2/3 s.
World twoBalls(StepMode mode) {
    WorldDef def;
    def.width = 10.0;
    def.height = 10.0;
    def.walls = false;
    World w(def, {.mode = mode});
    w.add({.position = Vec2(3.0, 5.0), .velocity = Vec2(2.0, 0.0), .mass = 1.0, .radius = 0.5});
    w.add({.position = Vec2(6.0, 5.0), .velocity = Vec2(-1.0, 0.0), .mass = 3.0, .radius = 0.5});
    return w;
}

class SessionData : public SessionFixture {
  protected:
    SessionData() : SessionFixture("psb-session-data", {}) {}

    [[nodiscard]] Session session() const {
        SessionOptions o = options();
        o.exportDir = dir_ / "out";
        std::filesystem::create_directories(o.exportDir);
        return Session(makeWorld(defaultScene()), SceneInfo{.name = "default", .dt = 1.0 / 60.0},
                       o);
    }

    /// Runs `frames` frames of 1/60 s.
    static void run(Session& s, int frames) {
        if (s.paused()) s.apply(cmd::TogglePause{});
        for (int k = 0; k < frames; ++k) {
            now_ += kFrame;
            s.update(kFrame, now_);
        }
        s.apply(cmd::TogglePause{});
    }

    static inline double now_ = 0.0;
};

TEST_F(SessionData, ExportValuesWritesEveryParticleIntoTheExportFolderAndNeverOverAFile) {
    Session s = session();
    s.apply(cmd::ExportTable{cmd::DataTable::Values, {}});
    const std::filesystem::path file = dir_ / "out" / "values.csv";
    ASSERT_TRUE(std::filesystem::exists(file)) << s.exportError();
    EXPECT_TRUE(said(s.takeNotices(), "Exported 6 rows of values to " + file.string()));
    EXPECT_EQ(s.lastExport(), file);
    const Rows rows = parse(readFile(file), ',');
    ASSERT_EQ(rows.size(), 7u);
    EXPECT_EQ(rows[0][0], "particle");
    EXPECT_EQ(rows[0][9], "radius_m");
    for (std::size_t k = 1; k < rows.size(); ++k) {
        const Particle p = s.world().get(s.world().ids()[k - 1]);
        EXPECT_EQ(std::stod(rows[k][1]), p.position.x()) << "full precision";
        EXPECT_EQ(std::stod(rows[k][3]), p.velocity.x()) << "signed";
    }
    const std::string first = readFile(file);
    s.apply(cmd::SpawnRandom{});
    s.apply(cmd::ExportTable{cmd::DataTable::Values, {}});
    EXPECT_EQ(s.lastExport(), dir_ / "out" / "values-2.csv");
    EXPECT_EQ(readFile(file), first) << "the first file is kept";
    EXPECT_EQ(parse(readFile(dir_ / "out" / "values-2.csv"), ',').size(), 8u);
}

TEST_F(SessionData, ATypedNameGetsCsvAndAnAbsolutePathIsKept) {
    Session s = session();
    s.apply(cmd::ExportTable{cmd::DataTable::Values, "lesson"});
    EXPECT_TRUE(std::filesystem::exists(dir_ / "out" / "lesson.csv"));
    s.apply(cmd::ExportTable{cmd::DataTable::Values, dir_ / "here.txt"});
    EXPECT_TRUE(std::filesystem::exists(dir_ / "here.txt"));
}

TEST_F(SessionData, AFailedExportSaysWhyAndLeavesNoFile) {
    Session s = session();
    s.apply(cmd::ExportTable{cmd::DataTable::Values, "no/such/folder/x.csv"});
    EXPECT_NE(s.exportError().find("Export failed"), std::string::npos);
    EXPECT_NE(s.exportError().find("does not exist"), std::string::npos) << s.exportError();
    EXPECT_TRUE(said(s.takeNotices(), "Export failed"));
    EXPECT_FALSE(std::filesystem::exists(dir_ / "out" / "no"));
    EXPECT_FALSE(s.lastExport());
}

TEST_F(SessionData, BadFileNamesAreRefusedAndNothingIsWritten) {
    Session s = session();
    const std::vector<std::string> bad = {
        ".csv", "sub/", "..", ".", "   ...", std::string("a\0b.csv", 7), ".hidden"};
    for (const std::string& name : bad) {
        s.apply(cmd::ExportTable{cmd::DataTable::Values, name});
        EXPECT_FALSE(s.exportError().empty()) << "'" << name << "' accepted";
        EXPECT_FALSE(s.lastExport()) << name;
    }
    EXPECT_TRUE(std::filesystem::is_empty(dir_ / "out"));
    // Any other bytes: written inside the export folder or refused, never a crash.
    std::mt19937 rng(11);
    const std::string alphabet = "ab.,-_ \t\"'%$:;*?<>|\\";
    for (int k = 0; k < 300; ++k) {
        std::string name;
        for (int n = 1 + static_cast<int>(rng() % 12); n > 0; --n)
            name += alphabet[rng() % alphabet.size()];
        s.apply(cmd::ExportTable{cmd::DataTable::Values, name});
        if (s.exportError().empty()) {
            ASSERT_TRUE(s.lastExport());
            EXPECT_EQ(s.lastExport()->parent_path(), dir_ / "out") << "'" << name << "'";
        }
    }
}

TEST_F(SessionData, CopyPutsTabSeparatedTextOnTheClipboardOnce) {
    Session s = session();
    EXPECT_FALSE(s.takeClipboardText());
    s.apply(cmd::CopyTable{cmd::DataTable::Values});
    const std::optional<std::string> text = s.takeClipboardText();
    ASSERT_TRUE(text);
    const Rows rows = parse(*text, '\t');
    ASSERT_EQ(rows.size(), 7u);
    EXPECT_EQ(rows[0][1], "x_m");
    EXPECT_EQ(text->find(','), std::string::npos);
    s.apply(cmd::ClipboardResult{true, {}});
    EXPECT_TRUE(said(s.takeNotices(), "Copied 6 rows of values to the clipboard"));
    EXPECT_FALSE(s.takeClipboardText()) << "taken once";
}

TEST_F(SessionData, CopiedIsSaidOnlyOnceTheClipboardHasTheText) {
    Session s = session();
    s.apply(cmd::CopyTable{cmd::DataTable::Values});
    ASSERT_TRUE(s.takeClipboardText());
    // A page's browser answers later: until it does, nothing claims the text was copied.
    for (const Notice& n : s.takeNotices())
        EXPECT_EQ(n.text.find("Copied"), std::string::npos) << n.text;
    s.apply(cmd::ClipboardResult{true, {}});
    EXPECT_TRUE(said(s.takeNotices(), "Copied 6 rows of values to the clipboard"));
    s.apply(cmd::ClipboardResult{true, {}});
    EXPECT_TRUE(s.takeNotices().empty()) << "one answer per copy";
}

TEST_F(SessionData, ARefusedCopySaysSoAndPointsToExport) {
    Session s = session();
    s.apply(cmd::CopyTable{cmd::DataTable::Values});
    ASSERT_TRUE(s.takeClipboardText());
    (void)s.takeNotices();
    s.apply(cmd::ClipboardResult{false, "Write permission denied."});
    const std::vector<Notice> notices = s.takeNotices();
    ASSERT_EQ(notices.size(), 1u);
    EXPECT_EQ(notices[0].level, Notice::Level::Warning);
    EXPECT_EQ(notices[0].text.find("Copied"), std::string::npos) << notices[0].text;
    EXPECT_NE(notices[0].text.find("Could not copy the values to the clipboard (Write permission "
                                   "denied.)"),
              std::string::npos)
        << notices[0].text;
    EXPECT_NE(notices[0].text.find("Export"), std::string::npos) << notices[0].text;
}

TEST_F(SessionData, TheTimeSeriesRunsFromTheStartWithCleanTimes) {
    Session s = session();
    s.apply(cmd::SetGravity{true});
    s.update(0.0, 0.0);  // the frame at t = 0
    run(s, 90);
    s.apply(cmd::ExportTable{cmd::DataTable::TimeSeries, "series"});
    const Rows rows = parse(readFile(dir_ / "out" / "series.csv"), ',');
    ASSERT_GE(rows.size(), 80u);
    EXPECT_EQ(rows[0][0], "time_s");
    // The rate is counted over the plots' window, and its column says how long that is.
    EXPECT_EQ(rows[0][7], "collision_rate_per_s_last_" + csv::number(s.rateWindow()) + "_s");
    EXPECT_EQ(rows[1][7], "") << "no rate at t = 0: no interval yet";
    ASSERT_FALSE(s.world().def().gravity.isZero()) << "the default scene has gravity";
    EXPECT_EQ(rows[0].back(), "mechanical_energy_J");
    EXPECT_EQ(rows[1][0], "0");
    EXPECT_EQ(rows.back()[0], "1.5") << "90 frames of 1/60 s: a clean 1.5, not 1.4999999999999998";
    for (std::size_t k = 2; k < rows.size(); ++k)
        EXPECT_LT(std::stod(rows[k - 1][0]), std::stod(rows[k][0]));
}

TEST_F(SessionData, NothingRecordedYetIsSaidNotWritten) {
    Session s = session();
    s.apply(cmd::ExportTable{cmd::DataTable::Trajectories, {}});
    EXPECT_NE(s.exportError().find("no trajectories yet"), std::string::npos);
    s.apply(cmd::CopyTable{cmd::DataTable::Collisions});
    EXPECT_FALSE(s.takeClipboardText());
    EXPECT_TRUE(std::filesystem::is_empty(dir_ / "out"));
}

TEST_F(SessionData, OnATouchScreenARecordingSaysThePanelsButtonStopsIt) {
    Session s = session();
    s.setWorld(twoBalls(StepMode::Discrete), SceneInfo{.name = "two balls", .dt = 1.0 / 60.0});
    s.apply(cmd::SetRecording{true, 1});
    EXPECT_TRUE(said(s.takeNotices(), "Recording all 2 particles every 1 step (X stops)"));
    s.apply(cmd::SetRecording{false});
    s.apply(cmd::SetTouch{true});
    s.apply(cmd::SetRecording{true, 1});
    EXPECT_TRUE(
        said(s.takeNotices(), "Recording all 2 particles every 1 step (Data: Stop recording)"));
}

TEST_F(SessionData, RecordingTwoBallsGivesTheirPathsAndTheTextbookCollisionInEveryMode) {
    for (const StepMode mode : {StepMode::Discrete, StepMode::Substep, StepMode::Exact}) {
        Session s = session();
        s.setWorld(twoBalls(mode), SceneInfo{.name = "two balls", .dt = 1.0 / 60.0});
        s.apply(cmd::SetRecording{true, 1});
        EXPECT_TRUE(s.data().recording());
        EXPECT_TRUE(said(s.takeNotices(), "Recording all 2 particles every 1 step"));
        run(s, 60);  // 1 s: the collision is at 2/3 s
        s.apply(cmd::SetRecording{false});
        EXPECT_FALSE(s.data().recording());
        // The world records nothing more for the recorder; a two-ball scene's collision card
        // listens all along (last_collision.hpp).
        EXPECT_EQ(s.world().recordingCollisions(),
                  LastCollision::listening(false, s.world().size()));

        s.apply(cmd::CopyTable{cmd::DataTable::Trajectories});
        const Rows path = parse(*s.takeClipboardText(), '\t');
        ASSERT_EQ(path.size(), 1u + 61u * 2u) << "t = 0 and each of 60 steps, two particles";
        EXPECT_EQ(path[1], (std::vector<std::string>{"0", "1", "3", "5", "2", "0"}));
        EXPECT_EQ(path.back()[0], "1");
        EXPECT_EQ(path.back()[1], "2");

        s.apply(cmd::ExportTable{cmd::DataTable::Collisions, "hits"});
        const std::filesystem::path file = *s.lastExport();
        const Rows hits = parse(readFile(file), ',');
        ASSERT_EQ(hits.size(), 2u) << readFile(file);
        const std::vector<std::string>& c = hits[1];
        EXPECT_EQ(c[2], "particle");
        // Whichever the stepper named first: the 1 kg ball goes from 2 to -2.5 m/s, the 3 kg
        // from -1 to 0.5 m/s, and the impulse on the first is its m dv.
        const bool oneFirst = c[1] == "1";
        const double m = oneFirst ? 1.0 : 3.0;
        EXPECT_NEAR(std::stod(c[4]), oneFirst ? 2.0 : -1.0, 1e-12);
        EXPECT_NEAR(std::stod(c[6]), oneFirst ? -2.5 : 0.5, 1e-12);
        EXPECT_NEAR(std::stod(c[8]), oneFirst ? -1.0 : 2.0, 1e-12);
        EXPECT_NEAR(std::stod(c[10]), oneFirst ? 0.5 : -2.5, 1e-12);
        EXPECT_NEAR(std::stod(c[12]), m * (std::stod(c[6]) - std::stod(c[4])), 1e-12);
        const double t = std::stod(c[0]);
        EXPECT_GE(t, 2.0 / 3.0 - 1e-9);
        EXPECT_LE(t, 2.0 / 3.0 + kFrame + 1e-9);
    }
}

TEST_F(SessionData, RecordingTheSelectedParticleEveryNSteps) {
    Session s = session();
    const ParticleId chosen = s.world().ids()[2];
    s.apply(cmd::Select{chosen});
    s.apply(cmd::SetRecording{true, 5});
    // Named by the number the app shows (the third particle is 3), not its storage slot.
    ASSERT_EQ(particleNumber(chosen), 3u);
    EXPECT_TRUE(said(s.takeNotices(), "Recording particle 3 every 5 steps"));
    run(s, 30);
    const std::vector<TrajectoryPoint>& samples = s.data().trajectory().samples();
    ASSERT_EQ(samples.size(), 7u) << "t = 0, then every 5th of 30 steps";
    for (const TrajectoryPoint& x : samples)
        EXPECT_EQ(x.id, chosen);
    for (const Collision& c : s.data().collisions())
        EXPECT_TRUE(c.involves(chosen));
}

TEST_F(SessionData, RecordingEverythingInACrowdNeedsASelection) {
    Session s = session();
    World crowd(WorldDef{});
    for (int k = 0; k < 150; ++k)
        crowd.add({.position = Vec2(10.0 + 4.0 * (k % 30), 10.0 + 4.0 * (k / 30)), .radius = 1.0});
    s.setWorld(std::move(crowd), SceneInfo{.name = "crowd", .dt = 1.0 / 60.0});
    s.apply(cmd::SetRecording{true, 1});
    EXPECT_FALSE(s.data().recording());
    EXPECT_TRUE(said(s.takeNotices(), "select a particle first"));
}

TEST_F(SessionData, GoingBackInTimeDropsWhatWasRecordedAfter) {
    Session s = session();
    s.apply(cmd::SetRecording{true, 1});
    run(s, 60);
    for (int k = 0; k < 20; ++k)
        s.apply(cmd::StepBack{});
    const double back = s.world().time();
    ASSERT_LT(back, 1.0 - 0.2);
    s.apply(cmd::TogglePause{});  // carries on from the frame shown
    now_ += kFrame;
    s.update(kFrame, now_);
    const std::vector<TrajectoryPoint>& samples = s.data().trajectory().samples();
    for (std::size_t k = 1; k < samples.size(); ++k)
        EXPECT_LE(samples[k - 1].time, samples[k].time) << "one history, in order";
    EXPECT_NEAR(samples.back().time, back + 1.0 / 60.0, 1e-9);
    for (const Collision& c : s.data().collisions())
        EXPECT_LE(c.time, samples.back().time + 1e-12);
    const std::vector<ObservablesSample>& run = s.data().run();
    for (std::size_t k = 1; k < run.size(); ++k)
        EXPECT_LT(run[k - 1].time, run[k].time);
}

TEST_F(SessionData, AStoppedRecordingIsWholeAfterSteppingBackAndRunningOn) {
    // The lesson: X records, Space runs, Space pauses, X stops, Shift+Left to the impact, Space
    // runs on: the exported trajectories had lost what was recorded after the frame gone back to.
    Session s = session();
    s.apply(cmd::SetRecording{true, 1});
    run(s, 60);
    s.apply(cmd::SetRecording{false});
    const std::string whole = s.tableText(cmd::DataTable::Trajectories, csv::Separator::Comma);
    const std::size_t samples = s.data().trajectory().samples().size();
    ASSERT_GT(samples, 60u);
    for (int k = 0; k < 20; ++k)
        s.apply(cmd::StepBack{});
    ASSERT_LT(s.world().time(), 1.0 - 0.2);
    run(s, 5);
    EXPECT_EQ(s.data().trajectory().samples().size(), samples);
    EXPECT_EQ(s.tableText(cmd::DataTable::Trajectories, csv::Separator::Comma), whole);
    const std::vector<ObservablesSample>& series = s.data().run();
    EXPECT_LT(series.back().time, 1.0 - 0.1) << "the plots' series follows the world back";
}

TEST_F(SessionData, RestartStopsRecordingAndKeepsWhatItRecordedToExport) {
    // A teacher's lesson: record, run, R to run again, then export: the recording was gone.
    Session s = session();
    s.apply(cmd::SetRecording{true, 1});
    run(s, 10);
    const std::size_t samples = s.data().trajectory().samples().size();
    ASSERT_GT(samples, 10u);
    (void)s.takeNotices();
    s.apply(cmd::Restart{});
    EXPECT_FALSE(s.data().recording());
    EXPECT_EQ(s.data().trajectory().samples().size(), samples);
    EXPECT_TRUE(said(s.takeNotices(), "Recording stopped: its "));
    EXPECT_LE(s.data().run().size(), 1u);  // the plots' run starts over
    run(s, 5);
    EXPECT_EQ(s.data().trajectory().samples().size(), samples);  // not recording, not dropped
    EXPECT_NE(s.tableText(cmd::DataTable::Trajectories, csv::Separator::Comma), "");
}

TEST_F(SessionData, APresetsKeyWhileRecordingSaysSoAndKeepsWhatWasRecorded) {
    // A trial at 200 %: a preset's number key while the Data section recorded stopped the
    // recording and dropped what it held, without a word. A scene opened (a preset, a new
    // scene) stops it, says so in the message line, and keeps it to export as it was recorded:
    // its heights counted from the floor of the box it was recorded in, not the new one's.
    for (const bool preset : {true, false}) {
        SessionOptions o = options();
        o.presets = testPresets();
        Session s(makeWorld(defaultScene()), SceneInfo{.name = "default", .dt = 1.0 / 60.0}, o);
        s.apply(cmd::SetRecording{true, 1});
        run(s, 10);
        const std::size_t samples = s.data().trajectory().samples().size();
        const std::size_t hits = s.data().collisions().size();
        ASSERT_GT(samples, 10u);
        const std::string trajectories =
            s.tableText(cmd::DataTable::Trajectories, csv::Separator::Comma);
        const std::string collisions =
            s.tableText(cmd::DataTable::Collisions, csv::Separator::Comma);
        const double height = s.world().def().height;
        (void)s.takeNotices();
        if (preset) {
            s.apply(cmd::OpenPreset{cmd::presetForDigit(2, true)});  // Shift+2: the ramp
        } else {
            s.apply(cmd::NewScene{10.0, 4.0, 0.0, true});
        }
        SCOPED_TRACE(preset ? "the ramp's key" : "a new scene");
        ASSERT_NE(s.world().def().height, height) << "the case: a box of another height";
        EXPECT_FALSE(s.data().recording());
        EXPECT_EQ(s.data().trajectory().samples().size(), samples);
        EXPECT_EQ(s.data().collisions().size(), hits);
        // Said last: the message line shows the last two lines, and a preset says two of its
        // own ("Opened ...", "Preset 12 of 14 ...") that pushed it off.
        const std::vector<Notice> notices = s.takeNotices();
        ASSERT_FALSE(notices.empty());
        EXPECT_EQ(notices.back().text.rfind(
                      "Recording stopped: its " + std::to_string(samples) + " samples", 0),
                  0u)
            << notices.back().text;
        EXPECT_EQ(s.tableText(cmd::DataTable::Trajectories, csv::Separator::Comma), trajectories);
        EXPECT_EQ(s.tableText(cmd::DataTable::Collisions, csv::Separator::Comma), collisions);
        EXPECT_LE(s.data().run().size(), 1u) << "the plots' run starts over";
        // Not recording, nothing said: a scene opened says nothing of a recording.
        s.apply(cmd::OpenPreset{0});
        for (const Notice& n : s.takeNotices())
            EXPECT_EQ(n.text.find("Recording"), std::string::npos) << n.text;
        EXPECT_EQ(s.data().trajectory().samples().size(), samples) << "still there to export";
    }
}

TEST_F(SessionData, TheTimeSeriesFirstRowIsTheSetUpAsPlayStartsIt) {
    // Particles placed while paused at t = 0: the t = 0 row is the box as it starts, not as it
    // was before they were placed.
    Session s = session();
    s.apply(cmd::NewScene{10.0, 4.0, 0.0, true});
    s.update(0.0, 0.0);
    s.apply(cmd::SpawnRandom{});
    s.apply(cmd::SpawnRandom{});
    s.update(0.0, 0.1);
    ASSERT_EQ(s.world().size(), 2u);
    ASSERT_FALSE(s.data().run().empty());
    EXPECT_EQ(s.data().run().front().time, 0.0);
    EXPECT_GT(s.data().run().front().kineticEnergy, 0.0);
    EXPECT_NEAR(s.data().run().front().kineticEnergy, s.observables().kineticEnergy, 1e-12);
}

TEST_F(SessionData, ToggleVideoIsHandedToTheAppOnceWithTheLastSettings) {
    Session s = session();
    EXPECT_FALSE(s.takeVideoToggle().has_value());
    EXPECT_EQ(s.videoSettings(), VideoSettings{});  // MP4 of the box at first
    s.apply(cmd::ToggleVideo{});
    auto toggle = s.takeVideoToggle();
    ASSERT_TRUE(toggle.has_value());
    EXPECT_EQ(toggle->format, VideoFormat::Mp4);
    EXPECT_FALSE(toggle->withPanel);
    EXPECT_FALSE(s.takeVideoToggle().has_value());  // once

    // The panel's choice is kept: Ctrl+R (no settings of its own) records with it.
    s.apply(cmd::SetVideoSettings{{VideoFormat::Gif, true}});
    EXPECT_FALSE(s.takeVideoToggle().has_value());  // a choice records nothing
    s.apply(cmd::ToggleVideo{});
    toggle = s.takeVideoToggle();
    ASSERT_TRUE(toggle.has_value());
    EXPECT_EQ(*toggle, (VideoSettings{VideoFormat::Gif, true}));
    // --record names its format, which becomes the choice.
    s.apply(cmd::ToggleVideo{VideoSettings{VideoFormat::WebM, false}});
    EXPECT_EQ(s.takeVideoToggle()->format, VideoFormat::WebM);
    EXPECT_EQ(s.videoSettings().format, VideoFormat::WebM);
}

TEST_F(SessionData, RecordingIsNotAnEditAndLeavesTheSceneSaved) {
    Session s = session();
    const bool dirty = s.unsavedChanges();
    s.apply(cmd::SetVideoSettings{{VideoFormat::WebM, false}});
    s.apply(cmd::ToggleVideo{});
    EXPECT_EQ(s.unsavedChanges(), dirty);
    EXPECT_FALSE(s.canUndo());
}

TEST(VideoSettings, FormatsByNameAndExtension) {
    EXPECT_EQ(parseVideoFormat("mp4"), VideoFormat::Mp4);
    EXPECT_EQ(parseVideoFormat("WebM"), VideoFormat::WebM);
    EXPECT_EQ(parseVideoFormat("GIF"), VideoFormat::Gif);
    EXPECT_FALSE(parseVideoFormat("avi").has_value());
    EXPECT_FALSE(parseVideoFormat("").has_value());
    EXPECT_STREQ(extension(VideoFormat::Mp4), ".mp4");
    EXPECT_STREQ(extension(VideoFormat::WebM), ".webm");
    EXPECT_STREQ(extension(VideoFormat::Gif), ".gif");
}

}  // namespace
}  // namespace psb::app
