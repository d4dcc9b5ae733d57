// Reading scenes: defaults, every field, generate blocks, limits, and the modes the world
// refuses.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <particle_sandbox/error.hpp>
#include <particle_sandbox/scene.hpp>

#include "scene/json_reader.hpp"

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

TEST(SceneReader, OnlyTheVersionIsRequiredAndEverythingElseHasItsDocumentedDefault) {
    const Scene s = parseScene(R"({"version": 1})", "s.json");
    EXPECT_EQ(s.version, 1);
    EXPECT_EQ(s.name, "");
    EXPECT_EQ(s.description, "");
    EXPECT_EQ(s.world.width, 700.0);
    EXPECT_EQ(s.world.height, 700.0);
    EXPECT_TRUE(s.world.walls);
    EXPECT_EQ(s.world.gravity, Vec2(0.0, 0.0));
    EXPECT_EQ(s.world.restitution, 1.0);
    EXPECT_EQ(s.world.friction, 0.0);
    EXPECT_EQ(s.solver.mode, StepMode::Discrete);
    EXPECT_EQ(s.dt, 0.01);
    EXPECT_EQ(s.solver.substeps, 1);
    EXPECT_EQ(s.solver.broadphase, BroadPhaseKind::Auto);
    EXPECT_TRUE(s.particles.empty());
    EXPECT_FALSE(s.allowOverlaps);
}

TEST(SceneReader, ReadsEveryFieldWithItsUnit) {
    const Scene s = parseScene(R"({
      "name": "n", "description": "d", "version": 1,
      "world": {"width": 200, "height": 100.5, "walls": false, "gravity": [0.5, 9.81],
                "restitution": 0.75, "friction": 0.25},
      "solver": {"mode": "substep", "dt": 0.002, "substeps": 4, "broadphase": "all-pairs"},
      "particles": [{"x": 10, "y": 20, "vx": -3.5, "vy": 4e-3, "mass": 2.5, "radius": 1.25,
                     "color": [1, 2, 3]},
                    {"x": 100, "y": 50, "mass": 7, "radius": 3}]
    })",
                               "s.json");
    EXPECT_EQ(s.name, "n");
    EXPECT_EQ(s.description, "d");
    EXPECT_EQ(s.world.width, 200.0);
    EXPECT_EQ(s.world.height, 100.5);
    EXPECT_FALSE(s.world.walls);
    EXPECT_EQ(s.world.gravity, Vec2(0.5, 9.81));
    EXPECT_EQ(s.world.restitution, 0.75);
    EXPECT_EQ(s.world.friction, 0.25);
    EXPECT_EQ(s.solver.mode, StepMode::Substep);
    EXPECT_EQ(s.dt, 0.002);
    EXPECT_EQ(s.solver.substeps, 4);
    EXPECT_EQ(s.solver.broadphase, BroadPhaseKind::AllPairs);
    ASSERT_EQ(s.particles.size(), 2u);
    const ParticleDef& p = s.particles[0];
    EXPECT_EQ(p.position, Vec2(10.0, 20.0));
    EXPECT_EQ(p.velocity, Vec2(-3.5, 4e-3));
    EXPECT_EQ(p.mass, 2.5);
    EXPECT_EQ(p.radius, 1.25);
    EXPECT_EQ(p.color, (Color{1, 2, 3}));
    // Omitted velocity and colour default to rest and white.
    EXPECT_EQ(s.particles[1].velocity, Vec2(0.0, 0.0));
    EXPECT_EQ(s.particles[1].color, (Color{255, 255, 255}));
}

TEST(SceneReader, KeyOrderDoesNotMatter) {
    const Scene a =
        parseScene(R"({"version": 1, "name": "x", "world": {"height": 5, "width": 6}})", "a");
    const Scene b =
        parseScene(R"({"world": {"width": 6, "height": 5}, "name": "x", "version": 1})", "b");
    EXPECT_EQ(a.world.width, b.world.width);
    EXPECT_EQ(a.world.height, b.world.height);
}

