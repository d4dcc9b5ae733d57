// Scene format version 6: the world's `periodic`, what it refuses, and its round trip.

#include <gtest/gtest.h>

#include <string>

#include <particle_sandbox/error.hpp>
#include <particle_sandbox/scene.hpp>
#include <particle_sandbox/world.hpp>

namespace psb {
namespace {

std::string messageOf(std::string_view json) {
    try {
        (void)parseScene(json, "s.json");
    } catch (const SceneError& e) {
        return e.what();
    }
    return "(loaded)";
}

TEST(ScenePeriodic, AVersion6WorldJoinsItsEdgesAndHasNoWalls) {
    const Scene s = parseScene(
        R"({"version": 6, "world": {"width": 20, "height": 10, "periodic": true},
            "particles": [{"x": 19.9, "y": 5, "radius": 1, "mass": 1}]})",
        "s.json");
    EXPECT_TRUE(s.world.periodic);
    EXPECT_FALSE(s.world.walls);
    const World w = makeWorld(s);
    EXPECT_TRUE(w.def().periodic);
    EXPECT_EQ(w.particles().unwrapX.size(), 1u);
}

TEST(ScenePeriodic, OlderVersionsReadAsBeforeAndRefuseTheKey) {
    const Scene old = parseScene(R"({"version": 5, "world": {"walls": false}})", "s.json");
    EXPECT_FALSE(old.world.periodic);
    EXPECT_FALSE(old.world.walls);
    const std::string m = messageOf(R"({"version": 5, "world": {"periodic": true}})");
    EXPECT_NE(m.find("world.periodic"), std::string::npos) << m;
    EXPECT_NE(m.find("version 6"), std::string::npos) << m;
}

TEST(ScenePeriodic, WallsAndPeriodicTogetherAreRefused) {
    const std::string m =
        messageOf(R"({"version": 6, "world": {"periodic": true, "walls": true}})");
    EXPECT_NE(m.find("world.walls"), std::string::npos) << m;
    EXPECT_NE(m.find("periodic"), std::string::npos) << m;
    // Walls false beside periodic says the same thing twice: accepted.
    const Scene s =
        parseScene(R"({"version": 6, "world": {"periodic": true, "walls": false}})", "s.json");
    EXPECT_TRUE(s.world.periodic);
}

TEST(ScenePeriodic, ABoxSmallerThanTwoDiametersIsRefusedNamingTheSide) {
    const std::string m = messageOf(
        R"({"version": 6, "world": {"width": 30, "height": 7.9, "periodic": true},
            "particles": [{"x": 1, "y": 1, "radius": 1, "mass": 1}, {"x": 5, "y": 4, "radius": 2, "mass": 1}]})");
    EXPECT_NE(m.find("world.height"), std::string::npos) << m;
    EXPECT_NE(m.find("two diameters"), std::string::npos) << m;
    EXPECT_NE(m.find("particles[1]"), std::string::npos) << m;
    // Dropper balls count as particles.
    const std::string d = messageOf(
        R"({"version": 6, "world": {"width": 3, "height": 30, "periodic": true},
            "droppers": [{"x": 1.5, "y": 1, "radius": 1, "interval": 1, "balls": 1, "mass": 1}]})");
    EXPECT_NE(d.find("world.width"), std::string::npos) << d;
    EXPECT_NE(d.find("droppers[0]"), std::string::npos) << d;
}

