// Soak: a long run of the gas preset in every step mode, the invariants checked after every
// step. Each mode runs kParticleSteps = 10^7 particle-steps (particles × steps), so a defect
// that shows once in millions of collisions (a pair resolved into NaN, a particle pushed
// through a wall, energy creeping up through the overlap correction) has its chance to show.
//
// Invariants: every coordinate and velocity finite; every particle inside the box (walls are
// on); the particle count constant; kinetic energy never above its initial value by more than
// 1e-9 relative (e = 1, no gravity).
//
// The preset runs as it is: 4000 particles for 2500 steps. kStride keeps every k-th particle
// instead (N = 4000 / kStride for 10^7 / N steps), for a core whose broadphase is only
// all-pairs (O(N²) per step: kStride = 2 took about a minute there).
// Labelled `soak` (tests/CMakeLists.txt); docs/testing.md has the timings.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>

#include <particle_sandbox/diagnostics.hpp>
#include <particle_sandbox/scene.hpp>
#include <particle_sandbox/world.hpp>

namespace psb {
namespace {

constexpr std::uint64_t kParticleSteps = 10'000'000;
constexpr std::size_t kStride = 1;

struct SoakMode {
    const char* name;
    SolverSettings solver;
    friend void PrintTo(const SoakMode& m, std::ostream* os) { *os << m.name; }
};

/// The gas preset, thinned to every kStride-th particle if kStride > 1 (the generator's sites
/// are sorted, so the kept ones still fill the box), stepped with `mode`'s solver.
Scene gasScene(const SolverSettings& solver) {
    Scene scene = loadScene(std::filesystem::path(PSB_ASSETS_DIR) / "scenes/04-gas-in-a-box.json");
    std::vector<ParticleDef> kept;
    for (std::size_t i = 0; i < scene.particles.size(); i += kStride)
        kept.push_back(scene.particles[i]);
    scene.particles = kept;
    scene.solver.mode = solver.mode;
    scene.solver.substeps = solver.substeps;
    scene.solver.broadphase = solver.broadphase;
    return scene;  // dt stays the preset's
}

class Soak : public testing::TestWithParam<SoakMode> {};

TEST_P(Soak, GasPresetKeepsEveryInvariantFor1e7ParticleSteps) {
    const Scene scene = gasScene(GetParam().solver);
    World w = makeWorld(scene);
    ASSERT_TRUE(w.def().walls);
    ASSERT_TRUE(w.def().gravity.isZero(0.0));
    ASSERT_EQ(w.def().restitution, 1.0);
    const std::size_t n = w.size();
    ASSERT_GT(n, 0u);
    const std::uint64_t steps = kParticleSteps / n;
    const double width = w.def().width, height = w.def().height;
    const double k0 = kineticEnergy(w);
    ASSERT_GT(k0, 0.0);
    double kMax = k0;

    for (std::uint64_t s = 0; s < steps; ++s) {
        w.step(scene.dt);
        ASSERT_EQ(w.size(), n) << "step " << s;
        const ParticleArrays& p = w.particles();
        for (std::size_t i = 0; i < n; ++i) {
            const double x = p.x[i], y = p.y[i], r = p.radius[i];
            ASSERT_TRUE(std::isfinite(x) && std::isfinite(y) && std::isfinite(p.vx[i]) &&
                        std::isfinite(p.vy[i]))
                << "step " << s << " particle " << i;
            // The wall stage's own bound: the centre lies in [r, extent - r].
            ASSERT_TRUE(x >= r && x <= width - r && y >= r && y <= height - r)
                << "step " << s << " particle " << i << " at (" << x << ", " << y << ")";
        }
        const double k = kineticEnergy(w);
        kMax = std::max(kMax, k);
        ASSERT_LE(k, k0 * (1.0 + 1e-9)) << "step " << s << ": energy grew by " << (k - k0) / k0;
    }
    RecordProperty("particles", static_cast<int>(n));
    RecordProperty("steps", static_cast<int>(steps));
    RecordProperty("collisions", std::to_string(w.counters().collisions));
    RecordProperty("max_relative_energy_gain", std::to_string((kMax - k0) / k0));
    EXPECT_GT(w.counters().collisions, 0u) << "a gas that never collides tests nothing";
}

std::string soakName(const testing::TestParamInfo<SoakMode>& info) {
    std::string name = info.param.name;
    name[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(name[0])));
    return name;
}

// One line per step mode; the broadphase is the one the core picks for the preset.
const SoakMode kModes[] = {
    {"discrete", {.mode = StepMode::Discrete}},
    {"substep", {.mode = StepMode::Substep, .substeps = 4}},
    {"exact", {.mode = StepMode::Exact}},
};
INSTANTIATE_TEST_SUITE_P(Modes, Soak, testing::ValuesIn(kModes), soakName);

}  // namespace
}  // namespace psb
