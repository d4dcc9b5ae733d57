// Save then load reproduces the state bit for bit, and saving is atomic.

#include <gtest/gtest.h>

#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <bit>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include <particle_sandbox/error.hpp>
#include <particle_sandbox/presets.hpp>
#include <particle_sandbox/scene.hpp>

#include "test_util.hpp"

namespace psb {
namespace {

namespace fs = std::filesystem;
using test::readFile;
using test::TempDir;

bool sameBits(double a, double b) {
    return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

void expectIdentical(const Scene& a, const Scene& b) {
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.description, b.description);
    EXPECT_TRUE(sameBits(a.world.width, b.world.width));
    EXPECT_TRUE(sameBits(a.world.height, b.world.height));
    EXPECT_EQ(a.world.walls, b.world.walls);
    EXPECT_TRUE(sameBits(a.world.gravity.x(), b.world.gravity.x()));
    EXPECT_TRUE(sameBits(a.world.gravity.y(), b.world.gravity.y()));
    EXPECT_TRUE(sameBits(a.world.restitution, b.world.restitution));
    EXPECT_TRUE(sameBits(a.world.friction, b.world.friction));
    EXPECT_TRUE(sameBits(a.world.tangentialRestitution, b.world.tangentialRestitution));
    EXPECT_EQ(a.solver.mode, b.solver.mode);
    EXPECT_TRUE(sameBits(a.dt, b.dt));
    EXPECT_EQ(a.solver.substeps, b.solver.substeps);
    EXPECT_EQ(a.solver.broadphase, b.solver.broadphase);
    EXPECT_EQ(a.allowOverlaps, b.allowOverlaps);
    ASSERT_EQ(a.particles.size(), b.particles.size());
    for (std::size_t i = 0; i < a.particles.size(); ++i) {
        const ParticleDef &p = a.particles[i], &q = b.particles[i];
        EXPECT_TRUE(sameBits(p.position.x(), q.position.x())) << i;
        EXPECT_TRUE(sameBits(p.position.y(), q.position.y())) << i;
        EXPECT_TRUE(sameBits(p.velocity.x(), q.velocity.x())) << i;
        EXPECT_TRUE(sameBits(p.velocity.y(), q.velocity.y())) << i;
        EXPECT_TRUE(sameBits(p.mass, q.mass)) << i;
        EXPECT_TRUE(sameBits(p.radius, q.radius)) << i;
        EXPECT_EQ(p.color, q.color) << i;
        EXPECT_TRUE(sameBits(p.angle, q.angle)) << i;
        EXPECT_TRUE(sameBits(p.angularVelocity, q.angularVelocity)) << i;
        EXPECT_TRUE(sameBits(p.inertiaFactor, q.inertiaFactor)) << i;
        EXPECT_EQ(p.fixedRotation, q.fixedRotation) << i;
    }
}

/// A fresh, empty directory under the system's temporary directory.

TEST(SceneRoundTrip, AwkwardDoublesSurviveSerializeAndParseBitForBit) {
    Scene s;
    s.name = "quotes \" and \\ backslashes\nand a newline";
    s.description = "caf\xc3\xa9";
    s.world.width = 0.1 + 0.2;  // 0.30000000000000004
    s.world.gravity = {1.0 / 3.0, -9.81};
    s.world.restitution = std::nextafter(1.0, 0.0);
    s.dt = 1.0 / 60.0;
    s.particles.push_back({.position = {0.1, 0.2},
                           .velocity = {-0.0, 5e-324},
                           .mass = 1e-300,
                           .radius = 0.05,
                           .color = {0, 128, 255}});
    s.particles.push_back({.position = {0.25, 0.2},
                           .velocity = {123456789.123456789, -1e-7},
                           .mass = 3.0,
                           .radius = 0.01});
    const Scene back = parseScene(serializeScene(s), "mem");
    expectIdentical(s, back);
    EXPECT_TRUE(std::signbit(back.particles[0].velocity.x()));  // -0.0 stays negative
}

TEST(SceneRoundTrip, SerializingTwiceGivesTheSameText) {
    const std::string once = serializeScene(defaultScene());
    EXPECT_EQ(serializeScene(parseScene(once, "mem")), once);
}

TEST(SceneRoundTrip, ARunningWorldSavedAndLoadedContinuesExactlyAsIfUninterrupted) {
    Scene start = parseScene(R"({"version": 1, "world": {"gravity": [0, 9.81], "restitution": 0.9},
        "generate": {"count": 300, "radius": 6, "speed": 200, "seed": 11}})",
                             "mem");
    World a = makeWorld(start);
    for (int k = 0; k < 50; ++k)
        a.step(start.dt);

