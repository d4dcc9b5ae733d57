// libFuzzer target for the world's mutations: what a user does to a running world.
//
// The bytes choose a small world (box, walls, gravity, restitution, friction, step mode, pegs,
// segments, droppers, particles) and then a sequence of steps and changes made through the
// public API alone, as the app and the session make them: add, remove, move, push, resize,
// reweigh, hold and let go, spin, turn, change the inertia factor, fix the rotation and the
// tangential restitution, obstacles added and removed, laws and box changed, the mode
// switched, droppers replaced, the world copied and both copies stepped, the exact mode's
// event state dropped, everything cleared. Values are mostly sensible and sometimes hostile
// (NaN, infinities, zero, negative, huge).
//
// Properties checked (the target is built with ASan and UBSan, so any memory error or undefined
// behaviour is a finding too):
//   - a refused change throws InvalidArgument and leaves the world as it was;
//   - after every step every position and velocity is finite;
//   - with walls on, every centre is inside the box (a particle wider than the box on its centre
//     line), to rounding;
//   - in the exact mode, consecutive steps with no change between them never deepen the deepest
//     overlap by more than the mode's stated bound (docs/exact.md: 1e-9 of a radius);
//   - a copy stepped alike stays bit-identical to the original.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <fuzzer/FuzzedDataProvider.h>

#include <particle_sandbox/error.hpp>
#include <particle_sandbox/scene.hpp>
#include <particle_sandbox/world.hpp>

