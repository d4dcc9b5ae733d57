// Leaks of the discrete mode through fixed obstacles, on the Galton board preset
// (assets/scenes/09-galton-board.json: 1000 balls from its dropper, 108 pegs, 14 bin walls), by
// step size. Balls a dropper releases are followed from the step they appear in; the preset's
// dropper empties in 50 s, so `--duration 56` runs it to its end.
//
// A leak is a ball whose centre, between the end of one step and the end of the next, crosses
// the core line of a segment (between its ends), or whose centre ends a step inside an
// obstacle's solid (closer to its core than the obstacle's own radius or half-thickness). Each
// ball is counted once, however often it leaks. The check reads only positions after each step
// (World's public state) and tests every ball against every obstacle with geometry of its own,
// so that it checks the engine's obstacle stage rather than repeating it.
//
//   build/release/bench/galton-leaks [--duration S] [--mode discrete|substep|exact] [--bins]
//                                    [--scene PATH] [dt ...]
//
// Prints a Markdown table: dt, steps, leaking balls, leak events, balls in the bins at the end,
// the deepest overlap between two balls, wall seconds. Defaults: 6 s, the discrete mode and
// dt = 0.001 (the scene's) to 0.016 s. In the exact mode dt changes only how often positions
// are checked (the trajectory does not depend on it); its default there is 0.01 s. --bins also
// prints the count in each bin at the end and the standard deviation of the binned balls' x,
// and for a scene with bins its own counts and their chi-squared test (psb::measureBins).
// --scene PATH runs another board than the preset.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <unordered_set>
#include <vector>

#include <particle_sandbox/bins.hpp>
#include <particle_sandbox/scene.hpp>