    TempDir dir("psb-scene-test");
    const fs::path file = dir.path() / "snap.json";
    saveScene(sceneFromWorld(a, start.dt, "snap"), file);
    const Scene saved = loadScene(file);
    EXPECT_TRUE(sameBits(saved.dt, start.dt));
    World b = makeWorld(saved);
    for (int k = 0; k < 50; ++k) {
        a.step(start.dt);
        b.step(saved.dt);
    }
    const ParticleArrays &pa = a.particles(), &pb = b.particles();
    ASSERT_EQ(pa.size(), pb.size());
    for (std::size_t i = 0; i < pa.size(); ++i) {
        ASSERT_TRUE(sameBits(pa.x[i], pb.x[i]) && sameBits(pa.y[i], pb.y[i]) &&
                    sameBits(pa.vx[i], pb.vx[i]) && sameBits(pa.vy[i], pb.vy[i]))
            << "particle " << i;
    }
}

TEST(SceneRoundTrip, RotationSurvivesSerializeAndParseBitForBitAsVersion5) {
    Scene s;
    s.world.width = 10.0;
    s.world.height = 10.0;
    s.world.friction = 0.4;
    s.world.tangentialRestitution = -0.3;
    s.particles = {
        {.position = {2.0, 2.0}, .radius = 0.5, .angle = -0.1, .angularVelocity = 1e-300},
        {.position = {5.0, 2.0}, .radius = 0.5, .inertiaFactor = 0.4},
        {.position = {8.0, 2.0}, .radius = 0.5, .fixedRotation = true},
        {.position = {2.0, 6.0}, .radius = 0.5, .angularVelocity = -7.25}};
    const std::string text = serializeScene(s);
    EXPECT_NE(text.find("\"version\": 5"), std::string::npos);
    expectIdentical(parseScene(text, "mem"), s);
    // Only what differs from the defaults is written.
    EXPECT_EQ(text.find("\"inertia_factor\": 0.5"), std::string::npos);
    EXPECT_NE(text.find("\"fixed_rotation\": true"), std::string::npos);
    EXPECT_EQ(text.find("\"fixed_rotation\": false"), std::string::npos);
}

TEST(SceneRoundTrip, ASceneWithoutRotationIsWrittenAsBefore) {
    // No rotation key and the version the scene had: an older build reads it.
    Scene s;
    s.particles = {{.position = {20.0, 20.0}, .radius = 1.0}};
    s.world.friction = 0.3;
    const std::string text = serializeScene(s);
    EXPECT_NE(text.find("\"version\": 1"), std::string::npos);
    for (const char* key : {"angle", "angular_velocity", "inertia_factor", "fixed_rotation",
                            "tangential_restitution"}) {
        EXPECT_EQ(text.find(key), std::string::npos) << key;
    }
}

TEST(SceneRoundTrip, ARollingWorldSavedAndLoadedContinuesExactlyAsIfUninterrupted) {
    // Friction and spin, in every mode: angles and angular velocities are state, saved to the
    // bit.
    for (const StepMode mode : {StepMode::Discrete, StepMode::Exact}) {
        Scene start = parseScene(R"({"version": 5,
            "world": {"gravity": [0, 9.81], "restitution": 0.5, "friction": 0.4,
                      "tangential_restitution": 0.2},
            "generate": {"count": 200, "radius": 6, "speed": 200, "seed": 12}})",
                                 "mem");
        start.solver.mode = mode;
        for (std::size_t i = 0; i < start.particles.size(); i += 3)
            start.particles[i].angularVelocity = 5.0;
        World a = makeWorld(start);
        for (int k = 0; k < 50; ++k)
            a.step(start.dt);
        const Scene saved = parseScene(serializeScene(sceneFromWorld(a, start.dt, "snap")), "mem");
        World b = makeWorld(saved);
        // The exact mode carries its event state, which a loaded world rebuilds: compare with a
        // copy of `a` rebuilt the same way (any change makes it rebuild).
        a.setTangentialRestitution(0.2);
        for (int k = 0; k < 50; ++k) {
            a.step(start.dt);
            b.step(saved.dt);
        }
        const ParticleArrays &pa = a.particles(), &pb = b.particles();
        ASSERT_EQ(pa.size(), pb.size());
        ASSERT_TRUE(pb.rotation);
        for (std::size_t i = 0; i < pa.size(); ++i) {
            ASSERT_TRUE(sameBits(pa.x[i], pb.x[i]) && sameBits(pa.vx[i], pb.vx[i]) &&
                        sameBits(pa.omega[i], pb.omega[i]) && sameBits(pa.angle[i], pb.angle[i]))
                << toString(mode) << " particle " << i;
        }
    }
}

