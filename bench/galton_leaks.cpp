// Leaks of the discrete mode through fixed obstacles, on the Galton board preset
// (assets/scenes/09-galton-board.json: 1000 balls, 319 pegs, 26 segments), by step size.
//
// A leak is a ball whose centre, between the end of one step and the end of the next, crosses
// the core line of a segment (between its ends), or whose centre ends a step inside an
// obstacle's solid (closer to its core than the obstacle's own radius or half-thickness). Each
// ball is counted once, however often it leaks. The check reads only positions after each step
// (World's public state), through the obstacles' own grid so that it is not the slow part.
//
//   build/release/bench/galton-leaks [--duration S] [dt ...]
//
// Prints a Markdown table: dt, steps, leaking balls, leak events, balls in the bins at the end,
// the deepest overlap between two balls, wall seconds. Defaults: 6 s and dt = 0.001 (the
// scene's) to 0.016 s.

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <particle_sandbox/scene.hpp>

#include "obstacle_geometry.hpp"
#include "obstacle_grid.hpp"

namespace {

struct Result {
    std::uint64_t steps = 0, leakers = 0, events = 0, inBins = 0;
    double seconds = 0.0, maxOverlap = 0.0;
};

Result run(const psb::Scene& scene, double dt, double duration) {
    psb::Scene s = scene;
    s.solver.dt = dt;
    psb::World w = psb::makeWorld(s);
    w.setThreads(1);
    psb::ObstacleGrid grid;
    grid.build(w.obstacles());
    const psb::Obstacles& obstacles = w.obstacles();
    double binsTop = 0.0;  // the bins start where the separators (vertical segments) start
    for (const psb::Obstacle& o : obstacles)
        if (!o.isPeg() && o.a.x() == o.b.x())
            binsTop = std::max(binsTop, std::min(o.a.y(), o.b.y()));

    Result r;
    std::vector<char> leaked(w.size(), 0);
    std::vector<psb::ParticleId> ids = w.ids();
    std::vector<double> px(w.size()), py(w.size());
    auto positions = [&](std::vector<double>& xs, std::vector<double>& ys) {
        for (std::size_t k = 0; k < ids.size(); ++k) {
            const psb::Vec2 p = w.get(ids[k]).position;  // by id: storage order may change
            xs[k] = p.x();
            ys[k] = p.y();
        }
    };
    positions(px, py);
    std::vector<double> qx(px.size()), qy(py.size());
    std::vector<std::uint32_t> near;
    const auto steps = static_cast<std::uint64_t>(std::llround(duration / dt));
    double stepSeconds = 0.0;
    for (std::uint64_t k = 0; k < steps; ++k) {
        const auto t0 = std::chrono::steady_clock::now();
        w.step(w.solver().dt);
        stepSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        positions(qx, qy);
        for (std::size_t i = 0; i < ids.size(); ++i) {
            grid.query(std::min(px[i], qx[i]), std::min(py[i], qy[i]), std::max(px[i], qx[i]),
                       std::max(py[i], qy[i]), near);
            for (const std::uint32_t j : near) {
                const psb::Obstacle& o = obstacles[j];
                double cx, cy;
                psb::nearestCorePoint(o, qx[i], qy[i], cx, cy);
                const bool inside = std::hypot(qx[i] - cx, qy[i] - cy) < o.radius;
                if (inside || psb::crossesCore(o, px[i], py[i], qx[i], qy[i])) {
                    ++r.events;
                    if (!leaked[i]) {
                        leaked[i] = 1;
                        ++r.leakers;
                    }
                }
            }
        }
        std::swap(px, qx);
        std::swap(py, qy);
    }
    r.steps = steps;
    r.seconds = stepSeconds;
    r.maxOverlap = w.counters().maxOverlap;
    for (std::size_t i = 0; i < ids.size(); ++i)
        r.inBins += py[i] > binsTop;
    return r;
}

}  // namespace

int main(int argc, char** argv) {
    double duration = 6.0;
    std::vector<double> dts;
    for (int k = 1; k < argc; ++k) {
        const std::string a = argv[k];
        if (a == "--duration" && k + 1 < argc) {
            duration = std::atof(argv[++k]);
        } else {
            dts.push_back(std::atof(argv[k]));
        }
    }
    if (dts.empty()) dts = {0.001, 0.002, 0.004, 0.008, 0.016};
    const psb::Scene scene =
        psb::loadScene(std::string(PSB_SOURCE_DIR) + "/assets/scenes/09-galton-board.json");
    std::printf(
        "| dt (ms) | steps | balls that leaked | leak events | balls in the bins | max "
        "ball overlap (mm) | step wall s |\n|---:|---:|---:|---:|---:|---:|---:|\n");
    for (const double dt : dts) {
        const Result r = run(scene, dt, duration);
        std::printf("| %g | %llu | %llu | %llu | %llu | %.2f | %.2f |\n", dt * 1e3,
                    static_cast<unsigned long long>(r.steps),
                    static_cast<unsigned long long>(r.leakers),
                    static_cast<unsigned long long>(r.events),
                    static_cast<unsigned long long>(r.inBins), r.maxOverlap * 1e3, r.seconds);
        std::fflush(stdout);
    }
    return 0;
}
