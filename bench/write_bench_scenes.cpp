// Writes the exact mode's mixed-size benchmark scenes as scene files, so that any particle-sim
// (this version or an older one) can run them:
//
//   build/bench/write-bench-scenes DIR
//   particle-sim DIR/mixed-big30.json -d 20 --dt 20
//
// Made with the core's scene builders, with the same arguments as exact_gas_bench's
// BM_ExactMixedSizes: 4000 discs of radius 1 m at packing 0.2 alone (mixed-none), with one disc
// of radius 10 or 30 m (mixed-big10, mixed-big30; areal density 1 kg/m² like the small ones,
// so R² kg), or with radii log-uniform from 1 to 10 m (mixed-1to10). All in exact mode.

#include <cstdio>
#include <filesystem>
#include <string>

#include <particle_sandbox/scene.hpp>
#include <particle_sandbox/scene_builders.hpp>

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: write-bench-scenes DIR\n");
        return 2;
    }
    const std::filesystem::path dir = argv[1];
    std::filesystem::create_directories(dir);
    const auto write = [&](psb::Scene s, const std::string& name) {
        s.solver.mode = psb::StepMode::Exact;
        s.name = name;
        s.trails.clear();  // a view property older readers do not know
        psb::saveScene(s, dir / (name + ".json"));
    };
    write(psb::scenes::gas({.count = 4000, .radius = 1.0, .packing = 0.2, .seed = 3}),
          "mixed-none");
    write(psb::scenes::brownian({.count = 4000, .bigRadius = 10.0, .bigMass = 100.0, .seed = 3}),
          "mixed-big10");
    write(psb::scenes::brownian({.count = 4000, .bigRadius = 30.0, .bigMass = 900.0, .seed = 3}),
          "mixed-big30");
    write(psb::scenes::gas(
              {.count = 4000, .radius = 1.0, .maxRadius = 10.0, .packing = 0.2, .seed = 3}),
          "mixed-1to10");
    return 0;
}