TEST(SceneReader, SolverDtIsTheScenesFrameLengthFiniteAndPositive) {
    // The file keeps the frame length in its solver block; the scene in memory has it as dt.
    EXPECT_EQ(parseScene(R"({"version": 1, "solver": {"dt": 0.004}})", "s.json").dt, 0.004);
    EXPECT_EQ(messageOf(R"({"version": 1, "solver": {"dt": 0}})"),
              "s.json: solver.dt: must be > 0 (got 0)");
    EXPECT_EQ(messageOf(R"({"version": 1, "solver": {"dt": -0.01}})"),
              "s.json: solver.dt: must be > 0 (got -0.01)");
    // JSON has no NaN or infinity: such a value is refused where it stands, at its path.
    const std::string nan = messageOf(R"({"version": 1, "solver": {"dt": NaN}})");
    EXPECT_EQ(nan.rfind("s.json: line 1, column 33 (solver.dt): syntax error", 0), 0u) << nan;
    EXPECT_EQ(messageOf(R"({"version": 1, "solver": {"dt": 1e999}})"),
              "s.json: line 1, column 33 (solver.dt): number overflow parsing '1e999'");
}

TEST(SceneReader, ParticlesOutsideTheBoxAreFineWhenThereAreNoWalls) {
    const Scene s = parseScene(
        R"({"version": 1, "world": {"walls": false},
            "particles": [{"x": -500, "y": 1e6, "mass": 1, "radius": 1}]})",
        "s.json");
    EXPECT_EQ(s.particles.size(), 1u);
}

TEST(SceneReader, TouchingParticlesDoNotOverlap) {
    // Newton's cradle: centres exactly one diameter apart.
    const Scene s = parseScene(
        R"({"version": 1, "particles": [{"x": 100, "y": 100, "mass": 1, "radius": 10},
                                        {"x": 120, "y": 100, "mass": 1, "radius": 10}]})",
        "s.json");
    EXPECT_EQ(s.particles.size(), 2u);
}

TEST(SceneReader, AParticleTouchingTheWallIsInside) {
    EXPECT_EQ(messageOf(R"({"version": 1, "world": {"width": 10, "height": 10},
                           "particles": [{"x": 9, "y": 1, "mass": 1, "radius": 1}]})"),
              "(loaded)");
}

TEST(SceneReader, AllowOverlapsAcceptsOverlappingParticles) {
    const char* overlapping = R"("particles": [{"x": 100, "y": 100, "mass": 1, "radius": 10},
                                               {"x": 105, "y": 100, "mass": 1, "radius": 10}])";
    EXPECT_EQ(messageOf(std::string(R"({"version": 1, )") + overlapping + "}"),
              "s.json: particles[0]: overlaps particles[1] (centres 5 m apart, radii sum to 20 m)");
    const Scene s = parseScene(
        std::string(R"({"version": 1, "allow_overlaps": true, )") + overlapping + "}", "s.json");
    EXPECT_TRUE(s.allowOverlaps);
    EXPECT_EQ(s.particles.size(), 2u);
}

TEST(SceneReader, OverlapMessageNamesTheLowestPairEvenAmongMany) {
    std::string json = R"({"version": 1, "particles": [)";
    for (int k = 0; k < 50; ++k) {
        json +=
            "{\"x\": " + std::to_string(10 + 12 * k) + ", \"y\": 100, \"mass\": 1, \"radius\": 5},";
    }
    // Particle 50 overlaps particles 7 and 8 (both sqrt(6² + 3²) away); the message names the
    // pair (7, 50).
    json += R"({"x": 100, "y": 103, "mass": 1, "radius": 5}]})";
    EXPECT_EQ(messageOf(json),
              "s.json: particles[7]: overlaps particles[50] (centres 6.708203932499369 m apart, "
              "radii sum to 10 m)");
}