namespace {

using psb::Vec2;

// Bounded so that an input stays fast to fuzz; the exact mode's events are bounded per input
// too (Stepper::kAllowance).
constexpr int kMaxOps = 32;
constexpr int kMaxStepsPerOp = 3;
constexpr std::size_t kMaxParticles = 48;
// A seed scene with more particles (or balls still to drop) is skipped: too slow to fuzz.
constexpr std::size_t kMaxSceneParticles = 200;

[[noreturn]] void violated(const char* what, const std::string& detail) {
    std::fprintf(stderr, "world_mutation_fuzzer: %s: %s\n", what, detail.c_str());
    std::abort();
}

/// PSB_FUZZ_TRACE=1 prints each change and step to stderr (for reading a finding).
bool tracing() {
    static const bool on = std::getenv("PSB_FUZZ_TRACE") != nullptr;
    return on;
}

bool sameBits(double a, double b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

/// A number for a physical quantity: mostly within [lo, hi], sometimes one that must be refused
/// or that stresses the step (zero, negative, NaN, infinite, tiny, huge).
double quantity(FuzzedDataProvider& in, double lo, double hi) {
    // Rarely absurdly large: a speed of 10^6 boxes a second takes 10^4 wall hits a step in the
    // exact mode, which is slow to fuzz.
    switch (in.ConsumeIntegralInRange<int>(0, 31)) {
        case 0:
            return std::numeric_limits<double>::quiet_NaN();
        case 1:
            return std::numeric_limits<double>::infinity();
        case 2:
            return 0.0;
        case 3:
            return -in.ConsumeFloatingPointInRange<double>(0.0, hi);
        case 4:
            return 1e-300;
        case 5:
            return hi * 1e3;
        case 6:
            return hi * 1e6;
        default:
            return in.ConsumeFloatingPointInRange<double>(lo, hi);
    }
}

/// A point in (or near) the box.
Vec2 pointIn(FuzzedDataProvider& in, const psb::World& w) {
    const double x = in.ConsumeFloatingPointInRange<double>(-0.1, 1.1) * w.def().width;
    const double y = in.ConsumeFloatingPointInRange<double>(-0.1, 1.1) * w.def().height;
    if (in.ConsumeIntegralInRange<int>(0, 31) == 0) return {std::nan(""), y};
    return {x, y};
}

double scaleOf(const psb::World& w) {
    return std::min(w.def().width, w.def().height);
}

psb::ParticleDef particleIn(FuzzedDataProvider& in, const psb::World& w) {
    const double s = scaleOf(w);
    psb::ParticleDef d;
    d.position = pointIn(in, w);
    d.velocity = {quantity(in, -20.0 * s, 20.0 * s), quantity(in, -20.0 * s, 20.0 * s)};
    d.mass = quantity(in, 1e-3, 10.0);
    d.radius = quantity(in, 0.005 * s, 0.15 * s);
    return d;
}

psb::Obstacle obstacleIn(FuzzedDataProvider& in, const psb::World& w) {
    const double s = scaleOf(w);
    if (in.ConsumeBool())
        return psb::Obstacle::peg(pointIn(in, w), quantity(in, 0.005 * s, 0.1 * s));
    return psb::Obstacle::segment(pointIn(in, w), pointIn(in, w),
                                  quantity(in, 0.005 * s, 0.05 * s));
}

psb::Dropper dropperIn(FuzzedDataProvider& in, const psb::World& w) {
    const double s = scaleOf(w);
    psb::Dropper d;
    d.position = pointIn(in, w);
    d.balls = in.ConsumeIntegralInRange<std::uint64_t>(0, 12);
    d.interval = quantity(in, 0.005, 0.2);
    d.radius = quantity(in, 0.005 * s, 0.05 * s);
    d.mass = quantity(in, 1e-3, 1.0);
    d.velocity = {in.ConsumeFloatingPointInRange<double>(-s, s), 0.0};
    d.spread = in.ConsumeFloatingPointInRange<double>(0.0, 0.05 * s);
    d.seed = in.ConsumeIntegral<std::uint64_t>();
    return d;
}

std::optional<psb::ParticleId> someParticle(FuzzedDataProvider& in, const psb::World& w) {
    const std::vector<psb::ParticleId> ids = w.ids();
    if (ids.empty()) return std::nullopt;
    psb::ParticleId id = ids[in.ConsumeIntegralInRange<std::size_t>(0, ids.size() - 1)];
    if (in.ConsumeIntegralInRange<int>(0, 15) == 0) id.generation += 1;  // a stale id
    return id;
}

/// Everything a refused change must leave as it was.
struct Snapshot {
    psb::WorldDef def;
    psb::SolverSettings solver;
    psb::Droppers droppers;
    std::vector<psb::ParticleId> ids;
    std::vector<double> values;

    explicit Snapshot(const psb::World& w)
        : def(w.def()), solver(w.solver()), droppers(w.droppers()), ids(w.ids()) {
        const psb::ParticleArrays& p = w.particles();
        for (std::size_t i = 0; i < p.size(); ++i) {
            values.insert(values.end(),
                          {p.x[i], p.y[i], p.vx[i], p.vy[i], p.mass[i], p.radius[i], p.invMass[i]});
        }
    }
    bool operator==(const Snapshot& o) const {
        if (ids != o.ids || !(droppers == o.droppers) || values.size() != o.values.size())
            return false;
        for (std::size_t k = 0; k < values.size(); ++k)
            if (!sameBits(values[k], o.values[k])) return false;
        const psb::WorldDef &a = def, &b = o.def;
        return sameBits(a.width, b.width) && sameBits(a.height, b.height) && a.walls == b.walls &&
               sameBits(a.gravity.x(), b.gravity.x()) && sameBits(a.gravity.y(), b.gravity.y()) &&
               sameBits(a.restitution, b.restitution) && sameBits(a.friction, b.friction) &&
               a.obstacles == b.obstacles && solver.mode == o.solver.mode &&
               solver.substeps == o.solver.substeps;
    }
};

/// Runs one change; a refusal must be an InvalidArgument that changed nothing. Returns whether
/// the world is different now.
template <typename F>
bool change(const psb::World& w, const char* what, F&& f) {
    if (tracing()) std::fprintf(stderr, "change %s\n", what);
    const Snapshot before(w);
    try {
        f();
    } catch (const psb::InvalidArgument& e) {
        if (tracing()) std::fprintf(stderr, "  refused: %s\n", e.what());
        if (!(Snapshot(w) == before)) violated("a refused change changed the world", what);
        return false;
    }
    return !(Snapshot(w) == before);
}

void checkState(const psb::World& w, const char* when) {
    const psb::ParticleArrays& p = w.particles();
    const psb::WorldDef& def = w.def();
    for (std::size_t i = 0; i < p.size(); ++i) {
        if (!std::isfinite(p.x[i]) || !std::isfinite(p.y[i]) || !std::isfinite(p.vx[i]) ||
            !std::isfinite(p.vy[i])) {
            violated(when, "particle " + std::to_string(i) + " is not finite");
        }
        if (!def.walls) continue;
        const auto inside = [](double x, double r, double extent) {
            const double tol = 1e-9 * extent;
            if (2.0 * r >= extent) return std::abs(x - 0.5 * extent) <= tol;
            return x >= r - tol && x <= extent - r + tol;
        };
        if (!inside(p.x[i], p.radius[i], def.width) || !inside(p.y[i], p.radius[i], def.height)) {
            violated(when, "particle " + std::to_string(i) + " is outside the box at (" +
                               std::to_string(p.x[i]) + ", " + std::to_string(p.y[i]) + ") r " +
                               std::to_string(p.radius[i]));
        }
    }
}

void checkSame(const psb::World& a, const psb::World& b) {
    const psb::ParticleArrays &p = a.particles(), &q = b.particles();
    if (p.id != q.id) violated("copy", "the copies hold different particles");
    for (std::size_t i = 0; i < p.size(); ++i) {
        if (!sameBits(p.x[i], q.x[i]) || !sameBits(p.y[i], q.y[i]) || !sameBits(p.vx[i], q.vx[i]) ||
            !sameBits(p.vy[i], q.vy[i])) {
            violated("copy", "particle " + std::to_string(i) + " differs after stepping alike");
        }
    }
}

double smallestRadius(const psb::World& w) {
    const psb::ParticleArrays& p = w.particles();
    double r = INFINITY;
    for (const double x : p.radius)
        r = std::min(r, x);
    return r;
}

void dump(const psb::World& w, double dt) {
    const psb::WorldDef& d = w.def();
    std::fprintf(
        stderr, "step %s dt %g: box %.17g x %.17g walls %d g (%g, %g) e %g mu %g, %zu obstacles\n",
        std::string(psb::toString(w.solver().mode)).c_str(), dt, d.width, d.height, d.walls,
        d.gravity.x(), d.gravity.y(), d.restitution, d.friction, d.obstacles.size());
    for (const psb::Obstacle& o : d.obstacles)
        std::fprintf(stderr, "  %s (%.17g, %.17g) (%.17g, %.17g) r %.17g\n",
                     o.isPeg() ? "peg" : "segment", o.a.x(), o.a.y(), o.b.x(), o.b.y(), o.radius);
    const psb::ParticleArrays& p = w.particles();
    for (std::size_t i = 0; i < p.size(); ++i) {
        std::fprintf(stderr, "  %zu: (%.17g, %.17g) v (%.17g, %.17g) r %.17g m %g%s", i, p.x[i],
                     p.y[i], p.vx[i], p.vy[i], p.radius[i], p.mass[i],
                     p.invMass[i] == 0.0 ? " held" : "");
        if (p.rotation) {
            std::fprintf(stderr, " omega %g k %g%s", p.omega[i], p.inertiaFactor[i],
                         p.fixedRotation[i] != 0 ? " fixed" : "");
        }
        std::fprintf(stderr, "\n");
    }
}

double largestRadius(const psb::World& w) {
    const psb::ParticleArrays& p = w.particles();
    double r = 0.0;
    for (const double x : p.radius)
        r = std::max(r, x);
    return r;
}

/// The deepest overlap between two particles that are not held (kinematic) and fit in the box:
/// a free particle crushed against a held one passes through it after 1000 collisions in a
/// step (the jam guard, docs/exact.md), so pairs with a held particle have no bound.
double deepestFreeOverlap(const psb::World& w) {
    const psb::ParticleArrays& p = w.particles();
    // A disc wider than the box sits pinned on its centre line; the exact mode does not track
    // its overlaps (docs/exact-gravity.md, "A disc wider than the box"), so it is left out too.
    const double fits = std::min(w.def().width, w.def().height);
    const auto tracked = [&](std::size_t i) {
        return p.invMass[i] != 0.0 && 2.0 * p.radius[i] < fits;
    };
    double deepest = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        if (!tracked(i)) continue;
        for (std::size_t j = i + 1; j < p.size(); ++j) {
            if (!tracked(j)) continue;
            const double d = std::hypot(p.x[j] - p.x[i], p.y[j] - p.y[i]);
            deepest = std::max(deepest, p.radius[i] + p.radius[j] - d);
        }
    }
    return deepest;
}

/// Steps a world, checking after each step. In the exact mode no free pair may overlap deeper than
/// the deepest overlap the steps since the last change met: at a collision (rounding) or placed
/// (a pair found overlapping when the stepper rebuilt after the change: docs/exact.md, "Pairs
/// placed overlapping keep the distance they were placed at"). StepCounters::maxOverlap records
/// both, a placed pair in every step that still keeps it at its placed distance (a change that
/// does not rebuild, such as new droppers, resets the counters too), so the counters are reset
/// at each change.
///
/// The event budget is the window's (kWindowBudget events per particle a step: a step may end
/// early, at its first event left) or the library's default, none: every step reaches its end,
/// however many events that takes. Particles at 10⁷ m/s in a 4 m box honestly ask for 10⁶
/// events a step, minutes of fuzzing for one input, so each input has an allowance of
/// kAllowance events in all, given to each step as a budget of what is left; when a step runs
/// out of it the input ends (not a finding). Without a budget, such a step must still have
/// advanced: the next kZenoProbe events must move the clock, or the stepper meets events at
/// one instant without end (a step of the library's default would never return).
class Stepper {
  public:
    static constexpr std::uint64_t kWindowBudget = 10000;
    static constexpr std::uint64_t kAllowance = 1'000'000;
    static constexpr std::uint64_t kZenoProbe = 100'000;

