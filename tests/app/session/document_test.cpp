// The document: a new scene replaces the world and the scene as loaded, the set-up Restart
// returns to, the file a scene belongs to (and whether Save may write it), the recent files, and
// a save that names the file it wrote, binds the scene to it and clears the unsaved mark.

#include <sys/stat.h>
#include <unistd.h>

#include <fstream>

#include <gtest/gtest.h>

#include <particle_sandbox/presets.hpp>
#include <particle_sandbox/scene.hpp>

#include "session/document.hpp"
#include "temp_dir_test.hpp"

namespace psb::app {
namespace {

class DocumentTest : public TempDirTest {
  protected:
    DocumentTest() : TempDirTest("psb-document") {}
};

TEST_F(DocumentTest, ANewSceneIsTheSceneAsLoadedAndNothingIsUnsaved) {
    Document d(makeWorld(defaultScene()), SceneInfo{.name = "first", .dt = 1.0 / 60.0},
               SceneFile{});
    const std::uint64_t g = d.generation;
    d.edited();
    World w;
    d.replace(w, SceneInfo{.name = "second", .description = "described", .dt = 1.0 / 60.0},
              SceneFile{dir_ / "x.json", true});
    EXPECT_NE(d.generation, g);
    EXPECT_FALSE(d.dirty);
    EXPECT_EQ(d.world.size(), 0u);
    EXPECT_EQ(d.loaded->size(), 0u);
    EXPECT_EQ(d.meta.name, "second");
    EXPECT_EQ(d.meta.description, "described");
    EXPECT_EQ(d.setup, d.loaded);
    EXPECT_FALSE(d.editedSinceSetup);
    EXPECT_EQ(d.file.path, dir_ / "x.json");
}

TEST_F(DocumentTest, PlayAfterAnEditMakesTheWorldTheSetUpAndPlayWithoutOneDoesNot) {
    Document d(makeWorld(defaultScene()), SceneInfo{.name = "s", .dt = 1.0 / 60.0}, SceneFile{});
    EXPECT_FALSE(d.play());  // nothing edited: the set-up is the scene as loaded
    EXPECT_EQ(d.setup, d.loaded);
    d.world.step(0.1);
    d.edited();
    EXPECT_TRUE(d.dirty);
    EXPECT_TRUE(d.play());
    EXPECT_NE(d.setup, d.loaded);
    EXPECT_EQ(d.setup->time(), d.world.time());
    d.world.step(0.1);
    EXPECT_FALSE(d.play());  // a pause and a play without an edit keep the set-up
    EXPECT_LT(d.setup->time(), d.world.time());
}

TEST_F(DocumentTest, AFileTheUserMayWriteIsWritableAPresetOrAReadOnlyFileIsNot) {
    const auto touch = [](const std::filesystem::path& p) { std::ofstream(p) << "{}"; };
    touch(dir_ / "mine.json");
    touch(dir_ / "preset.json");
    touch(dir_ / "locked.json");
    ::chmod((dir_ / "locked.json").c_str(), 0444);
    EXPECT_FALSE(sceneFile(std::nullopt).path);
    const SceneFile mine = sceneFile(dir_ / "mine.json", {dir_ / "preset.json"});
    EXPECT_TRUE(mine.writable);
    EXPECT_TRUE(mine.path->is_absolute());
    EXPECT_FALSE(sceneFile(dir_ / "preset.json", {dir_ / "preset.json"}).writable);
    // root may write any file; everyone else is refused a read-only one.
    if (::geteuid() != 0) {
        EXPECT_FALSE(sceneFile(dir_ / "locked.json").writable);
    }
    EXPECT_FALSE(sceneFile(dir_ / "missing-folder" / "x.json").writable);
}

TEST_F(DocumentTest, SceneMetaTakesTheFilesStemWhenTheSceneHasNoName) {
    Scene s = defaultScene();
    s.name.clear();
    s.trails = {0};
    s.dt = 1.0 / 240.0;
    const SceneInfo m = sceneInfo(s, std::filesystem::path("lessons/cradle.json"));
    EXPECT_EQ(m.name, "cradle");
    EXPECT_EQ(m.trails, std::vector<std::size_t>{0});
    EXPECT_EQ(m.dt, 1.0 / 240.0);  // the scene's frame length, what the session steps by
    EXPECT_EQ(sceneInfo(defaultScene(), std::nullopt).name, defaultScene().name);
}

TEST_F(DocumentTest, RecentFilesAreNewestFirstOnceEachAndAtMostFive) {
    Document d(World{}, SceneInfo{.name = "x", .dt = 1.0 / 60.0}, SceneFile{});
    for (int k = 0; k < 7; ++k) {
        std::string name = std::to_string(k);
        name.insert(0, 1, 'f');
        name += ".json";
        d.rememberFile(dir_ / name);
    }
    d.rememberFile(dir_ / "f4.json");
    ASSERT_EQ(d.recent.size(), Document::kRecentFiles);
    EXPECT_EQ(d.recent.front().filename(), "f4.json");
    EXPECT_EQ(d.recent[1].filename(), "f6.json");
    EXPECT_EQ(std::count(d.recent.begin(), d.recent.end(), d.recent.front()), 1);
}

TEST_F(DocumentTest, ASaveWritesTheMetaAndClearsTheUnsavedMark) {
    Document d(makeWorld(defaultScene()),
               SceneInfo{.name = "lesson", .description = "Two discs.", .dt = 1.0 / 240.0},
               SceneFile{});
    d.dirty = true;
    d.fileError = "Save failed: earlier";
    const std::string said = d.save(dir_ / "lesson.json");
    EXPECT_NE(said.find("lesson.json"), std::string::npos);
    EXPECT_FALSE(d.dirty);
    EXPECT_TRUE(d.fileError.empty());
    ASSERT_TRUE(d.lastSave);
    EXPECT_TRUE(d.lastSave->is_absolute());
    EXPECT_EQ(d.recent.front(), *d.lastSave);
    EXPECT_EQ(d.file.path, d.lastSave);  // the scene now belongs to the file the user named
    EXPECT_TRUE(d.file.writable);
    const Scene back = loadScene(dir_ / "lesson.json");
    EXPECT_EQ(back.name, "lesson");
    EXPECT_EQ(back.description, "Two discs.");
    EXPECT_EQ(back.dt, 1.0 / 240.0);  // the meta's frame length: the world keeps none
    EXPECT_THROW(d.save(dir_ / "no-such-folder" / "x.json"), SaveError);
    EXPECT_EQ(d.file.path, d.lastSave);  // a failed save changes nothing
}

}  // namespace
}  // namespace psb::app
