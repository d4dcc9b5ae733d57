// Ball droppers in scene files (version 4): read, written, round-tripped with where they have
// got to, and old scenes unchanged.

#include <gtest/gtest.h>

#include <string>

#include <particle_sandbox/scene.hpp>

namespace psb {
namespace {

const char* kScene = R"({
  "version": 4,
  "world": {"width": 1.0, "height": 1.0, "gravity": [0, 9.81]},
  "droppers": [{"x": 0.5, "y": 0.1, "balls": 12, "interval": 0.25, "radius": 0.01,
                "mass": 0.002, "color": [1, 2, 3], "vx": 0.5, "vy": -0.25, "spread": 0.02,
                "seed": 77, "released": 3, "next_ball_in": 0.125}]
})";

TEST(SceneDroppers, EveryFieldIsRead) {
    const Scene s = parseScene(kScene, "d.json");
    ASSERT_EQ(s.droppers.size(), 1u);
    const Dropper& d = s.droppers[0];
    EXPECT_EQ(d.position, Vec2(0.5, 0.1));
    EXPECT_EQ(d.balls, 12u);
    EXPECT_EQ(d.interval, 0.25);
    EXPECT_EQ(d.radius, 0.01);
    EXPECT_EQ(d.mass, 0.002);
    EXPECT_EQ(d.color, (Color{1, 2, 3}));
    EXPECT_EQ(d.velocity, Vec2(0.5, -0.25));
    EXPECT_EQ(d.spread, 0.02);
    EXPECT_EQ(d.seed, 77u);
    EXPECT_EQ(d.released, 3u);
    EXPECT_EQ(d.nextIn, 0.125);
}

TEST(SceneDroppers, ARunningDropperRoundTripsBitForBitAndContinues) {
    const Scene s = parseScene(kScene, "d.json");
    World w = makeWorld(s);
    for (int k = 0; k < 77; ++k)
        w.step(0.01);  // mid-interval, some balls out
    const Scene saved = sceneFromWorld(w, s.dt);
    const std::string text = serializeScene(saved);
    EXPECT_NE(text.find("\"version\": 4"), std::string::npos);
    const Scene back = parseScene(text, "saved.json");
    EXPECT_EQ(back.droppers, w.droppers());
    EXPECT_EQ(serializeScene(back), text);
    // The loaded one drops its next ball at the same step as the original.
    World resumed = makeWorld(back);
    for (int k = 0; k < 40; ++k) {
        w.step(0.01);
        resumed.step(0.01);
        ASSERT_EQ(resumed.size(), w.size()) << "step " << k;
    }
    EXPECT_EQ(resumed.droppers(), w.droppers());
}

TEST(SceneDroppers, AScenesWithoutDroppersIsWrittenAsBefore) {
    const Scene s = parseScene(R"({"version": 1, "particles": []})", "old.json");
    EXPECT_TRUE(s.droppers.empty());
    const std::string text = serializeScene(s);
    EXPECT_NE(text.find("\"version\": 1,"), std::string::npos);
    EXPECT_EQ(text.find("droppers"), std::string::npos);
}

}  // namespace
}  // namespace psb
