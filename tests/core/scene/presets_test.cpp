// The shipped presets and the built-in default scene.

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include <particle_sandbox/diagnostics.hpp>
#include <particle_sandbox/error.hpp>
#include <particle_sandbox/presets.hpp>
#include <particle_sandbox/scene.hpp>
#include <particle_sandbox/scene_builders.hpp>

namespace psb {
namespace {

const std::filesystem::path kScenes = std::filesystem::path(PSB_ASSETS_DIR) / "scenes";

/// What 08-brownian-motion.json is made of: 1 cm, 10 g discs at kT = 1 mJ around an 8 cm,
/// 640 g one (the same density), in a 1.54 m box.
const scenes::BrownianSpec kBrownianPreset{.count = 1500,
                                           .lightRadius = 0.01,
                                           .lightMass = 0.01,
                                           .bigRadius = 0.08,
                                           .bigMass = 0.64,
                                           .packing = 0.2,
                                           .temperature = 0.001,
                                           .seed = 7};

TEST(Presets, TheNumberedPresetsComeInOrder) {
    const auto files = sceneFiles(kScenes);
    const char* expected[] = {"01-original.json",
                              "02-newtons-cradle.json",
                              "03-billiards-break.json",
                              "04-gas-in-a-box.json",
                              "05-mass-ratio.json",
                              "06-bullet-into-crowd.json",
                              "07-pile-under-gravity.json",
                              "08-brownian-motion.json",
                              "09-galton-board.json",
                              "10-funnel.json",
                              "11-hourglass.json",
                              "12-ramp.json",
                              "13-basketball-and-tennis-ball.json",
                              "14-bowling.json"};
    ASSERT_EQ(files.size(), std::size(expected));
    for (std::size_t i = 0; i < files.size(); ++i)
        EXPECT_EQ(files[i].filename(), expected[i]);
}

TEST(Presets, EachStartsWithItsNameAndDescription) {
    for (const auto& file : sceneFiles(kScenes)) {
        SCOPED_TRACE(file.filename().string());
        std::ifstream in(file);
        std::string first, second, third;
        std::getline(in, first);
        std::getline(in, second);
        std::getline(in, third);
        EXPECT_EQ(first, "{");
        EXPECT_EQ(second.rfind("  \"name\": \"", 0), 0u) << second;
        EXPECT_EQ(third.rfind("  \"description\": \"", 0), 0u) << third;
        const Scene s = loadScene(file);
        EXPECT_FALSE(s.name.empty());
        EXPECT_GT(s.description.size(), 60u);
    }
}

TEST(Presets, ABodyThatCannotTurnIsNamedAsTheDiscItIsDrawn) {
    // The ramp lesson at 200 %: its description and the README called the third body "a block
    // that cannot turn", and the box drew a round ball. Every particle is a disc and is drawn as
    // one: a preset of a few bodies, each named in its description, names one that cannot turn
    // a disc that cannot turn (sliding as a block would), never a block.
    std::size_t named = 0;
    for (const auto& file : sceneFiles(kScenes)) {
        SCOPED_TRACE(file.filename().string());
        const Scene s = loadScene(file);
        if (s.particles.empty() || s.particles.size() > 10) continue;
        const bool oneCannotTurn =
            std::any_of(s.particles.begin(), s.particles.end(),
                        [](const ParticleDef& p) { return p.fixedRotation; });
        if (!oneCannotTurn) continue;
        ++named;
        EXPECT_NE(s.description.find("a disc that cannot turn"), std::string::npos)
            << s.description;
        EXPECT_EQ(s.description.find("block that cannot turn"), std::string::npos) << s.description;
    }
    EXPECT_GE(named, 2u) << "the ramp and bowling";
}

TEST(Presets, AllLoadAndRunKeepingEveryParticleInTheBox) {
    for (const auto& file : sceneFiles(kScenes)) {
        SCOPED_TRACE(file.filename().string());
        const Scene s = loadScene(file);
        // Every preset has particles, or a dropper that makes them.
        ASSERT_GT(s.particles.size() + s.droppers.size(), 0u);
        World w = makeWorld(s);
        const double e0 = kineticEnergy(w);
        for (int k = 0; k < 30; ++k)
            w.step(s.dt);
        std::uint64_t dropped = 0;
        for (std::size_t k = 0; k < s.droppers.size(); ++k)
            dropped += w.droppers()[k].released - s.droppers[k].released;
        EXPECT_EQ(w.size(), s.particles.size() + dropped);
        const ParticleArrays& p = w.particles();
        for (std::size_t i = 0; i < p.size(); ++i) {
            ASSERT_TRUE(std::isfinite(p.x[i]) && std::isfinite(p.y[i]));
            ASSERT_GE(p.x[i], p.radius[i]);
            ASSERT_LE(p.x[i], s.world.width - p.radius[i]);
        }
        // Elastic presets without gravity keep their kinetic energy (to rounding).
        if (s.world.restitution == 1.0 && s.world.gravity.isZero() && s.world.friction == 0.0) {
            EXPECT_NEAR(kineticEnergy(w), e0, 1e-12 * e0);
        }
    }
}

TEST(Presets, GasInABoxHasThousandsOfParticles) {
    EXPECT_GE(loadScene(kScenes / "04-gas-in-a-box.json").particles.size(), 1000u);
}

TEST(Presets, ThePileHasGravityAndInelasticCollisions) {
    const Scene s = loadScene(kScenes / "07-pile-under-gravity.json");
    EXPECT_GT(s.world.gravity.y(), 0.0);
    EXPECT_LT(s.world.restitution, 1.0);
}

TEST(Presets, EachIsAtTheScaleOfWhatItShows) {
    // Numbers a teacher recognises: boxes from a board to a room, discs from a grain to a
    // big ball, speeds a thrown object has, and Earth's gravity where gravity is on.
    for (const auto& file : sceneFiles(kScenes)) {
        SCOPED_TRACE(file.filename().string());
        const Scene s = loadScene(file);
        EXPECT_GE(std::min(s.world.width, s.world.height), 0.3);
        EXPECT_LE(std::max(s.world.width, s.world.height), 30.0);
        EXPECT_TRUE(s.world.gravity.isZero() || s.world.gravity == Vec2(0.0, 9.81));
        for (const ParticleDef& p : s.particles) {
            EXPECT_GE(p.radius, 0.001);
            EXPECT_LE(p.radius, 0.5);
            EXPECT_LE(p.mass, 100.0);
            EXPECT_LE(p.velocity.norm(), 30.0);
        }
    }
}

TEST(Presets, TheGaltonBoardsBinsAreUnderItsBinWallsOnePerNumberOfRightTurns) {
    const Scene s = loadScene(kScenes / "09-galton-board.json");
    ASSERT_TRUE(s.bins);
    ASSERT_TRUE(s.bins->binomial);
    std::set<double> rows;
    double lowestPeg = 0.0, pegRadius = 0.0, wallsTop = INFINITY;
    std::set<double> walls;
    for (const Obstacle& o : s.world.obstacles) {
        if (o.isPeg()) {
            rows.insert(o.a.y());
            lowestPeg = std::max(lowestPeg, o.a.y());
            pegRadius = o.radius;
        } else if (o.a.x() == o.b.x()) {  // a bin wall
            walls.insert(o.a.x());
            wallsTop = std::min({wallsTop, o.a.y(), o.b.y()});
        }
    }
    // One trial per row of pegs, one bin per number of right turns.
    EXPECT_EQ(s.bins->binomial->trials, static_cast<int>(rows.size()));
    EXPECT_EQ(s.bins->binomial->p, 0.5);
    ASSERT_EQ(s.bins->size(), rows.size() + 1);
    // Each edge is a bin wall, the walls start at the bins' top, below the last row's pegs.
    for (const double e : s.bins->edges)
        EXPECT_TRUE(walls.count(e)) << "edge " << e << " is no bin wall";
    EXPECT_EQ(s.bins->top, wallsTop);
    EXPECT_GT(s.bins->top, lowestPeg + pegRadius);
    // The bins are centred under the top peg, where the balls fall in.
    const double middle = 0.5 * (s.bins->edges.front() + s.bins->edges.back());
    EXPECT_NEAR(middle, 0.5 * s.world.width, 1e-12);
    // No ball yet: one spout above the top peg, in the middle, holds all 1000.
    EXPECT_TRUE(s.particles.empty());
    ASSERT_EQ(s.droppers.size(), 1u);
    const Dropper& d = s.droppers[0];
    EXPECT_EQ(d.balls, 1000u);
    EXPECT_EQ(d.released, 0u);
    EXPECT_EQ(d.position.x(), 0.5 * s.world.width);
    EXPECT_LT(d.position.y(), *rows.begin());
    // Its spread keeps a ball off the top peg's dead centre, within the peg's own width.
    EXPECT_GT(d.spread, 0.0);
    EXPECT_LT(d.spread, pegRadius);
}

TEST(Presets, BrownianMotionIsOneHeavyDiscWithItsTrailInAGas) {
    const Scene s = loadScene(kScenes / "08-brownian-motion.json");
    EXPECT_EQ(s.solver.mode, StepMode::Exact);
    ASSERT_EQ(s.trails, std::vector<std::size_t>{0});
    EXPECT_EQ(s.particles[0].mass, 0.64);
    EXPECT_EQ(s.particles[0].radius, 0.08);
    ASSERT_EQ(s.particles.size(), 1501u);
    for (std::size_t i = 1; i < s.particles.size(); ++i) {
        EXPECT_EQ(s.particles[i].mass, 0.01);
        EXPECT_EQ(s.particles[i].radius, 0.01);
    }
    // The file is what the builder makes (apart from the solver, set for the preset).
    Scene built = scenes::brownian(kBrownianPreset);
    ASSERT_EQ(built.particles.size(), s.particles.size());
    EXPECT_EQ(built.world.width, s.world.width);
    for (std::size_t i = 0; i < s.particles.size(); ++i) {
        EXPECT_EQ(built.particles[i].position, s.particles[i].position) << i;
        EXPECT_EQ(built.particles[i].velocity, s.particles[i].velocity) << i;
    }
}

TEST(Presets, TheBrownianBuilderTakesTheLightDiscsSizeMassAndTemperature) {
    const Scene s = scenes::brownian(kBrownianPreset);
    // The light discs cover 20 % of the area the heavy one leaves.
    const double side = s.world.width;
    double lightArea = 0.0, keSum = 0.0;
    for (std::size_t i = 1; i < s.particles.size(); ++i) {
        const ParticleDef& p = s.particles[i];
        lightArea += std::numbers::pi * p.radius * p.radius;
        keSum += 0.5 * p.mass * p.velocity.squaredNorm();
    }
    EXPECT_NEAR(lightArea / (side * side - std::numbers::pi * 0.08 * 0.08), 0.2, 1e-9);
    // Two degrees of freedom: the mean kinetic energy is kT (1500 samples: ~3 % noise).
    EXPECT_NEAR(keSum / 1500.0, 0.001, 0.0002);
    EXPECT_THROW((void)scenes::brownian({.lightRadius = 0.0}), InvalidArgument);
    EXPECT_THROW((void)scenes::brownian({.temperature = -1.0}), InvalidArgument);
}

TEST(Presets, NewtonsCradleSendsOffOnlyTheLastBall) {
    const Scene s = loadScene(kScenes / "02-newtons-cradle.json");
    World w = makeWorld(s);
    for (int k = 0; k < 240; ++k)
        w.step(s.dt);  // 1 s: the striker has hit the row
    const ParticleArrays& p = w.particles();
    for (std::size_t i = 0; i + 1 < p.size(); ++i)
        EXPECT_EQ(p.vx[i], 0.0) << i;
    EXPECT_DOUBLE_EQ(p.vx[p.size() - 1], 0.2);
}

TEST(Presets, TheDefaultSceneIsTheOriginalsAndMatchesItsFile) {
    const Scene s = defaultScene();
    EXPECT_EQ(s.world.width, 7.0);  // the original's 700 px at 1 px = 1 cm
    EXPECT_EQ(s.world.height, 7.0);
    EXPECT_TRUE(s.world.walls);
    EXPECT_TRUE(s.world.gravity.isZero());
    EXPECT_EQ(s.world.restitution, 1.0);
    ASSERT_GE(s.particles.size(), 3u);
    ASSERT_LE(s.particles.size(), 10u);
    for (const ParticleDef& p : s.particles) {
        EXPECT_GE(p.mass, 3.0);
        EXPECT_LE(p.mass, 20.0);
        EXPECT_DOUBLE_EQ(p.radius, 0.025 * p.mass);  // 7.5 to 50 cm
        EXPECT_LE(std::abs(p.velocity.x()), 3.0);
        EXPECT_LE(std::abs(p.velocity.y()), 3.0);
    }
    // Valid by the loader's own rules (inside, no overlaps), and the same as the shipped file.
    EXPECT_EQ(serializeScene(parseScene(serializeScene(s), "default")), serializeScene(s));
    EXPECT_EQ(serializeScene(loadScene(kScenes / "01-original.json")), serializeScene(s));
}

TEST(Presets, SceneFilesOfAMissingDirectoryIsEmpty) {
    EXPECT_TRUE(sceneFiles("no/such/directory").empty());
}

}  // namespace
}  // namespace psb