    explicit Stepper(bool windowBudget) : window_(windowBudget) {}

    void changed(psb::World& w) { w.resetCounters(); }

    /// `count` steps of `dt` (the frame length, the driver's), `twin` (if any) stepped alike and
    /// compared after them. False when the input's allowance ran out: the input ends.
    bool step(psb::World& w, psb::World* twin, double dt, int count) {
        for (int k = 0; k < count; ++k) {
            const std::uint64_t worlds = twin ? 2 : 1;
            const std::uint64_t left =
                (kAllowance - std::min(kAllowance, spent_)) / ((w.size() + 1) * worlds);
            if (left == 0) return false;
            const std::uint64_t budget = window_ ? std::min(kWindowBudget, left) : left;
            const bool cut = stepOnce(w, dt, budget);
            if (twin) {
                stepOnce(*twin, dt, budget);
                checkSame(w, *twin);
            }
            if (!cut) continue;
            if (window_ && budget == kWindowBudget) continue;  // the window's own budget
            if (!window_) probeForAZeno(w, dt);
            return false;
        }
        return true;
    }

  private:
    /// One step with `budget` events per particle; whether the budget cut it short.
    bool stepOnce(psb::World& w, double dt, std::uint64_t budget) {
        if (tracing()) dump(w, dt);
        w.setExactEventBudget(budget);
        const std::uint64_t events = w.counters().events, cutShort = w.counters().cutShort;
        const double before = w.time();
        const double simulated = w.step(dt);
        spent_ += w.counters().events - events;
        const bool cut = w.counters().cutShort != cutShort;
        checkState(w, "step");
        if (!(simulated >= 0.0 && simulated <= dt) || w.time() != before + simulated ||
            (simulated < dt && !cut)) {
            violated("step", "simulated " + std::to_string(simulated) + " s of a " +
                                 std::to_string(dt) + " s step");
        }
        if (w.solver().mode == psb::StepMode::Exact && w.size() >= 2) {
            // A step the event budget cut short ends at its first event left, exact too.
            const double overlap = deepestFreeOverlap(w);
            const double bound = w.counters().maxOverlap;
            const double tol = 1e-9 * smallestRadius(w) +
                               1e-12 * std::max({largestRadius(w), w.def().width, w.def().height});
            if (overlap > bound + tol) {
                violated("exact step", "a pair overlaps by " + std::to_string(overlap) +
                                           " m, deeper than any the steps met (" +
                                           std::to_string(bound) + " m)");
            }
        }
        return cut;
    }

