// Scene overrides (SceneOverride, the runner's --set): a value set by its path before the file
// is checked, and every way a path can be wrong named in words.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include <particle_sandbox/scene.hpp>

namespace psb {
namespace {

constexpr const char* kGas = R"({
  "version": 5,
  "name": "gas",
  "world": {"width": 20, "height": 20},
  "generate": {"count": 10, "radius": 0.5, "temperature": 1, "seed": 1}
})";

Scene withSets(const char* text, std::vector<SceneOverride> sets) {
    return parseScene(text, "gas.json", sets);
}

std::string refusal(const char* text, std::vector<SceneOverride> sets) {
    try {
        (void)withSets(text, std::move(sets));
    } catch (const SceneError& e) {
        return e.what();
    }
    return "(accepted)";
}

TEST(SceneOverrides, ValuesAreSetByPathBeforeTheSceneIsRead) {
    const Scene s = withSets(kGas, {{"world.restitution", "0.9"},
                                    {"generate.count", "25"},
                                    {"name", "a run with spaces"},
                                    {"world.gravity", "[0, -9.81]"}});
    EXPECT_EQ(s.world.restitution, 0.9);
    EXPECT_EQ(s.particles.size(), 25u);
    EXPECT_EQ(s.name, "a run with spaces") << "not JSON: taken as a string";
    EXPECT_EQ(s.world.gravity.y(), -9.81);
    EXPECT_EQ(withSets(kGas, {}).particles.size(), 10u);
}

TEST(SceneOverrides, MissingObjectsAreMadeAndLaterSetsWin) {
    const Scene s =
        withSets(kGas, {{"solver.mode", "\"exact\""}, {"solver.dt", "0.5"}, {"solver.dt", "0.25"}});
    EXPECT_EQ(s.solver.mode, StepMode::Exact);
    EXPECT_EQ(s.dt, 0.25);
}

TEST(SceneOverrides, AnArrayOfBlocksIsIndexed) {
    constexpr const char* kTwo = R"({
      "version": 5, "world": {"width": 40, "height": 20},
      "generate": [{"count": 5, "radius": 0.5, "temperature": 1, "seed": 1, "region": [0, 0, 20, 20]},
                   {"count": 5, "radius": 0.5, "temperature": 1, "seed": 2, "region": [20, 0, 40, 20]}]
    })";
    EXPECT_EQ(withSets(kTwo, {{"generate[1].count", "7"}}).particles.size(), 12u);
    EXPECT_EQ(refusal(kTwo, {{"generate.count", "7"}}),
              "gas.json: --set generate.count: generate is an array of 2 elements: say which, as "
              "in generate[0].count");
    EXPECT_EQ(refusal(kTwo, {{"generate[2].count", "7"}}),
              "gas.json: --set generate[2].count: generate has 2 elements: no index 2");
}

TEST(SceneOverrides, AWrongPathOrValueIsNamed) {
    // The reader's own check names the nearest key of the format.
    const std::string typo = refusal(kGas, {{"world.restitutoin", "0.9"}});
    EXPECT_NE(typo.find("world.restitutoin: unknown key"), std::string::npos) << typo;
    EXPECT_NE(typo.find("restitution"), std::string::npos) << typo;
    const std::string type = refusal(kGas, {{"world.walls", "3"}});
    EXPECT_NE(type.find("world.walls: expected true or false, got an integer"), std::string::npos)
        << type;
    EXPECT_EQ(refusal(kGas, {{"name.first", "x"}}),
              "gas.json: --set name.first: name is a string, not an object: it has no key 'first'");
    EXPECT_EQ(refusal(kGas, {{"particles[0].mass", "2"}}),
              "gas.json: --set particles[0].mass: particles is not in the scene");
    EXPECT_EQ(refusal(kGas, {{"world..width", "2"}}),
              "gas.json: --set world..width: an empty key (two dots, or a dot at an end)");
    EXPECT_EQ(refusal(kGas, {{"", "2"}}),
              "gas.json: --set : an empty path (say which value: world.restitution)");
    EXPECT_EQ(refusal(kGas, {{"world[x]", "2"}}),
              "gas.json: --set world[x]: an index is a whole number, as in particles[3]");
    EXPECT_EQ(refusal(kGas, {{"world.width\x1b[2J", "2"}}).find('\x1b'), std::string::npos)
        << "no control character reaches a terminal";
}

}  // namespace
}  // namespace psb
