// The exact mode on a granular scene over time: events, collisions of each kind and CPU time per
// simulated second, and how many particles have passed a line, in frames of 1/60 s as the app
// steps it (docs/exact-gravity.md, "Sliding and hops, measured").
//
//   build/release/bench/exact-flow SCENE [--duration S] [--every S] [--below Y] [--mode M]
//
// Prints a Markdown table, one row per --every seconds of simulated time (default 0.5 s of
// 2 s): events, obstacle, pair and wall collisions per simulated second, CPU seconds per
// simulated second, and the particles whose centre is below y = Y (y grows downwards; the
// neck of a funnel or an hourglass), then a line of totals. Another pour of a preset: a copy
// with another "seed" in its generate block. --mode discrete or substep runs the same scene in
// that mode instead, in steps of the scene's own dt (its substeps for the substep mode), for
// the particles below Y and the CPU time to compare with (events are then steps' collisions).

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <optional>
#include <string>

#include <particle_sandbox/scene.hpp>
#include <particle_sandbox/scene_builders.hpp>
#include <particle_sandbox/solver_settings.hpp>
#include <particle_sandbox/world.hpp>

namespace {

double cpuSeconds() {
    return static_cast<double>(std::clock()) / CLOCKS_PER_SEC;
}

bool number(const char* text, double& out) {
    char* end = nullptr;
    out = std::strtod(text, &end);
    return end != text && *end == '\0';
}

}  // namespace

int main(int argc, char** argv) {
    double duration = 2.0, every = 0.5, below = 1e300;
    const char* path = nullptr;
    psb::StepMode mode = psb::StepMode::Exact;
    for (int k = 1; k < argc; ++k) {
        const std::string arg = argv[k];
        if (arg == "--mode") {
            const auto parsed = k + 1 < argc ? psb::parseStepMode(argv[k + 1]) : std::nullopt;
            if (!parsed) {
                std::fprintf(stderr, "exact-flow: --mode needs discrete, substep or exact\n");
                return 2;
            }
            mode = *parsed;
            ++k;
            continue;
        }
        double* target = arg == "--duration" ? &duration
                         : arg == "--every"  ? &every
                         : arg == "--below"  ? &below
                                             : nullptr;
        if (target) {
            if (k + 1 == argc || !number(argv[k + 1], *target)) {
                std::fprintf(stderr, "exact-flow: %s needs a number\n", arg.c_str());
                return 2;
            }
            ++k;
        } else if (path == nullptr && arg.rfind("--", 0) != 0) {
            path = argv[k];
        } else {
            std::fprintf(stderr, "exact-flow: unknown argument '%s'\n", argv[k]);
            return 2;
        }
    }
    if (path == nullptr || !(duration > 0.0) || !(every > 0.0)) {
        std::fprintf(stderr,
                     "usage: exact-flow SCENE [--duration S] [--every S] [--below Y] [--mode M]\n");
        return 2;
    }
    psb::Scene scene;
    try {
        scene = psb::loadScene(path);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "exact-flow: %s\n", e.what());
        return 1;
    }
    scene.solver.mode = mode;
    psb::World w = psb::makeWorld(scene);
    // The exact mode in the app's frames; the others in the steps their accuracy needs.
    const double dt = mode == psb::StepMode::Exact ? 1.0 / 60.0 : scene.dt;
    const auto frames = static_cast<long>(duration / dt + 0.5);
    const auto perRow = std::max(1L, static_cast<long>(every / dt + 0.5));
    std::printf(
        "| t (s) | events/s | obstacle coll./s | pair coll./s | wall coll./s | CPU s per "
        "s | below y |\n|---:|---:|---:|---:|---:|---:|---:|\n");
    psb::StepCounters last{};
    double cpu0 = cpuSeconds(), cpuAll = 0.0;
    for (long f = 1; f <= frames; ++f) {
        w.step(dt);
        if (f % perRow != 0 && f != frames) continue;
        const double span = static_cast<double>(f % perRow == 0 ? perRow : f % perRow) * dt;
        const double cpu = cpuSeconds() - cpu0;
        cpuAll += cpu;
        const psb::StepCounters& c = w.counters();
        int past = 0;
        for (const double y : w.particles().y)
            past += y > below ? 1 : 0;
        std::printf("| %.2f | %.0f | %.0f | %.0f | %.0f | %.3f | %d |\n", f * dt,
                    (c.events - last.events) / span,
                    (c.obstacleCollisions - last.obstacleCollisions) / span,
                    (c.collisions - last.collisions) / span,
                    (c.wallCollisions - last.wallCollisions) / span, cpu / span, past);
        std::fflush(stdout);
        last = c;
        cpu0 = cpuSeconds();
    }
    const psb::StepCounters& c = w.counters();
    std::printf(
        "\ntotal: %llu events, %llu obstacle, %llu pair, %llu wall collisions, %.2f CPU s\n",
        static_cast<unsigned long long>(c.events),
        static_cast<unsigned long long>(c.obstacleCollisions),
        static_cast<unsigned long long>(c.collisions),
        static_cast<unsigned long long>(c.wallCollisions), cpuAll);
    return 0;
}
