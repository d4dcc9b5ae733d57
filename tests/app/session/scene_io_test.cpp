// What the app opens and saves: the built-in scene, the presets, and the Ctrl+S snapshot.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <particle_sandbox/scene.hpp>

#include "session/scene_io.hpp"

namespace psb::app {
namespace {

namespace fs = std::filesystem;

class SceneIo : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("psb-app-scene-io-" +
                std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "-" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    fs::path dir_;
};

std::string readAll(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

TEST(SaveFileName, AddsJsonDropsTrailingDotsAndSpacesAndRefusesHiddenOrEmptyNames) {
    std::string why;
    EXPECT_EQ(saveFileName("lesson", why), fs::path("lesson.json"));
    EXPECT_EQ(saveFileName("dir/lesson.json", why), fs::path("dir/lesson.json"));
    EXPECT_EQ(saveFileName("lesson.txt", why), fs::path("lesson.txt"));
    EXPECT_EQ(saveFileName("a.", why), fs::path("a.json"));
    EXPECT_EQ(saveFileName("a. . ", why), fs::path("a.json"));
    EXPECT_EQ(saveFileName("v1.2", why), fs::path("v1.2"));  // an extension the user chose
    EXPECT_FALSE(saveFileName(".json", why));
    EXPECT_NE(why.find("hidden file"), std::string::npos) << why;
    EXPECT_FALSE(saveFileName(".hidden", why));
    EXPECT_FALSE(saveFileName("dir/..", why));
    EXPECT_FALSE(saveFileName(". ", why));
    EXPECT_NE(why.find("is not a file name"), std::string::npos) << why;
    EXPECT_FALSE(saveFileName("dir/", why));
    EXPECT_EQ(why, "the path ends in a folder; type a file name after it");
    // A NUL ends the name the system sees: "dir/\0x" would be "dir/" (found by the session
    // fuzzer: the search for a free name beside it never ended).
    EXPECT_FALSE(saveFileName(fs::path(std::string("dir/\0x", 6)), why));
    EXPECT_NE(why.find("NUL"), std::string::npos) << why;
}

TEST_F(SceneIo, WithoutAFileTheBuiltInSceneOpens) {
    const Scene s = openScene(std::nullopt);
    EXPECT_EQ(s.particles.size(), 6u);
    EXPECT_DOUBLE_EQ(s.world.width, 7.0);
}

TEST_F(SceneIo, AMissingFileIsASceneErrorNamingIt) {
    try {
        (void)openScene(dir_ / "nope.json");
        FAIL() << "no error";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("nope.json"), std::string::npos) << e.what();
    }
}

TEST_F(SceneIo, SavedWorldLoadsBackWithTheSameParticles) {
    World w;
    ParticleDef d;
    d.position = {100.0, 200.0};
    d.velocity = {1.5, -2.25};
    d.mass = 3.0;
    d.radius = 7.5;
    const ParticleId held = w.add(d);
    d.position = {400.0, 200.0};
    w.add(d);
    w.setKinematic(held, true);  // a held particle is saved as a free one
    const fs::path path = dir_ / "snap.json";
    const std::string message = saveWorld(w, {"snap", "Two discs, \"quoted\", e = 1."}, path);
    EXPECT_NE(message.find("2 particles"), std::string::npos) << message;
    const Scene s = loadScene(path);
    ASSERT_EQ(s.particles.size(), 2u);
    EXPECT_EQ(s.particles[0].position, Vec2(100.0, 200.0));
    EXPECT_EQ(s.particles[0].velocity, Vec2(1.5, -2.25));
    EXPECT_EQ(s.name, "snap");
    EXPECT_EQ(s.description, "Two discs, \"quoted\", e = 1.");
}

TEST_F(SceneIo, TheSaveMessageNamesTheFullPathWithoutDotSegments) {
    World w;
    const std::string message = saveWorld(w, {"snap"}, dir_ / "." / "snap.json");
    EXPECT_NE(message.find((dir_ / "snap.json").lexically_normal().string()), std::string::npos)
        << message;
    EXPECT_EQ(message.find("/./"), std::string::npos) << message;
}

TEST_F(SceneIo, AFailedSaveSaysWhyAndLeavesTheOldFileIntact) {
    const fs::path old = dir_ / "keep.json";
    std::ofstream(old) << "old contents";
    World w;
    // A regular file where a directory should be: the save cannot succeed.
    EXPECT_THROW(saveWorld(w, {"x"}, old / "inside.json"), SaveError);
    EXPECT_EQ(readAll(old), "old contents");
    // A directory where the file should be.
    fs::create_directories(dir_ / "adir");
    EXPECT_THROW(saveWorld(w, {"x"}, dir_ / "adir"), SaveError);
    EXPECT_TRUE(fs::is_directory(dir_ / "adir"));
}

}  // namespace
}  // namespace psb::app