TEST(ScenePeriodic, DiscsOverlappingAcrossAnEdgeOrACornerAreRefused) {
    // 0.2 m from the left edge and 0.2 m from the right one: 0.4 m apart across the edge, with
    // radii summing to 1 m. Without the periodic box they are 19.6 m apart and load.
    const auto scene = [](const char* world, const char* second) {
        return std::string(R"({"version": 6, "world": )") + world +
               R"(, "particles": [{"x": 0.2, "y": 5, "radius": 0.5, "mass": 1},
                                  {"x": 3, "y": 3, "radius": 0.5, "mass": 1}, )" +
               second + "]}";
    };
    const char* periodic = R"({"width": 20, "height": 20, "periodic": true})";
    const std::string m = messageOf(scene(periodic, R"({"x": 19.8, "y": 5.1, "radius": 0.5,
                                                        "mass": 1})"));
    EXPECT_NE(m.find("particles[0]: overlaps particles[2]"), std::string::npos) << m;
    EXPECT_NE(m.find("across the box's edge"), std::string::npos) << m;
    EXPECT_EQ(messageOf(scene(R"({"width": 20, "height": 20, "walls": false})",
                              R"({"x": 19.8, "y": 5.1, "radius": 0.5, "mass": 1})")),
              "(loaded)");
    // Across a corner: (0.2, 5) and (19.9, 19.9) are not near; (0.3, 0.3) and (19.8, 19.8) are
    // 0.71 m apart through the corner.
    const std::string c = messageOf(
        R"({"version": 6, "world": {"width": 20, "height": 20, "periodic": true},
            "particles": [{"x": 0.3, "y": 0.3, "radius": 0.5, "mass": 1},
                          {"x": 19.8, "y": 19.8, "radius": 0.5, "mass": 1}]})");
    EXPECT_NE(c.find("particles[0]: overlaps particles[1]"), std::string::npos) << c;
    // A generated gas that fills the box to its edges loads: the lattice keeps its spacing
    // across them.
    EXPECT_EQ(messageOf(R"({"version": 6, "world": {"width": 1, "height": 1, "periodic": true},
        "generate": {"count": 900, "radius": 1, "packing_fraction": 0.7, "seed": 2}})"),
              "(loaded)");
}

TEST(ScenePeriodic, AnObstacleNearAnEdgeIsRefusedNamingIt) {
    const std::string m = messageOf(
        R"({"version": 6, "world": {"width": 20, "height": 20, "periodic": true},
            "obstacles": [{"type": "peg", "x": 10, "y": 10, "radius": 1},
                          {"type": "peg", "x": 19, "y": 10, "radius": 0.5}],
            "particles": [{"x": 5, "y": 5, "radius": 0.5, "mass": 1}]})");
    EXPECT_NE(m.find("obstacles[1]"), std::string::npos) << m;
    EXPECT_NE(m.find("inside every edge"), std::string::npos) << m;
}

TEST(ScenePeriodic, ARoundTripKeepsTheBoxPeriodicAndWritesVersion6) {
    const Scene s = parseScene(
        R"({"version": 6, "world": {"width": 20, "height": 10, "periodic": true},
            "particles": [{"x": 3, "y": 5, "vx": 1, "radius": 1, "mass": 1}]})",
        "s.json");
    const std::string text = serializeScene(s);
    EXPECT_NE(text.find("\"version\": 6"), std::string::npos) << text;
    EXPECT_NE(text.find("\"periodic\": true"), std::string::npos) << text;
    EXPECT_EQ(text.find("\"walls\""), std::string::npos) << text;
    const Scene back = parseScene(text, "back.json");
    EXPECT_TRUE(back.world.periodic);
    EXPECT_EQ(serializeScene(back), text);
    // A world that is not periodic is written as before: no key, its own version.
    const Scene walled = parseScene(R"({"version": 3, "world": {"walls": true}})", "s.json");
    const std::string plain = serializeScene(walled);
    EXPECT_EQ(plain.find("periodic"), std::string::npos) << plain;
    EXPECT_NE(plain.find("\"version\": 3"), std::string::npos) << plain;
}

TEST(ScenePeriodic, ASavedWorldStaysPeriodic) {
    WorldDef def;
    def.width = 12.0;
    def.height = 12.0;
    def.periodic = true;
    World w(def);
    ParticleDef d;
    d.position = {11.5, 6.0};
    d.velocity = {2.0, 0.0};
    d.radius = 1.0;
    w.add(d);
    w.step(0.5);
    const Scene s = sceneFromWorld(w, 0.01);
    EXPECT_TRUE(s.world.periodic);
    ASSERT_EQ(s.particles.size(), 1u);
    EXPECT_NEAR(s.particles[0].position.x(), 0.5, 1e-12);
}

}  // namespace
}  // namespace psb