TEST(SceneRoundTrip, ASavedWorldListsItsParticlesInNumberOrder) {
    // Particles 1..5 with mass k kg; 2 removed (the last one moves into its place in storage):
    // the scene lists 1, 3, 4, 5, which open as 1..4 in that order.
    World w;
    std::vector<ParticleId> ids;
    for (int k = 1; k <= 5; ++k)
        ids.push_back(w.add({.position = {10.0 * k, 5.0}, .mass = double(k)}));
    w.remove(ids[1]);
    const Scene s = sceneFromWorld(w, Scene{}.dt);
    ASSERT_EQ(s.particles.size(), 4u);
    const double masses[] = {1.0, 3.0, 4.0, 5.0};
    for (std::size_t i = 0; i < 4; ++i)
        EXPECT_EQ(s.particles[i].mass, masses[i]) << i;
    const World reopened = makeWorld(s);
    EXPECT_EQ(reopened.get(reopened.ids()[3]).mass, 5.0);
    EXPECT_EQ(particleNumber(reopened.ids()[3]), 4u);
}

TEST(SceneRoundTrip, ASnapshotWithOverlapsIsMarkedSoThatItLoads) {
    World w;
    w.add({.position = {100.0, 100.0}, .radius = 10.0});
    w.add({.position = {105.0, 100.0}, .radius = 10.0});
    const Scene s = sceneFromWorld(w, Scene{}.dt);
    EXPECT_TRUE(s.allowOverlaps);
    EXPECT_EQ(parseScene(serializeScene(s), "mem").particles.size(), 2u);
    World apart;
    apart.add({.position = {100.0, 100.0}, .radius = 10.0});
    EXPECT_FALSE(sceneFromWorld(apart, Scene{}.dt).allowOverlaps);
}

TEST(SceneRoundTrip, ASnapshotWithAParticleOverAnObstacleIsMarkedSoThatItLoads) {
    // An obstacle drawn over a particle in the app, or a particle resting on a peg with the
    // discrete mode's small overlap: the save must load again.
    World w;
    w.add({.position = {100.0, 100.0}, .radius = 10.0});
    w.addObstacle(Obstacle::segment({50.0, 105.0}, {150.0, 105.0}, 4.0));
    const Scene s = sceneFromWorld(w, Scene{}.dt);
    EXPECT_TRUE(s.allowOverlaps);
    EXPECT_EQ(parseScene(serializeScene(s), "mem").world.obstacles.size(), 1u);
    World clear;
    clear.add({.position = {100.0, 100.0}, .radius = 10.0});
    clear.addObstacle(Obstacle::peg({100.0, 200.0}, 5.0));
    EXPECT_FALSE(sceneFromWorld(clear, Scene{}.dt).allowOverlaps);
}

TEST(SceneRoundTrip, MakeWorldKeepsTheSceneOrderAndSettings) {
    const Scene s = defaultScene();
    const World w = makeWorld(s);
    ASSERT_EQ(w.size(), s.particles.size());
    EXPECT_EQ(w.def().width, s.world.width);
    EXPECT_EQ(w.solver().mode, s.solver.mode);
    EXPECT_EQ(w.solver().substeps, s.solver.substeps);
    EXPECT_EQ(sceneFromWorld(w, s.dt).dt, s.dt);  // the frame length is the scene's
    for (std::size_t i = 0; i < s.particles.size(); ++i) {
        EXPECT_EQ(w.particles().x[i], s.particles[i].position.x());
        EXPECT_EQ(w.particles().mass[i], s.particles[i].mass);
    }
}

TEST(SceneSave, ReplacesTheFileAndLeavesNoTemporaryBehind) {
    TempDir dir("psb-scene-test");
    const fs::path file = dir.path() / "scene.json";
    saveScene(defaultScene(), file);
    Scene other = defaultScene();
    other.name = "second";
    saveScene(other, file);
    EXPECT_EQ(loadScene(file).name, "second");
    EXPECT_EQ(std::distance(fs::directory_iterator(dir.path()), fs::directory_iterator{}), 1);
}

TEST(SceneSave, AMissingDirectoryIsReportedAndNothingIsCreated) {
    TempDir dir("psb-scene-test");
    const fs::path file = dir.path() / "missing" / "scene.json";
    try {
        saveScene(defaultScene(), file);
        FAIL();
    } catch (const SaveError& e) {
        EXPECT_EQ(std::string(e.what()), "cannot save " + file.string() + ": directory " +
                                             (dir.path() / "missing").string() + " does not exist");
    }
    EXPECT_FALSE(fs::exists(dir.path() / "missing"));
}

TEST(SceneSave, ADirectoryInTheWayIsReportedAndLeftAlone) {
    TempDir dir("psb-scene-test");
    const fs::path file = dir.path() / "scene.json";
    fs::create_directory(file);
    try {
        saveScene(defaultScene(), file);
        FAIL();
    } catch (const SaveError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "cannot save " + file.string() + ": a directory is in the way");
    }
    EXPECT_TRUE(fs::is_directory(file));
}

