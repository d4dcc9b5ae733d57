// The session as a document program: Save writes the file the scene belongs to, or asks for a
// name (presets, new and built-in scenes); an undo to another scene brings its file back;
// Restart goes back to the set-up Play last started, Revert to the file; the title and
// description the user writes are saved; a new scene is an empty box from a dialog.

#include <gtest/gtest.h>

#include <filesystem>

#include <particle_sandbox/presets.hpp>
#include <particle_sandbox/scene.hpp>

#include "core/test_util.hpp"
#include "session/keys.hpp"
#include "session/scene_io.hpp"
#include "session/session.hpp"
#include "session/session_fixture.hpp"
#include "session/test_assets.hpp"

namespace psb::app {
namespace {

namespace fs = std::filesystem;

class SessionDocument : public SessionFixture {
  protected:
    SessionDocument() : SessionFixture("psb-session-document", TestWindow{.presets = true}) {}

    /// A scene file of `n` default-scene particles in the test's folder.
    [[nodiscard]] fs::path sceneFileOf(std::size_t n, const char* name = "lesson.json") const {
        Scene s = defaultScene();
        s.particles.resize(n);
        saveScene(s, dir_ / name);
        return dir_ / name;
    }
};

TEST_F(SessionDocument, SaveWritesAFileTheUserOpenedAndAsksForAPresetsName) {
    Session s = session();
    const fs::path file = sceneFileOf(2);
    s.apply(cmd::OpenFile{file});
    EXPECT_TRUE(s.sceneFile().writable);
    s.apply(cmd::SpawnRandom{});
    s.apply(cmd::Save{});
    EXPECT_FALSE(s.dialog().open());
    EXPECT_EQ(loadScene(file).particles.size(), 3u);
    EXPECT_FALSE(s.unsavedChanges());

    // A preset is never written: Save asks, proposing --save-to.
    s.apply(cmd::OpenPreset{0});
    EXPECT_FALSE(s.sceneFile().writable);
    ASSERT_TRUE(s.sceneFile().path);
    s.apply(cmd::SpawnRandom{});
    s.apply(cmd::Save{});
    ASSERT_EQ(s.dialog().kind, Dialog::Kind::SaveAs);
    EXPECT_EQ(s.dialog().proposal.filename(), "save.json");
    const auto before = fs::last_write_time(s.presets()[0].file);
    s.apply(cmd::SaveAs{s.dialog().proposal});
    EXPECT_EQ(fs::last_write_time(s.presets()[0].file), before);
    EXPECT_EQ(*s.sceneFile().path, fs::absolute(dir_ / "save.json").lexically_normal());
    EXPECT_TRUE(s.sceneFile().writable);
}

TEST_F(SessionDocument, WithoutSaveToSaveAsProposesTheScenesNameInTheSaveFolder) {
    SessionOptions o = options();
    o.saveTo.reset();
    o.saveFolder = dir_ / "pictures";
    fs::create_directories(o.saveFolder);
    Session s(makeWorld(defaultScene()), SceneInfo{.name = "Newton's cradle", .dt = 1.0 / 60.0}, o);
    s.apply(cmd::AskSaveAs{});
    EXPECT_EQ(s.dialog().proposal,
              fs::absolute(dir_ / "pictures" / "newton-s-cradle.json").lexically_normal());
    // A bare name typed in the dialog goes in the folder it shows.
    s.apply(cmd::SaveAs{"mine"});
    EXPECT_TRUE(fs::exists(dir_ / "pictures" / "mine.json"));
    EXPECT_EQ(sceneFileName("  "), "scene.json");
    EXPECT_EQ(sceneFileName("Gas: 200 discs!"), "gas-200-discs.json");
}

TEST_F(SessionDocument, AnUndoToAnotherSceneBringsItsFileBack) {
    Session s = session();
    const fs::path file = sceneFileOf(2);
    s.apply(cmd::OpenFile{file});
    s.apply(cmd::OpenPreset{0});
    ASSERT_FALSE(s.sceneFile().writable);
    s.apply(cmd::Undo{});
    EXPECT_EQ(s.world().size(), 2u);
    EXPECT_TRUE(s.sceneFile().writable);
    EXPECT_EQ(*s.sceneFile().path, fs::absolute(file).lexically_normal());
    // Within one scene a save stays where it went: undoing an edit made before it keeps the
    // file the user named.
    Session t = session();
    t.apply(cmd::SpawnRandom{});
    t.apply(cmd::SaveAs{dir_ / "named.json"});
    t.apply(cmd::Undo{});
    EXPECT_TRUE(t.sceneFile().writable);
    t.apply(cmd::Save{});
    EXPECT_FALSE(t.dialog().open());
    EXPECT_EQ(loadScene(dir_ / "named.json").particles.size(), t.world().size());
}

TEST_F(SessionDocument, RestartGoesBackToTheSetUpPlayLastStartedAfterAnEdit) {
    Session s = session();
    const std::uint64_t loaded = test::stateHash(s.world());
    s.apply(cmd::TogglePause{});  // Play with no edit: the set-up is the scene as loaded
    s.update(0.5, 1.0);
    s.apply(cmd::TogglePause{});
    s.apply(cmd::Restart{});
    EXPECT_EQ(test::stateHash(s.world()), loaded);

    // Set up: a particle more, then Play.
    s.apply(cmd::SpawnRandom{});
    const std::uint64_t setup = test::stateHash(s.world());
    s.apply(cmd::TogglePause{});
    EXPECT_TRUE(said(s.takeNotices(), "R restarts from this set-up"));
    s.update(0.5, 2.0);
    s.apply(cmd::TogglePause{});
    s.apply(cmd::TogglePause{});  // pause and play again without an edit: the same set-up
    s.update(0.5, 3.0);
    ASSERT_NE(test::stateHash(s.world()), setup);
    s.apply(cmd::Restart{});
    EXPECT_EQ(test::stateHash(s.world()), setup);
    EXPECT_EQ(s.world().size(), 7u);
    EXPECT_TRUE(s.unsavedChanges());  // the spawned particle is still not saved
    // Restart is undoable.
    s.apply(cmd::Undo{});
    EXPECT_NE(test::stateHash(s.world()), setup);
}

TEST_F(SessionDocument, ReplacingUnsavedChangesSaysCtrlZBringsThemBack) {
    // A new user's stray digit opened a preset over their unsaved lesson, without a word.
    Session s = session();
    const fs::path file = sceneFileOf(3);
    s.apply(cmd::OpenFile{file});
    (void)s.takeNotices();
    s.apply(cmd::OpenPreset{1});  // nothing unsaved: nothing to say
    EXPECT_FALSE(said(s.takeNotices(), "unsaved changes"));
    s.apply(cmd::SpawnRandom{});
    ASSERT_TRUE(s.unsavedChanges());
    const std::size_t n = s.world().size();
    const std::string name = s.meta().name;
    s.apply(cmd::OpenPreset{0});
    EXPECT_TRUE(said(s.takeNotices(),
                     "The unsaved changes to " + name + " were replaced: Ctrl+Z brings them back"));
    s.apply(cmd::Undo{});
    EXPECT_EQ(s.world().size(), n);
    EXPECT_TRUE(s.unsavedChanges());
    s.apply(cmd::NewScene{5.0, 5.0, 0.0, true});
    EXPECT_TRUE(said(s.takeNotices(), "were replaced: Ctrl+Z brings them back"));
}

TEST_F(SessionDocument, ReplacingUnsavedChangesOnATouchScreenNamesThePanelsUndo) {
    Session s = session();
    s.apply(cmd::SetTouch{true});
    s.apply(cmd::SpawnRandom{});
    ASSERT_TRUE(s.unsavedChanges());
    (void)s.takeNotices();
    s.apply(cmd::OpenPreset{0});
    const std::vector<Notice> n = s.takeNotices();
    EXPECT_TRUE(said(n, "were replaced: Time: Undo brings them back"));
    EXPECT_FALSE(said(n, "Ctrl+Z"));
}

TEST_F(SessionDocument, WhereEscDoesNotQuitItOnlyClosesWhatIsOpen) {
    // A web page: nothing to quit to.
    SessionOptions o = options();
    o.inPage = true;
    Session s(makeWorld(defaultScene()), SceneInfo{.name = "default", .dt = 1.0 / 60.0}, o);
    s.apply(cmd::ToggleHelp{});
    s.apply(cmd::Back{});
    EXPECT_FALSE(s.helpShown());
    s.apply(cmd::Back{});
    EXPECT_TRUE(s.running());
    EXPECT_FALSE(s.dialog().open());
    EXPECT_TRUE(said(s.takeNotices(), "nothing is open"));
    s.apply(cmd::SpawnRandom{});
    s.apply(cmd::Back{});  // unsaved changes: still no quit dialog
    EXPECT_TRUE(s.running());
    EXPECT_FALSE(s.dialog().open());
    // A desktop window's Esc asks whether to quit.
    Session d = session();
    d.apply(cmd::Back{});
    EXPECT_TRUE(d.running());
    EXPECT_EQ(d.dialog().kind, Dialog::Kind::Quit);
}

// A web page hands what it saves to the browser as a download: the dialog and the messages
// speak of the browser's downloads and the file's name, never the page's own folder, and a
// name saved before is not "replaced" (the browser keeps both).
TEST_F(SessionDocument, InAPageSavingIsADownloadNamedByItsFileAlone) {
    SessionOptions o = options();
    o.inPage = true;
    o.saveTo.reset();
    o.saveFolder = dir_;
    Session s(makeWorld(defaultScene()), SceneInfo{.name = "default", .dt = 1.0 / 60.0}, o);
    s.apply(cmd::Save{});
    ASSERT_EQ(s.dialog().kind, Dialog::Kind::SaveAs);
    EXPECT_TRUE(s.dialog().download);
    auto notices = s.takeNotices();
    EXPECT_TRUE(said(notices, "the browser downloads it"));
    EXPECT_FALSE(said(notices, dir_.string()));
    s.apply(cmd::SaveAs{"lesson"});
    EXPECT_FALSE(s.dialog().open());
    notices = s.takeNotices();
    EXPECT_TRUE(said(notices, "as lesson.json"));
    EXPECT_FALSE(said(notices, dir_.string()));
    // The same name again: saved, not a Replace question.
    s.apply(cmd::AskSaveAs{});
    s.apply(cmd::SaveAs{"lesson"});
    EXPECT_FALSE(s.dialog().open());
    EXPECT_TRUE(said(s.takeNotices(), "as lesson.json"));
    // On the desktop the folder is named in full, and an existing name is asked about.
    SessionOptions w = options();
    w.saveTo.reset();
    w.saveFolder = dir_;
    Session d(makeWorld(defaultScene()), SceneInfo{.name = "default", .dt = 1.0 / 60.0}, w);
    d.apply(cmd::AskSaveAs{});
    EXPECT_FALSE(d.dialog().download);
    EXPECT_TRUE(said(d.takeNotices(), fs::absolute(dir_).lexically_normal().string()));
    d.apply(cmd::SaveAs{"lesson"});
    EXPECT_EQ(d.dialog().kind, Dialog::Kind::SaveAs);
    EXPECT_FALSE(d.dialog().replace.empty());
}

TEST_F(SessionDocument, RevertReadsTheFileAgainAndUndoBringsTheChangesBack) {
    Session s = session();
    const fs::path file = sceneFileOf(3);
    s.apply(cmd::OpenFile{file});
    s.apply(cmd::SpawnRandom{});
    s.apply(cmd::SpawnRandom{});
    s.apply(cmd::Revert{});
    EXPECT_EQ(s.world().size(), 3u);
    EXPECT_FALSE(s.unsavedChanges());
    EXPECT_TRUE(said(s.takeNotices(), "Reverted to lesson.json"));
    s.apply(cmd::Undo{});
    EXPECT_EQ(s.world().size(), 5u);
    // A scene with no file goes back to how it was made.
    Session t = session();
    const std::size_t n = t.world().size();
    t.apply(cmd::SpawnRandom{});
    t.apply(cmd::Revert{});
    EXPECT_EQ(t.world().size(), n);
    EXPECT_FALSE(t.unsavedChanges());
}

TEST_F(SessionDocument, TheTitleAndDescriptionTheUserWritesAreSavedAndUndoable) {
    Session s = session();
    s.apply(cmd::SetSceneText{"Momentum lesson", "Two carts; e = 0.7 after the change."});
    EXPECT_EQ(s.meta().name, "Momentum lesson");
    EXPECT_TRUE(s.unsavedChanges());
    s.apply(cmd::SaveAs{dir_ / "momentum.json"});
    const Scene saved = loadScene(dir_ / "momentum.json");
    EXPECT_EQ(saved.name, "Momentum lesson");
    EXPECT_EQ(saved.description, "Two carts; e = 0.7 after the change.");
    s.apply(cmd::Undo{});
    EXPECT_EQ(s.meta().name, "default");
}

TEST_F(SessionDocument, ANewSceneIsAnEmptyBoxFromTheDialogAndBadValuesAreRefused) {
    Session s = session();
    s.apply(keys::restitution(s, -1));
    s.apply(cmd::AskNewScene{});
    ASSERT_EQ(s.dialog().kind, Dialog::Kind::NewScene);
    EXPECT_EQ(s.dialog().newScene.width, s.world().def().width);
    const std::size_t n = s.world().size();
    for (const cmd::NewScene bad :
         {cmd::NewScene{0.0, 5.0, 0.0, true}, cmd::NewScene{5.0, NAN, 0.0, true},
          cmd::NewScene{5.0, 5.0, -9.81, true}, cmd::NewScene{5.0, 5.0, INFINITY, true},
          cmd::NewScene{1e300, 5.0, 0.0, true}}) {
        s.apply(bad);
        EXPECT_EQ(s.world().size(), n);
        EXPECT_EQ(s.dialog().kind, Dialog::Kind::NewScene);
        EXPECT_FALSE(s.dialog().error.empty());
    }
    s.apply(cmd::NewScene{4.0, 3.0, 9.81, false});
    EXPECT_FALSE(s.dialog().open());
    EXPECT_EQ(s.world().size(), 0u);
    EXPECT_EQ(s.world().def().width, 4.0);
    EXPECT_EQ(s.world().def().height, 3.0);
    EXPECT_EQ(s.world().def().gravity, Vec2(0.0, 9.81));
    EXPECT_FALSE(s.world().def().walls);
    EXPECT_EQ(s.world().def().restitution, 0.95);  // the laws carry over
    EXPECT_TRUE(s.paused());
    EXPECT_FALSE(s.sceneFile().path);
    EXPECT_FALSE(s.unsavedChanges());
    // Undo brings the old scene back.
    s.apply(cmd::Undo{});
    EXPECT_EQ(s.world().size(), n);
}

TEST_F(SessionDocument, ADialogHoldsEveryCommandButItsAnswers) {
    Session s = session();
    s.apply(cmd::AskSaveAs{});
    const std::size_t n = s.world().size();
    s.apply(cmd::SpawnRandom{});
    s.apply(cmd::OpenPreset{1});
    s.apply(cmd::SetRestitution{0.5});
    EXPECT_EQ(s.world().size(), n);
    EXPECT_EQ(s.world().def().restitution, 1.0);
    EXPECT_EQ(s.dialog().kind, Dialog::Kind::SaveAs);
    s.apply(cmd::CloseDialog{});
    EXPECT_FALSE(s.dialog().open());
    s.apply(cmd::SpawnRandom{});
    EXPECT_EQ(s.world().size(), n + 1);
}

}  // namespace
}  // namespace psb::app