    void probeForAZeno(psb::World& w, double dt) {
        const std::uint64_t budget = std::max<std::uint64_t>(1, kZenoProbe / (w.size() + 1));
        w.setExactEventBudget(budget);
        const double before = w.time();
        if (w.step(dt) == 0.0) {
            violated("step", std::to_string(budget * (w.size() + 1)) + " events at t = " +
                                 std::to_string(before) + " s without the clock moving");
        }
    }

    bool window_;
    std::uint64_t spent_ = 0;
};

/// A world chosen by the bytes, and in `dt` the frame length to step it by.
psb::World worldFrom(FuzzedDataProvider& in, double& dt) {
    psb::WorldDef def;
    def.width = in.ConsumeFloatingPointInRange<double>(0.2, 20.0);
    def.height = in.ConsumeFloatingPointInRange<double>(0.2, 20.0);
    def.walls = in.ConsumeIntegralInRange<int>(0, 7) != 0;
    switch (in.ConsumeIntegralInRange<int>(0, 3)) {
        case 0:
            def.gravity = {0.0, 0.0};
            break;
        case 1:
            def.gravity = {0.0, 9.81};
            break;
        default:
            def.gravity = {in.ConsumeFloatingPointInRange<double>(-20.0, 20.0),
                           in.ConsumeFloatingPointInRange<double>(-20.0, 20.0)};
    }
    def.restitution = in.ConsumeProbability<double>();
    def.friction = in.ConsumeBool() ? 0.0 : in.ConsumeFloatingPointInRange<double>(0.0, 1.0);
    psb::SolverSettings solver;
    solver.mode = static_cast<psb::StepMode>(in.ConsumeIntegralInRange<int>(0, 2));
    dt = in.PickValueInArray({1.0 / 60.0, 0.002, 0.01, 0.03});
    solver.substeps = in.ConsumeIntegralInRange<int>(1, 6);
    psb::World world(def, solver);

    const int obstacles = in.ConsumeIntegralInRange<int>(0, 4);
    for (int k = 0; k < obstacles; ++k)
        change(world, "addObstacle", [&] { world.addObstacle(obstacleIn(in, world)); });
    if (in.ConsumeBool()) {
        psb::Droppers droppers(in.ConsumeIntegralInRange<std::size_t>(1, 2));
        for (psb::Dropper& d : droppers)
            d = dropperIn(in, world);
        change(world, "setDroppers", [&] { world.setDroppers(droppers); });
    }
    const int particles = in.ConsumeIntegralInRange<int>(0, 12);
    for (int k = 0; k < particles; ++k)
        change(world, "add", [&] { world.add(particleIn(in, world)); });
    return world;
}

}  // namespace