TEST(SceneSave, AParentThatIsAFileIsReported) {
    TempDir dir("psb-scene-test");
    std::ofstream(dir.path() / "plain") << "x";
    const fs::path file = dir.path() / "plain" / "scene.json";
    try {
        saveScene(defaultScene(), file);
        FAIL();
    } catch (const SaveError& e) {
        EXPECT_EQ(std::string(e.what()), "cannot save " + file.string() + ": " +
                                             (dir.path() / "plain").string() +
                                             " is not a directory");
    }
    EXPECT_EQ(readFile(dir.path() / "plain"), "x");
}

TEST(SceneSave, NoPermissionLeavesTheOldFileIntact) {
    if (::geteuid() == 0) GTEST_SKIP() << "root ignores directory permissions";
    TempDir dir("psb-scene-test");
    const fs::path file = dir.path() / "scene.json";
    saveScene(defaultScene(), file);
    const std::string before = readFile(file);
    fs::permissions(dir.path(), fs::perms::owner_read | fs::perms::owner_exec);
    Scene other = defaultScene();
    other.name = "must not be written";
    try {
        saveScene(other, file);
        FAIL();
    } catch (const SaveError& e) {
        EXPECT_EQ(std::string(e.what()), "cannot save " + file.string() +
                                             ": cannot create a temporary file in " +
                                             dir.path().string() + " (Permission denied)");
    }
    fs::permissions(dir.path(), fs::perms::owner_all);
    EXPECT_EQ(readFile(file), before);
    EXPECT_EQ(std::distance(fs::directory_iterator(dir.path()), fs::directory_iterator{}), 1);
}

TEST(SceneSave, AWriteThatFailsHalfwayLeavesTheOldFileIntactAndNoTemporary) {
    // A file-size limit makes write(2) fail part way, as a full disk would, even for root.
    TempDir dir("psb-scene-test");
    const fs::path file = dir.path() / "scene.json";
    saveScene(defaultScene(), file);
    const std::string before = readFile(file);

    Scene big = defaultScene();
    big.particles.resize(2000, big.particles[0]);
    rlimit old{};
    ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &old), 0);
    rlimit small = old;
    small.rlim_cur = 4096;
    const auto oldHandler = std::signal(SIGXFSZ, SIG_IGN);  // get EFBIG, not a signal
    ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &small), 0);
    std::string message;
    try {
        saveScene(big, file);
    } catch (const SaveError& e) {
        message = e.what();
    }
    ::setrlimit(RLIMIT_FSIZE, &old);
    std::signal(SIGXFSZ, oldHandler);

    EXPECT_EQ(message, "cannot save " + file.string() + ": write failed (File too large)");
    EXPECT_EQ(readFile(file), before);
    EXPECT_EQ(std::distance(fs::directory_iterator(dir.path()), fs::directory_iterator{}), 1);
}

TEST(SceneSave, ADirectoryThatRefusesNewFilesIsReportedEvenForRoot) {
    // /proc accepts no new files, whoever asks; the reason comes from the system.
    try {
        saveScene(defaultScene(), "/proc/psb-scene.json");
        FAIL();
    } catch (const SaveError& e) {
        const std::string prefix =
            "cannot save /proc/psb-scene.json: cannot create a temporary file in /proc (";
        EXPECT_EQ(std::string(e.what()).substr(0, prefix.size()), prefix) << e.what();
    }
}

TEST(SceneSave, ANonFiniteValueIsRefusedBeforeTheFileIsTouched) {
    TempDir dir("psb-scene-test");
    const fs::path file = dir.path() / "scene.json";
    saveScene(defaultScene(), file);
    const std::string before = readFile(file);
    Scene bad = defaultScene();
    bad.particles[2].velocity.x() = std::numeric_limits<double>::quiet_NaN();
    try {
        saveScene(bad, file);
        ADD_FAILURE() << "a NaN velocity was written";
    } catch (const SaveError& e) {
        // The refusal names the particle by its place in the file.
        EXPECT_NE(std::string(e.what()).find(": particles[2].vx is not finite"), std::string::npos)
            << e.what();
    }
    EXPECT_EQ(readFile(file), before);
    // The frame length too, named by its place in the file.
    Scene badDt = defaultScene();
    badDt.dt = std::numeric_limits<double>::quiet_NaN();
    try {
        (void)serializeScene(badDt);
        ADD_FAILURE() << "a NaN dt was written";
    } catch (const InvalidArgument& e) {
        EXPECT_STREQ(e.what(), "solver.dt is not finite");
    }
    EXPECT_THROW(saveScene(badDt, file), SaveError);
    EXPECT_EQ(readFile(file), before);
}

}  // namespace
}  // namespace psb
