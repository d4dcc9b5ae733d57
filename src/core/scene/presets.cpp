// Scenes built in code, and the list of preset files.

#include <particle_sandbox/presets.hpp>

#include <algorithm>
#include <system_error>

namespace psb {

Scene defaultScene() {
    Scene s;
    s.name = "The original's default";
    s.description =
        "A handful of particles in a 7 m box with walls, no gravity and perfectly elastic "
        "collisions (e = 1): the original program's opening scene at 1 pixel = 1 cm, mass "
        "3..20 kg, radius 2.5 cm per kg, speeds up to 3 m/s. Kinetic energy stays constant; "
        "momentum changes only when a particle bounces off a wall.";
    s.world = WorldDef{};
    s.world.width = 7.0;  // the original's 700-pixel window at 1 px = 1 cm
    s.world.height = 7.0;
    s.solver.mode = StepMode::Discrete;
    s.dt = 1.0 / 60.0;  // the original's frame
    s.solver.substeps = 1;
    s.solver.broadphase = BroadPhaseKind::Auto;
    struct Seed {
        double x, y, vx, vy, mass, radius;  // radius 2.5 cm per kg, written out exactly
        Color color;
    };
    // Positions in metres (the original's pixels / 100); velocities are the original's
    // per-frame integers (-5..5 px/frame) times 60 frames/s, in m/s at 1 px = 1 cm.
    constexpr Seed kSeeds[] = {
        {1.5, 1.2, 1.8, 1.2, 12.0, 0.3, {230, 120, 140}},
        {3.2, 0.9, -2.4, 0.6, 5.0, 0.125, {120, 200, 255}},
        {5.2, 1.6, -0.6, 2.4, 18.0, 0.45, {255, 210, 110}},
        {2.5, 2.6, 3.0, -1.8, 8.0, 0.2, {150, 255, 160}},
        {4.3, 3.0, -1.2, -3.0, 3.0, 0.075, {210, 150, 255}},
        {6.0, 3.3, 0.0, -1.2, 15.0, 0.375, {255, 160, 100}},
    };
    for (const Seed& k : kSeeds) {
        s.particles.push_back(ParticleDef{.position = {k.x, k.y},
                                          .velocity = {k.vx, k.vy},
                                          .mass = k.mass,
                                          .radius = k.radius,
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