// An input is either bytes that choose the world and then the changes, or a scene file, the
// line kOpsMark, then bytes that choose the changes (how the corpus is seeded with the presets
// and with the scenes of past crashes; a scene the loader refuses, or too large to step fast,
// is skipped).
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static constexpr std::string_view kOpsMark = "\n#ops\n";
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    std::optional<psb::World> made;
    double dt = 0.0;  // the frame length: the driver's, as the app keeps it beside the world
    std::size_t opsFrom = 0;
    if (const std::size_t mark = text.find(kOpsMark); !text.empty() && text[0] == '{') {
        if (mark == std::string_view::npos) return 0;
        try {
            const psb::Scene scene = psb::parseScene(text.substr(0, mark), "seed.json");
            std::uint64_t balls = 0;
            for (const psb::Dropper& d : scene.droppers)
                balls += d.balls;
            if (scene.particles.size() + balls > kMaxSceneParticles) return 0;
            made.emplace(psb::makeWorld(scene));
            dt = scene.dt;
        } catch (const psb::SceneError&) {
            return 0;
        } catch (const psb::InvalidArgument&) {
            return 0;  // parseScene accepted it; the world refuses it (a fuzzed file only)
        }
        opsFrom = mark + kOpsMark.size();
    }
    FuzzedDataProvider in(data + opsFrom, size - opsFrom);
    psb::World world = made ? std::move(*made) : worldFrom(in, dt);
    world.setThreads(1);
    // The library's default (no budget: every step reaches its end) or the window's frame budget.
    Stepper stepper(/*windowBudget=*/!in.ConsumeBool());
    stepper.changed(world);
    std::optional<psb::World> twin;  // a copy stepped alike, until the next change
    for (int op = 0; op < kMaxOps && in.remaining_bytes() > 0; ++op) {
        const int what = in.ConsumeIntegralInRange<int>(0, 22);
        if (what <= 3) {
            const int count = in.ConsumeIntegralInRange<int>(1, kMaxStepsPerOp);
            if (!stepper.step(world, twin ? &*twin : nullptr, dt, count)) break;
            continue;
        }
        twin.reset();
        bool differs = false;  // the world changed: the next exact step rebuilds
        const auto change = [&differs](const psb::World& w, const char* what, auto&& f) {
            differs = ::change(w, what, f) || differs;
        };
        const std::optional<psb::ParticleId> id = someParticle(in, world);
        const double s = scaleOf(world);
        switch (what) {
            case 4:
                if (world.size() < kMaxParticles)
                    change(world, "add", [&] { world.add(particleIn(in, world)); });
                break;
            case 5:
                if (id) change(world, "remove", [&] { world.remove(*id); });
                break;
            case 6:
                if (id)
                    change(world, "setPosition",
                           [&] { world.setPosition(*id, pointIn(in, world)); });
                break;
            case 7:
                if (id) {
                    const Vec2 v{quantity(in, -30.0 * s, 30.0 * s),
                                 quantity(in, -30.0 * s, 30.0 * s)};
                    change(world, "setVelocity", [&] { world.setVelocity(*id, v); });
                }
                break;
            case 8:
                if (id) {
                    const double m = quantity(in, 1e-3, 10.0);
                    change(world, "setMass", [&] { world.setMass(*id, m); });
                }
                break;
            case 9:
                if (id) {
                    const double r = quantity(in, 0.005 * s, 0.2 * s);
                    change(world, "setRadius", [&] { world.setRadius(*id, r); });
                }
                break;
            case 10:
                if (id) {
                    const bool held = in.ConsumeBool();
                    change(world, "setKinematic", [&] { world.setKinematic(*id, held); });
                }
                break;
            case 11:
                if (world.obstacles().size() < 8)
                    change(world, "addObstacle", [&] { world.addObstacle(obstacleIn(in, world)); });
                break;
            case 12: {
                const std::size_t k = in.ConsumeIntegralInRange<std::size_t>(0, 8);
                change(world, "removeObstacle", [&] { world.removeObstacle(k); });
                break;
            }
            case 13: {
                const Vec2 g{quantity(in, -20.0, 20.0), quantity(in, -20.0, 20.0)};
                change(world, "setGravity", [&] { world.setGravity(g); });
                break;
            }
            case 14: {
                const double e = quantity(in, 0.0, 1.0), mu = quantity(in, 0.0, 1.0);
                change(world, "setRestitution", [&] { world.setRestitution(e); });
                change(world, "setFriction", [&] { world.setFriction(mu); });
                break;
            }
            case 15: {
                psb::SolverSettings next = world.solver();
                next.mode = static_cast<psb::StepMode>(in.ConsumeIntegralInRange<int>(0, 2));
                next.substeps = in.ConsumeIntegralInRange<int>(0, 6);
                // The frame length is the driver's, not the world's: a new one comes with the
                // settings; a bad one World::step refuses, changing nothing.
                const double frame = in.ConsumeBool() ? dt : quantity(in, 0.001, 0.03);
                if (!(std::isfinite(frame) && frame > 0.0)) {
                    change(world, "step by a bad dt", [&] { world.step(frame); });
                    break;
                }
                const double before = dt;
                change(world, "setSolver", [&] {
                    world.setSolver(next);
                    dt = frame;
                });
                if (!sameBits(dt, before)) differs = true;  // counted as a change, as it was
                break;
            }
            case 16: {
                const double w = quantity(in, 0.2, 20.0), h = quantity(in, 0.2, 20.0);
                change(world, "setBox", [&] { world.setBox(w, h); });
                if (in.ConsumeBool()) {
                    const bool walls = in.ConsumeBool();
                    change(world, "setWalls", [&] { world.setWalls(walls); });
                }
                break;
            }
            case 17: {
                psb::Droppers droppers(in.ConsumeIntegralInRange<std::size_t>(0, 2));
                for (psb::Dropper& d : droppers)
                    d = dropperIn(in, world);
                change(world, "setDroppers", [&] { world.setDroppers(droppers); });
                break;
            }
            case 18:
                // A copy (as the undo history and the timeline keep) stepped alike from here.
                if (in.ConsumeBool()) {
                    world.dropEventState();
                    differs = true;
                }
                twin.emplace(world);
                break;
            case 19:
                if (in.ConsumeIntegralInRange<int>(0, 3) == 0) {
                    world.clear();
                    differs = true;
                } else
                    world = psb::World(world);  // copy-assign, as undo restores a state
                break;
            case 20:
                // Spin (hostile: NaN, infinite, huge), refused on a fixed-rotation particle.
                if (id) {
                    const double omega = quantity(in, -50.0, 50.0);
                    const double angle = quantity(in, -10.0, 10.0);
                    change(world, "setAngularVelocity",
                           [&] { world.setAngularVelocity(*id, omega); });
                    change(world, "setAngle", [&] { world.setAngle(*id, angle); });
                }
                break;
            case 21:
                // The inertia factor, 0.05 to 1 (its bounds, 0.001 and 1, and what lies outside
                // them are rotation_test's).
                if (id) {
                    const double k = quantity(in, 0.05, 1.0);
                    const bool fixed = in.ConsumeIntegralInRange<int>(0, 3) == 0;
                    change(world, "setInertiaFactor", [&] { world.setInertiaFactor(*id, k); });
                    change(world, "setFixedRotation", [&] { world.setFixedRotation(*id, fixed); });
                }
                break;
            case 22: {
                const double beta = quantity(in, -1.0, 1.0);
                change(world, "setTangentialRestitution",
                       [&] { world.setTangentialRestitution(beta); });
                break;
            }
            default:
                break;
        }
        if (differs) stepper.changed(world);
    }
    return 0;
}