TEST(SceneReader, EveryModeLoadsWithGravity) {
    // The event-driven mode included (it used to refuse gravity).
    EXPECT_EQ(
        messageOf(
            R"({"version": 1, "world": {"gravity": [0, 9.81]}, "solver": {"mode": "exact"}})"),
        "(loaded)");
    // Every mode and broadphase name the format lists loads in a world that allows it.
    for (const char* field :
         {R"("mode": "exact")", R"("mode": "substep")", R"("broadphase": "grid")",
          R"("broadphase": "quadtree")", R"("broadphase": "all-pairs")"}) {
        EXPECT_EQ(messageOf(std::string(R"({"version": 1, "solver": {)") + field + "}}"),
                  "(loaded)")
            << field;
    }
}

TEST(SceneReader, AbsurdSizesAreRefusedBeforeAnyWorkIsDone) {
    EXPECT_EQ(messageOf(R"({"version": 1, "generate": {"count": 1000000000000, "radius": 1}})"),
              "s.json: generate.count: must be in [0, 1000000] (got 1000000000000)");
    const std::string big(kMaxSceneFileBytes + 1, ' ');
    EXPECT_EQ(messageOf(big), "s.json: larger than the limit of 256 MiB");
}

TEST(SceneReader, DeepNestingIsRefusedNotRecursedInto) {
    const std::string deep = std::string(100000, '[') + std::string(100000, ']');
    EXPECT_EQ(messageOf(deep), "s.json: nested deeper than 64 levels");
}

TEST(SceneReader, LoadSceneNamesAMissingFileAndADirectory) {
    try {
        (void)loadScene("no/such/scene.json");
        FAIL();
    } catch (const SceneError& e) {
        EXPECT_STREQ(e.what(), "no/such/scene.json: cannot open (No such file or directory)");
    }
    try {
        (void)loadScene(".");
        FAIL();
    } catch (const SceneError& e) {
        EXPECT_STREQ(e.what(), ".: is a directory, not a scene file");
    }
}

TEST(SceneReader, NegativeZeroAndTinyNumbersReadExactly) {
    const Scene s = parseScene(
        R"({"version": 1, "world": {"walls": false}, "particles": [{"x": 5e-324, "y": 1, "vx": -0.0, "vy": 9.999999999999998e14,
             "mass": 1, "radius": 1e-300}]})",
        "s.json");
    const ParticleDef& p = s.particles[0];
    EXPECT_EQ(p.position.x(), 5e-324);
    EXPECT_TRUE(std::signbit(p.velocity.x()));
    EXPECT_EQ(p.velocity.y(), 9.999999999999998e14);
    EXPECT_EQ(p.radius, 1e-300);
}

TEST(SceneReader, MessagesEscapeControlCharactersAndShortenHugeKeys) {
    // "\u001b[2J" would clear the terminal the message is printed on.
    EXPECT_EQ(messageOf(R"({"version": 1, "solver": {"mode": "\u001b[2J"}})"),
              "s.json: solver.mode: unknown mode '\\x1b[2J' (expected one of: discrete, substep, "
              "exact)");
    const std::string key(100000, 'k');
    EXPECT_EQ(messageOf(R"({"version": 1, ")" + key + R"(": 1})"),
              "s.json: " + std::string(64, 'k') +
                  "...: unknown key (expected one of: version, name, description, world, solver, "
                  "particles, generate, allow_overlaps, obstacles, bins, droppers)");
}

TEST(JsonReader, LineAndColumnCountBytesFromOne) {
    const std::string_view text = "ab\ncd\n\nef";
    EXPECT_EQ(detail::positionOf(text, 0).line, 1u);
    EXPECT_EQ(detail::positionOf(text, 0).column, 1u);
    EXPECT_EQ(detail::positionOf(text, 4).line, 2u);
    EXPECT_EQ(detail::positionOf(text, 4).column, 2u);
    EXPECT_EQ(detail::positionOf(text, 7).line, 4u);
    EXPECT_EQ(detail::positionOf(text, 7).column, 1u);
    EXPECT_EQ(detail::positionOf(text, 999).line, 4u);  // clamped to the end
}

}  // namespace
}  // namespace psb
