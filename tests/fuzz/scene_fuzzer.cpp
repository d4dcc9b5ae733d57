// libFuzzer target for the scene loader (psb::parseScene).
//
// The property under test is the loader's contract: any byte string is either a Scene or a
// SceneError whose message starts with the source name; nothing else may escape, and nothing
// may crash, hang, leak or invoke undefined behaviour (the target is built with ASan and
// UBSan). A scene that loads must also be one the rest of the program can use: World accepts
// it, it steps without producing a non-finite number, and it survives serialize/parse bit for
// bit. The expensive checks are skipped for large scenes so that the fuzzer keeps its pace.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <string_view>

#include <particle_sandbox/scene.hpp>
#include <particle_sandbox/world.hpp>

namespace {

[[noreturn]] void violated(const char* what, const std::string& detail) {
    std::fprintf(stderr, "scene_fuzzer: %s: %s\n", what, detail.c_str());
    std::abort();
}

bool sameBits(double a, double b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

void checkRoundTrip(const psb::Scene& s) {
    const psb::Scene t = psb::parseScene(psb::serializeScene(s), "round-trip");
    if (t.particles.size() != s.particles.size()) violated("round trip", "particle count");
    for (std::size_t i = 0; i < s.particles.size(); ++i) {
        const psb::ParticleDef &a = s.particles[i], &b = t.particles[i];
        if (!sameBits(a.position.x(), b.position.x()) ||
            !sameBits(a.position.y(), b.position.y()) ||
            !sameBits(a.velocity.x(), b.velocity.x()) ||
            !sameBits(a.velocity.y(), b.velocity.y()) || !sameBits(a.mass, b.mass) ||
            !sameBits(a.radius, b.radius)) {
            violated("round trip", "particle " + std::to_string(i) + " changed");
        }
    }
    if (!sameBits(t.world.width, s.world.width) || !sameBits(t.world.height, s.world.height) ||
        !sameBits(t.dt, s.dt) || t.solver.mode != s.solver.mode ||
        t.solver.substeps != s.solver.substeps || t.world.walls != s.world.walls) {
        violated("round trip", "world or solver changed");
    }
}

void checkSteps(const psb::Scene& s) {
    psb::World world = psb::makeWorld(s);
    psb::SolverSettings solver = world.solver();
    solver.substeps = std::min(solver.substeps, 4);  // the substep loop is not what is fuzzed
    world.setSolver(solver);
    for (int k = 0; k < 3; ++k)
        world.step(s.dt);
    const psb::ParticleArrays& p = world.particles();
    for (std::size_t i = 0; i < p.size(); ++i) {
        if (!std::isfinite(p.x[i]) || !std::isfinite(p.y[i]) || !std::isfinite(p.vx[i]) ||
            !std::isfinite(p.vy[i])) {
            violated("step", "particle " + std::to_string(i) + " is not finite");
        }
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    psb::Scene scene;
    try {
        scene = psb::parseScene(text, "fuzz.json");
    } catch (const psb::SceneError& e) {
        if (std::string_view(e.what()).substr(0, 11) != "fuzz.json: ") {
            violated("message does not name the source", e.what());
        }
        return 0;
    }
    if (scene.particles.size() <= 2000) checkRoundTrip(scene);
    if (scene.particles.size() <= 200) checkSteps(scene);
    return 0;
}
