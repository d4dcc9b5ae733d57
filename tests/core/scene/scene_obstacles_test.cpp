// Obstacles in scene files: they round-trip bit for bit, the version written is the lowest that
// has them, old scenes are untouched, and a run saved halfway continues identically.

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <filesystem>

#include <particle_sandbox/presets.hpp>
#include <particle_sandbox/scene.hpp>

namespace psb {
namespace {

bool sameBits(double a, double b) {
    return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

Scene withObstacles() {
    Scene s;
    s.name = "obstacles";
    s.world.width = 10.0;
    s.world.height = 7.0;
    s.world.obstacles = {Obstacle::peg(Vec2(1.0 / 3.0, 0.1), 0.1 + 0.2),
                         Obstacle::segment(Vec2(-0.0, 7.0), Vec2(10.0, 5.0e-300), 1e-7 / 3.0),
                         Obstacle::peg(Vec2(9.999999999999998, 3.0), 2.5)};
    s.particles.push_back({.position = {2.0, 1.0}, .velocity = {1.0, -2.0}, .radius = 0.5});
    return s;
}

TEST(SceneObstacles, RoundTripBitForBit) {
    const Scene a = withObstacles();
    const Scene b = parseScene(serializeScene(a), "round trip");
    ASSERT_EQ(b.world.obstacles.size(), a.world.obstacles.size());
    for (std::size_t k = 0; k < a.world.obstacles.size(); ++k) {
        const Obstacle &x = a.world.obstacles[k], &y = b.world.obstacles[k];
        SCOPED_TRACE(k);
        EXPECT_EQ(x.kind, y.kind);
        EXPECT_TRUE(sameBits(x.a.x(), y.a.x()));
        EXPECT_TRUE(sameBits(x.a.y(), y.a.y()));
        EXPECT_TRUE(sameBits(x.b.x(), y.b.x()));
        EXPECT_TRUE(sameBits(x.b.y(), y.b.y()));
        EXPECT_TRUE(sameBits(x.radius, y.radius));
    }
    EXPECT_EQ(serializeScene(b), serializeScene(a));
}

TEST(SceneObstacles, VersionWrittenIsTheLowestThatHasEverythingUsed) {
    Scene s = withObstacles();
    EXPECT_NE(serializeScene(s).find("\"version\": 2,"), std::string::npos);
    EXPECT_EQ(parseScene(serializeScene(s), "x").version, 2);
    s.world.obstacles.clear();
    const std::string text = serializeScene(s);
    EXPECT_NE(text.find("\"version\": 1,"), std::string::npos);
    EXPECT_EQ(text.find("\"obstacles\":"), std::string::npos);
    // A version-2 file without obstacles keeps its version.
    EXPECT_NE(serializeScene(parseScene(R"({"version": 2})", "x")).find("\"version\": 2,"),
              std::string::npos);
}

TEST(SceneObstacles, OldScenesLoadAndSaveUnchanged) {
    for (const auto& file : sceneFiles(std::filesystem::path(PSB_ASSETS_DIR) / "scenes")) {
        const Scene s = loadScene(file);
        if (s.version != 1) continue;
        SCOPED_TRACE(file.filename().string());
        EXPECT_TRUE(s.world.obstacles.empty());
        const std::string text = serializeScene(s);
        EXPECT_NE(text.find("\"version\": 1,"), std::string::npos);
        EXPECT_EQ(text.find("\"obstacles\":"), std::string::npos);
    }
}

TEST(SceneObstacles, ARunSavedHalfwayContinuesIdentically) {
    // The Galton board in the discrete mode (the exact mode's event state, what sleeps where,
    // is not in a scene file): its spout, saved with how far it has got, drops the same balls
    // at the same steps after the save.
    Scene scene =
        loadScene(std::filesystem::path(PSB_ASSETS_DIR) / "scenes" / "09-galton-board.json");
    scene.solver.mode = StepMode::Discrete;
    scene.dt = 0.001;
    World straight = makeWorld(scene);
    straight.setThreads(1);
    for (int k = 0; k < 200; ++k)
        straight.step(scene.dt);
    const Scene saved = parseScene(serializeScene(sceneFromWorld(straight, scene.dt)), "saved");
    World resumed = makeWorld(saved);
    resumed.setThreads(1);
    for (int k = 0; k < 200; ++k) {
        straight.step(scene.dt);
        resumed.step(saved.dt);
    }
    EXPECT_EQ(resumed.obstacles(), straight.obstacles());
    EXPECT_EQ(resumed.droppers(), straight.droppers());
    EXPECT_EQ(straight.droppers()[0].released, 8u);  // 4 before the save, 4 after
    EXPECT_EQ(resumed.particles().x, straight.particles().x);
    EXPECT_EQ(resumed.particles().vy, straight.particles().vy);
}

}  // namespace
}  // namespace psb
