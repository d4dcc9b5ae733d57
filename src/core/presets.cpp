// Scenes built in code, and the list of preset files.

#include <particle_sandbox/presets.hpp>

#include <algorithm>
#include <system_error>

namespace psb {

Scene defaultScene() {
    Scene s;
    s.name = "The original's default";
    s.description =
        "A handful of particles in a 700 m box with walls, no gravity and perfectly elastic "
        "collisions (e = 1), as the original program started: mass 3..20 kg, radius 2.5 m per "
        "kg, speeds up to 300 m/s. Kinetic energy and momentum stay constant.";
    s.world = WorldDef{};  // 700 × 700 m, walls, no gravity, e = 1, no friction
    s.solver.mode = StepMode::Discrete;
    s.solver.dt = 1.0 / 60.0;  // the original's frame
    s.solver.substeps = 1;
    s.solver.broadphase = BroadPhaseKind::Auto;
    struct Seed {
        double x, y, vx, vy, mass;
        Color color;
    };
    // Velocities are the original's per-frame integers (-5..5 px/frame) times 60 frames/s.
    constexpr Seed kSeeds[] = {
        {150.0, 120.0, 180.0, 120.0, 12.0, {230, 120, 140}},
        {320.0, 90.0, -240.0, 60.0, 5.0, {120, 200, 255}},
        {520.0, 160.0, -60.0, 240.0, 18.0, {255, 210, 110}},
        {250.0, 260.0, 300.0, -180.0, 8.0, {150, 255, 160}},
        {430.0, 300.0, -120.0, -300.0, 3.0, {210, 150, 255}},
        {600.0, 330.0, 0.0, -120.0, 15.0, {255, 160, 100}},
    };
    for (const Seed& k : kSeeds) {
        s.particles.push_back(ParticleDef{.position = {k.x, k.y},
                                          .velocity = {k.vx, k.vy},
                                          .mass = k.mass,
                                          .radius = 2.5 * k.mass,
                                          .color = k.color});
    }
    return s;
}

std::vector<std::filesystem::path> sceneFiles(const std::filesystem::path& directory) {
    std::vector<std::filesystem::path> files;
    std::error_code ec;
    std::filesystem::directory_iterator it(directory, ec), end;
    for (; !ec && it != end; it.increment(ec)) {
        const auto& path = it->path();
        std::error_code fileEc;
        if (path.extension() == ".json" && it->is_regular_file(fileEc)) files.push_back(path);
    }
    std::sort(files.begin(), files.end(),
              [](const auto& a, const auto& b) { return a.filename() < b.filename(); });
    return files;
}

}  // namespace psb