namespace {

/// Distance from (x, y) to the obstacle's core: a peg's centre, or the segment from a to b.
double coreDistance(const psb::Obstacle& o, double x, double y) {
    const double ex = o.b.x() - o.a.x(), ey = o.b.y() - o.a.y();
    const double len2 = ex * ex + ey * ey;
    double t = len2 > 0.0 ? ((x - o.a.x()) * ex + (y - o.a.y()) * ey) / len2 : 0.0;
    t = std::clamp(t, 0.0, 1.0);
    return std::hypot(x - (o.a.x() + t * ex), y - (o.a.y() + t * ey));
}

/// Whether the move from (x0, y0) to (x1, y1) and a segment's core cross (each ends strictly on
/// either side of the other's line).
bool crossesCore(const psb::Obstacle& o, double x0, double y0, double x1, double y1) {
    if (o.isPeg()) return false;
    const auto side = [](double ax, double ay, double bx, double by, double px, double py) {
        return (bx - ax) * (py - ay) - (by - ay) * (px - ax);
    };
    const double s0 = side(o.a.x(), o.a.y(), o.b.x(), o.b.y(), x0, y0);
    const double s1 = side(o.a.x(), o.a.y(), o.b.x(), o.b.y(), x1, y1);
    const double e0 = side(x0, y0, x1, y1, o.a.x(), o.a.y());
    const double e1 = side(x0, y0, x1, y1, o.b.x(), o.b.y());
    return s0 * s1 < 0.0 && e0 * e1 <= 0.0;
}

struct Result {
    std::uint64_t steps = 0, leakers = 0, events = 0, inBins = 0;
    std::vector<int> bins;  // balls between consecutive bin walls (and the box walls), left first
    double spread = 0.0;    // standard deviation of the binned balls' x, metres
    double seconds = 0.0, maxOverlap = 0.0;
    std::optional<psb::BinsMeasurement> sceneBins;  // the scene's own bins, if it has them
};

Result run(const psb::Scene& scene, psb::StepMode mode, double dt, double duration) {
    psb::Scene s = scene;
    s.dt = dt;
    s.solver.mode = mode;
    psb::World w = psb::makeWorld(s);
    w.setThreads(1);
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
    const auto steps = static_cast<std::uint64_t>(std::llround(duration / dt));
    double stepSeconds = 0.0;
    for (std::uint64_t k = 0; k < steps; ++k) {
        const auto t0 = std::chrono::steady_clock::now();
        w.step(dt);
        stepSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        // Balls a dropper released in this step start where they appeared.
        if (w.size() > ids.size()) {
            const std::unordered_set<psb::ParticleId> known(ids.begin(), ids.end());
            for (const psb::ParticleId id : w.ids()) {
                if (known.count(id)) continue;
                ids.push_back(id);
                leaked.push_back(0);
                const psb::Vec2 p = w.get(id).position;
                px.push_back(p.x());
                py.push_back(p.y());
            }
            qx.resize(px.size());
            qy.resize(py.size());
        }
        positions(qx, qy);
        for (std::size_t i = 0; i < ids.size(); ++i) {
            for (const psb::Obstacle& o : obstacles) {
                const bool inside = coreDistance(o, qx[i], qy[i]) < o.radius;
                if (inside || crossesCore(o, px[i], py[i], qx[i], qy[i])) {
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
    std::vector<double> walls{0.0};
    for (const psb::Obstacle& o : obstacles)
        if (!o.isPeg() && o.a.x() == o.b.x()) walls.push_back(o.a.x());
    walls.push_back(w.def().width);
    std::sort(walls.begin(), walls.end());
    r.bins.assign(walls.size() - 1, 0);
    double sum = 0.0, sum2 = 0.0;
    for (std::size_t i = 0; i < ids.size(); ++i) {
        if (!(py[i] > binsTop)) continue;
        ++r.inBins;
        const auto k = std::upper_bound(walls.begin(), walls.end(), px[i]) - walls.begin() - 1;
        ++r.bins[static_cast<std::size_t>(std::clamp<std::ptrdiff_t>(k, 0, r.bins.size() - 1))];
        sum += px[i];
        sum2 += px[i] * px[i];
    }
    if (s.bins) r.sceneBins = psb::measureBins(*s.bins, w.particles());
    if (r.inBins > 1) {
        const double n = static_cast<double>(r.inBins);
        r.spread = std::sqrt(std::max(0.0, (sum2 - sum * sum / n) / (n - 1.0)));
    }
    return r;
}

}  // namespace

int main(int argc, char** argv) {
    double duration = 6.0;
    psb::StepMode mode = psb::StepMode::Discrete;
    bool bins = false;
    std::string scenePath = std::string(PSB_SOURCE_DIR) + "/assets/scenes/09-galton-board.json";
    std::vector<double> dts;
    for (int k = 1; k < argc; ++k) {
        const std::string a = argv[k];
        if (a == "--duration" && k + 1 < argc) {
            duration = std::atof(argv[++k]);
        } else if (a == "--scene" && k + 1 < argc) {
            scenePath = argv[++k];
        } else if (a == "--bins") {
            bins = true;
        } else if (a == "--mode" && k + 1 < argc) {
            const std::optional<psb::StepMode> m = psb::parseStepMode(argv[++k]);
            if (!m) {
                std::fprintf(stderr, "galton-leaks: --mode: unknown mode '%s'\n", argv[k]);
                return 2;
            }
            mode = *m;
        } else {
            dts.push_back(std::atof(argv[k]));
        }
    }
    if (dts.empty()) {
        dts = mode == psb::StepMode::Exact ? std::vector<double>{0.01}
                                           : std::vector<double>{0.001, 0.002, 0.004, 0.008, 0.016};
    }
    const psb::Scene scene = psb::loadScene(scenePath);
    std::printf(
        "| dt (ms) | steps | balls that leaked | leak events | balls in the bins | max "
        "ball overlap (mm) | step wall s |\n|---:|---:|---:|---:|---:|---:|---:|\n");
    for (const double dt : dts) {
        const Result r = run(scene, mode, dt, duration);
        std::printf("| %g | %llu | %llu | %llu | %llu | %.2f | %.2f |\n", dt * 1e3,
                    static_cast<unsigned long long>(r.steps),
                    static_cast<unsigned long long>(r.leakers),
                    static_cast<unsigned long long>(r.events),
                    static_cast<unsigned long long>(r.inBins), r.maxOverlap * 1e3, r.seconds);
        std::fflush(stdout);
        if (bins) {
            std::printf("bins (left to right):");
            for (const int b : r.bins)
                std::printf(" %d", b);
            std::printf("; spread of x %.1f mm\n", r.spread * 1e3);
            if (const auto& m = r.sceneBins) {
                std::printf("scene bins:");
                for (const std::size_t c : m->counts.counts)
                    std::printf(" %zu", c);
                std::printf(" (%zu outside, %zu above)", m->counts.outside, m->counts.above);
                if (m->test && m->test->valid()) {
                    std::printf("; chi-squared %.2f on %d dof, 1 %% critical %.2f: %s",
                                m->test->statistic, m->test->dof, m->test->critical,
                                m->test->passes() ? "passes" : "fails");
                }
                std::printf("\n");
            }
        }
    }
    return 0;
}
