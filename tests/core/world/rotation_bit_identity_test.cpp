// Rotation is modelled only where a scene needs it: a scene without friction and without spin
// steps exactly as it did before discs could turn, bit for bit, in every mode.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <particle_sandbox/scene.hpp>
#include <particle_sandbox/world.hpp>

#include "test_util.hpp"
#include "world_checks.hpp"

namespace psb {
namespace {

struct PresetRun {
    const char* file;  ///< a preset of assets/scenes without friction
    StepMode mode;
    std::uint64_t hash;  ///< stateHash after kSteps steps of the scene's dt
};

constexpr int kSteps = 60;

World runPreset(const std::string& file, StepMode mode) {
    Scene s = loadScene(std::filesystem::path(PSB_ASSETS_DIR) / "scenes" / file);
    s.solver.mode = mode;
    s.solver.substeps = mode == StepMode::Substep ? 4 : 1;
    World w = makeWorld(s);
    w.setThreads(1);
    for (int k = 0; k < kSteps; ++k)
        w.step(s.dt);
    return w;
}

/// The preset with one more disc near its top-left corner, spinning when `spin`: rotation state
/// that no frictionless contact can read, so the world keeps rotation arrays and turns that
/// disc, and must move everything exactly as without.
World runPresetWithExtraDisc(const std::string& file, StepMode mode, bool spin) {
    Scene s = loadScene(std::filesystem::path(PSB_ASSETS_DIR) / "scenes" / file);
    s.solver.mode = mode;
    s.solver.substeps = mode == StepMode::Substep ? 4 : 1;
    World w = makeWorld(s);
    w.setThreads(1);
    ParticleDef extra;
    extra.radius = 0.02 * s.world.width;
    extra.position = Vec2(0.1 * s.world.width, 0.1 * s.world.height);
    extra.velocity = Vec2(0.3, 0.2);
    if (spin) {
        extra.angularVelocity = 3.0;
        extra.inertiaFactor = 0.4;
    }
    w.add(extra);
    for (int k = 0; k < kSteps; ++k)
        w.step(s.dt);
    return w;
}

// The hashes of these runs before rotation existed (the same code on the commit this work
// started from): a frictionless scene must not move by one bit.
TEST(RotationBitIdentity, FrictionlessPresetsStepAsBeforeRotationInEveryMode) {
    const std::vector<PresetRun> runs = {
        {"01-original.json", StepMode::Discrete, 0x787c5b4d02509841ull},
        {"01-original.json", StepMode::Substep, 0x6e5a87dae9992a3cull},
        {"01-original.json", StepMode::Exact, 0x6e5f0ea4f86863c8ull},
        {"02-newtons-cradle.json", StepMode::Discrete, 0x1d56806b038dce99ull},
        {"02-newtons-cradle.json", StepMode::Substep, 0x375e6ef52b6735cdull},
        {"02-newtons-cradle.json", StepMode::Exact, 0x6ae91791d41bc90aull},
        {"03-billiards-break.json", StepMode::Discrete, 0x4954222df00ced71ull},
        {"03-billiards-break.json", StepMode::Substep, 0x74557d535cdf8f34ull},
        {"03-billiards-break.json", StepMode::Exact, 0x23ab990f254e7104ull},
        {"04-gas-in-a-box.json", StepMode::Discrete, 0x3afc7902e124a109ull},
        {"04-gas-in-a-box.json", StepMode::Substep, 0x61d9f80ad4717594ull},
        {"04-gas-in-a-box.json", StepMode::Exact, 0x637fa9e73eed2340ull},
        {"09-galton-board.json", StepMode::Discrete, 0x63f7aef4093a1212ull},
        {"09-galton-board.json", StepMode::Substep, 0x32d4131e0aeb5f7cull},
        {"09-galton-board.json", StepMode::Exact, 0x1db877a1ce690599ull},
        {"13-basketball-and-tennis-ball.json", StepMode::Discrete, 0xbedfa50a9cfb7e81ull},
        {"13-basketball-and-tennis-ball.json", StepMode::Substep, 0x589fbdfa8c4c8c34ull},
        {"13-basketball-and-tennis-ball.json", StepMode::Exact, 0x655e7bea485550c0ull},
    };
    for (const PresetRun& run : runs) {
        const World w = runPreset(run.file, run.mode);
        const std::uint64_t h = test::stateHash(w);
        EXPECT_EQ(h, run.hash) << "{\"" << run.file << "\", StepMode::"
                               << (run.mode == StepMode::Discrete  ? "Discrete"
                                   : run.mode == StepMode::Substep ? "Substep"
                                                                   : "Exact")
                               << ", 0x" << std::hex << h << "ull},";
    }
}

World runPresetFixed(const std::string& file, StepMode mode) {
    // The five-ball ramp the ramp preset was before it raced a ball, a disc and a block is kept
    // in the loader's good corpus.
    Scene s = file == "ramp_five_balls.json"
                  ? test::corpusScene(file)
                  : loadScene(std::filesystem::path(PSB_ASSETS_DIR) / "scenes" / file);
    s.solver.mode = mode;
    s.solver.substeps = mode == StepMode::Substep ? 4 : 1;
    // Every particle set not to turn, as every particle was before rotation existed.
    for (ParticleDef& d : s.particles)
        d.fixedRotation = true;
    World w = makeWorld(s);
    w.setThreads(1);
    for (int k = 0; k < kSteps; ++k)
        w.step(s.dt);
    return w;
}

// Friction scenes whose discs do not turn (fixed rotation) and tangential restitution 0: the
// rough contacts reduce, bit for bit, to the friction of discs before rotation existed.
TEST(RotationBitIdentity, FrictionPresetsOfDiscsThatDoNotTurnStepAsBeforeRotation) {
    const std::vector<PresetRun> runs = {
        {"07-pile-under-gravity.json", StepMode::Discrete, 0xbf2d22ef7a1b20feull},
        {"07-pile-under-gravity.json", StepMode::Substep, 0x508c11263843a6e0ull},
        {"07-pile-under-gravity.json", StepMode::Exact, 0xbd6414e966f67dc2ull},
        {"10-funnel.json", StepMode::Discrete, 0xb3acd938cdef3baeull},
        {"10-funnel.json", StepMode::Substep, 0x9ed1d4860e407535ull},
        {"10-funnel.json", StepMode::Exact, 0x734bd73deee4638full},
        {"ramp_five_balls.json", StepMode::Discrete, 0x6cccb7f04492d8c7ull},
        {"ramp_five_balls.json", StepMode::Substep, 0x69d23e464a5354acull},
        {"ramp_five_balls.json", StepMode::Exact, 0x31dc7ea40633055aull},
    };
    for (const PresetRun& run : runs) {
        const World w = runPresetFixed(run.file, run.mode);
        const std::uint64_t h = test::stateHash(w);
        EXPECT_EQ(h, run.hash) << "{\"" << run.file << "\", StepMode::"
                               << (run.mode == StepMode::Discrete  ? "Discrete"
                                   : run.mode == StepMode::Substep ? "Substep"
                                                                   : "Exact")
                               << ", 0x" << std::hex << h << "ull},";
    }
}

TEST(RotationBitIdentity, SpinWithoutFrictionLeavesEveryCentreAndVelocityAlone) {
    for (const StepMode mode : {StepMode::Discrete, StepMode::Substep, StepMode::Exact}) {
        for (const char* file : {"04-gas-in-a-box.json", "09-galton-board.json"}) {
            SCOPED_TRACE(file);
            const World plain = runPresetWithExtraDisc(file, mode, false);
            const World turning = runPresetWithExtraDisc(file, mode, true);
            EXPECT_FALSE(plain.rotationInUse());
            ASSERT_TRUE(turning.rotationInUse());
            EXPECT_EQ(test::stateHash(plain), test::stateHash(turning));
            // Every disc turned freely: no contact without friction changes a spin.
            const ParticleArrays& p = turning.particles();
            double spin = 0.0;
            for (std::size_t i = 0; i < p.size(); ++i)
                spin += std::abs(p.omega[i]);
            EXPECT_EQ(spin, 3.0);
        }
    }
}

}  // namespace
}  // namespace psb
