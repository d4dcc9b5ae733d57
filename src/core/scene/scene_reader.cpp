// Reading scene files: parseScene and loadScene.
//
// The reader trusts nothing. It walks the JSON DOM with the path of every value in hand, so
// each error can name the file, the path (`particles[3].mass`) and the problem, and it checks
// the whole scene (types, ranges, unknown keys, the box, overlaps, and whether World accepts
// the solver settings) before a World is ever built from it. Messages are part of the
// interface: tests/core/scene/scene_corpus pins each one.

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <initializer_list>
#include <limits>
#include <numbers>
#include <optional>

#include <nlohmann/json.hpp>
#include <particle_sandbox/csv.hpp>
#include <particle_sandbox/detail/nearest_name.hpp>
#include <particle_sandbox/error.hpp>
#include <particle_sandbox/hard_disc_theory.hpp>
#include <particle_sandbox/scene.hpp>
#include <particle_sandbox/validation.hpp>

#include "broadphase/overlap_check.hpp"
#include "obstacles/obstacle_geometry.hpp"
#include "scene/json_reader.hpp"
#include "scene/json_values.hpp"
#include "scene/scene_generate.hpp"
#include "scene/scene_overrides.hpp"
#include "support/periodic_box.hpp"
#include "support/printable.hpp"

namespace psb {
namespace {

using json = nlohmann::json;
using detail::element;
using detail::Keys;
using detail::member;
using detail::ValueReader;

constexpr int kVersion = 6;
/// Version 2 added `obstacles`, version 3 `bins`, version 4 `droppers`, version 5 rotation (a
/// particle's `angle`, `angular_velocity`, `inertia_factor`, `fixed_rotation` and the world's
/// `tangential_restitution`), version 6 the world's `periodic`; a file without them may say any
/// version.
constexpr int kFirstVersion = 1, kObstaclesVersion = 2, kBinsVersion = 3, kDroppersVersion = 4,
              kRotationVersion = 5, kPeriodicVersion = 6;

/// Numbers in messages as the exports write them: the shortest text that reads back as the same
/// double.
std::string num(double v) {
    return csv::number(v);
}

/// Where each particle of the scene came from, for messages: "particles[3]" or
/// "generate[1] particle 17".
struct Origin {
    std::string block;  // "particles" or the generate block's path
    std::size_t index;
};

std::string describe(const Origin& o) {
    if (o.block == "particles") return element("particles", o.index);
    return "particle " + std::to_string(o.index) + " of " + o.block;
}

/// A key of version 5 (rotation) in a file that says an older version is refused.
void requireRotationVersion(const ValueReader& r, const std::string& path, int version) {
    if (version < kRotationVersion) {
        r.fail(path, "need version " + std::to_string(kRotationVersion) +
                         " or later (the file says version " + std::to_string(version) + ")");
    }
}

void readWorld(const ValueReader& r, const json& j, WorldDef& w, int version) {
    const std::string path = "world";
    r.object(j, path,
             {"width", "height", "walls", "periodic", "gravity", "restitution", "friction",
              "tangential_restitution"});
    if (const json* v = ValueReader::find(j, "width")) w.width = r.positive(*v, "world.width");
    if (const json* v = ValueReader::find(j, "height")) w.height = r.positive(*v, "world.height");
    if (const json* v = ValueReader::find(j, "walls")) w.walls = r.boolean(*v, "world.walls");
    if (const json* v = ValueReader::find(j, "periodic")) {
        w.periodic = r.boolean(*v, "world.periodic");
        if (version < kPeriodicVersion) {
            r.fail("world.periodic", "need version " + std::to_string(kPeriodicVersion) +
                                         " or later (the file says version " +
                                         std::to_string(version) + ")");
        }
    }
    if (w.periodic) {
        // Joined edges are not walls: a file that asks for both asks for two boxes at once.
        const json* walls = ValueReader::find(j, "walls");
        if (walls && w.walls) {
            r.fail("world.walls",
                   "cannot be true in a periodic world (its edges are joined, so "
                   "it has no walls): leave 'walls' out or set it false");
        }
        w.walls = false;
    }
    if (const json* v = ValueReader::find(j, "gravity")) w.gravity = r.vec2(*v, "world.gravity");
    if (const json* v = ValueReader::find(j, "restitution")) {
        w.restitution = r.inRange(*v, "world.restitution", 0.0, 1.0);
    }
    if (const json* v = ValueReader::find(j, "friction")) {
        w.friction = r.nonNegative(*v, "world.friction");
    }
    if (const json* v = ValueReader::find(j, "tangential_restitution")) {
        requireRotationVersion(r, "world.tangential_restitution", version);
        w.tangentialRestitution = r.inRange(*v, "world.tangential_restitution", -1.0, 1.0);
    }
}

template <typename Parse>
auto readName(const ValueReader& r, const json& j, const std::string& path, const char* what,
              Parse parse, Keys known) {
    const std::string name = r.string(j, path);
    const auto value = parse(name);
    if (!value) {
        r.fail(path, std::string("unknown ") + what + " '" + name.substr(0, 64) + "'" +
                         detail::suggestion(name, known));
    }
    return *value;
}

/// The solver block: the settings, and the scene's frame length `dt` (kept in the file's solver
/// block, by the scene in memory).
void readSolver(const ValueReader& r, const json& j, SolverSettings& s, double& dt) {
    r.object(j, "solver", {"mode", "dt", "substeps", "broadphase"});
    if (const json* v = ValueReader::find(j, "mode")) {
        s.mode = readName(r, *v, "solver.mode", "mode", &parseStepMode,
                          {"discrete", "substep", "exact"});
    }
    if (const json* v = ValueReader::find(j, "dt")) dt = r.positive(*v, "solver.dt");
    if (const json* v = ValueReader::find(j, "substeps")) {
        s.substeps = static_cast<int>(r.integer(*v, "solver.substeps", 1, psb::kMaxSubsteps));
    }
    if (const json* v = ValueReader::find(j, "broadphase")) {
        s.broadphase = readName(r, *v, "solver.broadphase", "broadphase", &parseBroadPhase,
                                {"auto", "all-pairs", "grid", "quadtree"});
    }
}

/// Asks the core whether a World would accept the settings (validate(), no world made), so that
/// a mode or broadphase this build lacks, or a combination it refuses, is reported at its JSON
/// path with World's reason.
void checkWorldAccepts(const ValueReader& r, const WorldDef& def, const SolverSettings& s) {
    const std::vector<SettingProblem> problems = validate(def, s);
    const auto why = [](const SettingProblem& p) { return "refused (World: " + describe(p) + ")"; };
    for (const SettingProblem& p : problems) {
        if (p.setting == "mode" || p.because == "mode") r.fail("solver.mode", why(p));
    }
    for (const SettingProblem& p : problems) {
        if (p.setting == "broadphase") r.fail("solver.broadphase", why(p));
    }
    if (!problems.empty()) r.fail("solver", why(problems.front()));
}

ParticleDef readParticle(const ValueReader& r, const json& j, const std::string& path, int version,
                         bool& trail) {
    r.object(j, path,
             {"x", "y", "vx", "vy", "mass", "radius", "color", "trail", "angle", "angular_velocity",
              "inertia_factor", "fixed_rotation"});
    ParticleDef d;
    d.position = {r.number(r.require(j, path, "x"), member(path, "x")),
                  r.number(r.require(j, path, "y"), member(path, "y"))};
    if (const json* v = ValueReader::find(j, "vx"))
        d.velocity.x() = r.number(*v, member(path, "vx"));
    if (const json* v = ValueReader::find(j, "vy"))
        d.velocity.y() = r.number(*v, member(path, "vy"));
    d.mass = r.mass(r.require(j, path, "mass"), member(path, "mass"));
    d.radius = r.positive(r.require(j, path, "radius"), member(path, "radius"));
    if (const json* v = ValueReader::find(j, "color")) d.color = r.color(*v, member(path, "color"));
    trail = false;
    if (const json* v = ValueReader::find(j, "trail")) trail = r.boolean(*v, member(path, "trail"));
    if (const json* v = ValueReader::find(j, "angle")) {
        requireRotationVersion(r, member(path, "angle"), version);
        d.angle = r.number(*v, member(path, "angle"));
    }
    if (const json* v = ValueReader::find(j, "angular_velocity")) {
        requireRotationVersion(r, member(path, "angular_velocity"), version);
        d.angularVelocity = r.number(*v, member(path, "angular_velocity"));
    }
    if (const json* v = ValueReader::find(j, "inertia_factor")) {
        const std::string at = member(path, "inertia_factor");
        requireRotationVersion(r, at, version);
        d.inertiaFactor = r.positive(*v, at);
        if (d.inertiaFactor > 1.0) r.fail(at, "must be <= 1 (got " + num(d.inertiaFactor) + ")");
        if (d.inertiaFactor < kMinInertiaFactor) {
            r.fail(at, "must be >= 0.001 (got " + num(d.inertiaFactor) + ")");
        }
    }
    if (const json* v = ValueReader::find(j, "fixed_rotation")) {
        requireRotationVersion(r, member(path, "fixed_rotation"), version);
        d.fixedRotation = r.boolean(*v, member(path, "fixed_rotation"));
        if (d.fixedRotation && d.angularVelocity != 0.0) {
            r.fail(member(path, "angular_velocity"),
                   "must be 0 for a particle with fixed_rotation (got " + num(d.angularVelocity) +
                       ")");
        }
    }
    return d;
}

/// One obstacle: {"type": "peg", "x", "y", "radius"} or {"type": "segment", "from": [x, y],
/// "to": [x, y], "thickness"}. Its centre or ends must lie in the closed box, where it can be
/// drawn; a segment must have two distinct ends.
Obstacle readObstacle(const ValueReader& r, const json& j, const std::string& path,
                      const WorldDef& w) {
    r.expectType(j, path, j.is_object(), "an object");
    const std::string typePath = member(path, "type");
    const std::string type = r.string(r.require(j, path, "type"), typePath);
    std::string box = "the ";
    box += num(w.width);
    box += " x ";
    box += num(w.height);
    box += " m box";
    auto inBox = [&](const Vec2& v) {
        return v.x() >= 0.0 && v.x() <= w.width && v.y() >= 0.0 && v.y() <= w.height;
    };
    auto text = [](const Vec2& v) {
        std::string t(1, '[');
        t += num(v.x());
        t += ", ";
        t += num(v.y());
        t += ']';
        return t;
    };
    if (type == "peg") {
        r.object(j, path, {"type", "x", "y", "radius"});
        const Vec2 c(r.number(r.require(j, path, "x"), member(path, "x")),
                     r.number(r.require(j, path, "y"), member(path, "y")));
        const double radius = r.positive(r.require(j, path, "radius"), member(path, "radius"));
        if (radius > std::max(w.width, w.height)) {
            r.fail(member(path, "radius"), "must be at most the box's larger side, " +
                                               num(std::max(w.width, w.height)) + " m (got " +
                                               num(radius) + ")");
        }
        if (!inBox(c)) r.fail(path, "centre " + text(c) + " lies outside " + box);
        return Obstacle::peg(c, radius);
    }
    if (type == "segment") {
        r.object(j, path, {"type", "from", "to", "thickness"});
        const Vec2 a = r.vec2(r.require(j, path, "from"), member(path, "from"));
        const Vec2 b = r.vec2(r.require(j, path, "to"), member(path, "to"));
        const double thickness =
            r.positive(r.require(j, path, "thickness"), member(path, "thickness"));
        if (thickness > 2.0 * std::max(w.width, w.height)) {
            r.fail(member(path, "thickness"), "must be at most twice the box's larger side, " +
                                                  num(2.0 * std::max(w.width, w.height)) +
                                                  " m (got " + num(thickness) + ")");
        }
        if (a == b) r.fail(path, "has zero length: both ends at " + text(a) + " (use a peg)");
        if (!inBox(a)) r.fail(member(path, "from"), text(a) + " lies outside " + box);
        if (!inBox(b)) r.fail(member(path, "to"), text(b) + " lies outside " + box);
        const Obstacle o = Obstacle::segment(a, b, thickness);
        if (!(o.radius > 0.0))
            r.fail(member(path, "thickness"), "is too small (got " + num(thickness) + ")");
        return o;
    }
    r.fail(typePath, "unknown obstacle type '" + type.substr(0, 64) + "'" +
                         detail::suggestion(type, {"peg", "segment"}));
}

void readObstacles(const ValueReader& r, const json& j, int version, WorldDef& w) {
    r.expectType(j, "obstacles", j.is_array(), "an array");
    if (version < kObstaclesVersion && !j.empty()) {
        r.fail("obstacles", "need version " + std::to_string(kObstaclesVersion) +
                                " or later (the file says version " + std::to_string(version) +
                                ")");
    }
    if (j.size() > kMaxSceneObstacles) {
        r.fail("obstacles", "holds " + std::to_string(j.size()) +
                                " obstacles, more than the limit of " +
                                std::to_string(kMaxSceneObstacles));
    }
    w.obstacles.reserve(j.size());
    for (std::size_t i = 0; i < j.size(); ++i)
        w.obstacles.push_back(readObstacle(r, j[i], element("obstacles", i), w));
}

/// `bins`: {"edges": [x0, ..., xn], "top": y, "expected": {"binomial": {"trials": n, "p": p}}}.
/// Edges strictly increasing and inside the box, the top inside it, and a binomial's bins one
/// per number of successes.
Bins readBins(const ValueReader& r, const json& j, int version, const WorldDef& w) {
    r.object(j, "bins", {"edges", "top", "expected"});
    if (version < kBinsVersion) {
        r.fail("bins", "need version " + std::to_string(kBinsVersion) +
                           " or later (the file says version " + std::to_string(version) + ")");
    }
    Bins b;
    const json& edges = r.require(j, "bins", "edges");
    r.expectType(edges, "bins.edges", edges.is_array(), "an array of numbers");
    if (edges.size() < 2 || edges.size() > kMaxBins + 1) {
        r.fail("bins.edges", "needs 2 to " + std::to_string(kMaxBins + 1) +
                                 " edges (one more than the bins), got " +
                                 std::to_string(edges.size()));
    }
    for (std::size_t i = 0; i < edges.size(); ++i) {
        const std::string path = element("bins.edges", i);
        const double x = r.number(edges[i], path);
        if (x < 0.0 || x > w.width) {
            r.fail(path, num(x) + " lies outside the box (x from 0 to " + num(w.width) + " m)");
        }
        if (!b.edges.empty() && !(x > b.edges.back())) {
            r.fail(path, "must be greater than the edge before it (" + num(b.edges.back()) +
                             "), got " + num(x));
        }
        b.edges.push_back(x);
    }
    b.top = r.number(r.require(j, "bins", "top"), "bins.top");
    if (b.top < 0.0 || b.top > w.height) {
        r.fail("bins.top",
               num(b.top) + " lies outside the box (y from 0 to " + num(w.height) + " m)");
    }
    if (const json* e = ValueReader::find(j, "expected")) {
        r.object(*e, "bins.expected", {"binomial"});
        const json& binomial = r.require(*e, "bins.expected", "binomial");
        const std::string path = "bins.expected.binomial";
        r.object(binomial, path, {"trials", "p"});
        BinomialExpectation x;
        x.trials = static_cast<int>(r.integer(r.require(binomial, path, "trials"), path + ".trials",
                                              1, kMaxBinomialTrials));
        x.p = r.inRange(r.require(binomial, path, "p"), path + ".p", 0.0, 1.0);
        if (static_cast<std::size_t>(x.trials) + 1 != b.size()) {
            r.fail(path + ".trials", std::to_string(x.trials) + " trials need " +
                                         std::to_string(x.trials + 1) + " bins (0 to " +
                                         std::to_string(x.trials) + " successes), the edges make " +
                                         std::to_string(b.size()));
        }
        b.binomial = x;
    }
    return b;
}

/// The index of the first obstacle that a ball released anywhere along a dropper's line
/// (x - spread to x + spread at y) would start inside, if any.
std::optional<std::size_t> dropperInObstacle(const Dropper& d, const Obstacles& obstacles) {
    const Obstacle line = Obstacle::segment({d.position.x() - d.spread, d.position.y()},
                                            {d.position.x() + d.spread, d.position.y()}, 0.0);
    const auto distance = [](const Obstacle& core, const Vec2& p) {
        double qx, qy;
        nearestCorePoint(core, p.x(), p.y(), qx, qy);
        return std::hypot(p.x() - qx, p.y() - qy);
    };
    for (std::size_t k = 0; k < obstacles.size(); ++k) {
        const Obstacle& o = obstacles[k];
        // Two segments are nearest at an end of one of them, unless they cross.
        double gap = std::min(
            {distance(line, o.a), distance(line, o.b), distance(o, line.a), distance(o, line.b)});
        if (!o.isPeg() && crossesCore(o, line.a.x(), line.a.y(), line.b.x(), line.b.y())) gap = 0.0;
        if (gap < d.radius + o.radius) return k;
    }
    return std::nullopt;
}

/// One dropper: {"x", "y", "balls", "interval", "radius", "mass"} and optionally "color",
/// "vx", "vy", "spread", "seed", and where it has got to: "released", "next_ball_in". Its balls
/// must fit in the box at every release point and start clear of every obstacle.
Dropper readDropper(const ValueReader& r, const json& j, const std::string& path, const WorldDef& w,
                    std::uint64_t room) {
    r.object(j, path,
             {"x", "y", "balls", "interval", "radius", "mass", "color", "vx", "vy", "spread",
              "seed", "released", "next_ball_in"});
    Dropper d;
    d.position = {r.number(r.require(j, path, "x"), member(path, "x")),
                  r.number(r.require(j, path, "y"), member(path, "y"))};
    const std::string ballsPath = member(path, "balls");
    d.balls = static_cast<std::uint64_t>(r.integer(r.require(j, path, "balls"), ballsPath, 0,
                                                   static_cast<std::int64_t>(kMaxDropperBalls)));
    if (d.balls > room) {
        r.fail(ballsPath, "the scene would hold more than the limit of " +
                              std::to_string(kMaxSceneParticles) + " particles");
    }
    d.interval = r.positive(r.require(j, path, "interval"), member(path, "interval"));
    const std::string radiusPath = member(path, "radius");
    d.radius = r.positive(r.require(j, path, "radius"), radiusPath);
    d.mass = r.mass(r.require(j, path, "mass"), member(path, "mass"));
    if (const json* v = ValueReader::find(j, "color")) d.color = r.color(*v, member(path, "color"));
    if (const json* v = ValueReader::find(j, "vx"))
        d.velocity.x() = r.number(*v, member(path, "vx"));
    if (const json* v = ValueReader::find(j, "vy"))
        d.velocity.y() = r.number(*v, member(path, "vy"));
    if (const json* v = ValueReader::find(j, "spread")) {
        d.spread = r.nonNegative(*v, member(path, "spread"));
    }
    if (const json* v = ValueReader::find(j, "seed")) {
        d.seed = static_cast<std::uint64_t>(r.integer(*v, member(path, "seed"), 0, INT64_MAX));
    }
    if (const json* v = ValueReader::find(j, "released")) {
        d.released =
            static_cast<std::uint64_t>(r.integer(*v, member(path, "released"), 0, INT64_MAX));
    }
    if (const json* v = ValueReader::find(j, "next_ball_in")) {
        const std::string np = member(path, "next_ball_in");
        d.nextIn = r.number(*v, np);
        if (d.nextIn > d.interval) {
            r.fail(np, "must be at most the interval, " + num(d.interval) + " s (got " +
                           num(d.nextIn) + ")");
        }
    }
    const std::string box = "the " + num(w.width) + " x " + num(w.height) + " m box";
    if (w.walls && (2.0 * d.radius > w.width || 2.0 * d.radius > w.height)) {
        r.fail(radiusPath, "a ball of radius " + num(d.radius) + " m does not fit in " + box);
    }
    // With walls a ball's centre must be a radius inside them, as the wall stage keeps it.
    const double margin = w.walls ? d.radius : 0.0;
    const double x0 = d.position.x() - d.spread, x1 = d.position.x() + d.spread;
    if (x0 < margin || x1 > w.width - margin) {
        std::string problem =
            "balls would start outside " + box + " (x from " + num(x0) + " to " + num(x1) + " m";
        problem += w.walls ? ", radius " + num(d.radius) + " m)" : ")";
        r.fail(member(path, "x"), problem);
    }
    if (d.position.y() < margin || d.position.y() > w.height - margin) {
        std::string problem =
            "balls would start outside " + box + " (y = " + num(d.position.y()) + " m";
        problem += w.walls ? ", radius " + num(d.radius) + " m)" : ")";
        r.fail(member(path, "y"), problem);
    }
    if (const auto k = dropperInObstacle(d, w.obstacles)) {
        r.fail(path, "balls would start inside obstacles[" + std::to_string(*k) + "]");
    }
    return d;
}

void readDroppers(const ValueReader& r, const json& j, Scene& s) {
    r.expectType(j, "droppers", j.is_array(), "an array");
    if (s.version < kDroppersVersion && !j.empty()) {
        r.fail("droppers", "need version " + std::to_string(kDroppersVersion) +
                               " or later (the file says version " + std::to_string(s.version) +
                               ")");
    }
    if (j.size() > kMaxDroppers) {
        r.fail("droppers", "holds " + std::to_string(j.size()) +
                               " droppers, more than the limit of " + std::to_string(kMaxDroppers));
    }
    std::uint64_t room = kMaxSceneParticles - s.particles.size();
    for (std::size_t i = 0; i < j.size(); ++i) {
        s.droppers.push_back(readDropper(r, j[i], element("droppers", i), s.world, room));
        room -= s.droppers.back().balls;
    }
}

/// A generate block's `packing_fraction`: the box (its shape kept) sized so that the block's
/// `count` discs cover that fraction of it. Read before anything is checked against the box.
void sizeBoxForPacking(const ValueReader& r, const json& root, WorldDef& world) {
    const json* g = ValueReader::find(root, "generate");
    if (g == nullptr) return;
    const bool many = g->is_array();
    for (std::size_t k = 0; many && k < g->size(); ++k) {
        if ((*g)[k].is_object() && ValueReader::find((*g)[k], "packing_fraction")) {
            r.fail(member(element("generate", k), "packing_fraction"),
                   "sizes the box, so it needs a scene with one generate block, not an array");
        }
    }
    if (many || !g->is_object()) return;
    const json* v = ValueReader::find(*g, "packing_fraction");
    if (v == nullptr) return;
    const std::string path = "generate.packing_fraction";
    const double phi = r.number(*v, path);
    if (!(phi > 0.0) || phi >= hard_discs::kClosePacking) {
        r.fail(path, "must be above 0 and below " + num(hard_discs::kClosePacking) +
                         ", the close packing of equal discs (hexagonal); got " + num(phi));
    }
    if (phi > kMaxPackingFraction) {
        r.fail(path, num(phi) + " is above " + num(kMaxPackingFraction) +
                         " (π/4), the densest a generate block's square lattice places discs");
    }
    for (const char* other : {"packing", "region"}) {
        if (ValueReader::find(*g, other)) {
            r.fail(path, std::string("sizes the box: give it without '") + other + "'");
        }
    }
    const json* count = ValueReader::find(*g, "count");
    if (count == nullptr) r.fail(path, "needs 'count': the box is sized for that many discs");
    const auto n = static_cast<double>(
        r.integer(*count, "generate.count", 1, static_cast<std::int64_t>(kMaxSceneParticles)));
    const double radius = r.positive(r.require(*g, "generate", "radius"), "generate.radius");
    // Area n π r² / φ, the box's aspect ratio kept.
    const double area = n * std::numbers::pi * radius * radius / phi;
    const double scale = std::sqrt(area / (world.width * world.height));
    if (!(std::isfinite(scale) && scale > 0.0)) r.fail(path, "gives a box of no finite size");
    world.width *= scale;
    world.height *= scale;
}

/// Reads one generate block and appends its particles.
void readGenerate(const ValueReader& r, const json& j, const std::string& path,
                  const WorldDef& world, int version, std::vector<ParticleDef>& out,
                  std::vector<Origin>& origins) {
    r.object(j, path,
             {"count", "packing", "packing_fraction", "radius", "mass", "region", "temperature",
              "speed", "color", "seed", "fixed_rotation"});
    detail::GenerateSpec spec;
    spec.radius = r.positive(r.require(j, path, "radius"), member(path, "radius"));
    if (const json* v = ValueReader::find(j, "mass")) spec.mass = r.mass(*v, member(path, "mass"));

    spec.x0 = 0.0;
    spec.y0 = 0.0;
    spec.x1 = world.width;
    spec.y1 = world.height;
    if (const json* v = ValueReader::find(j, "region")) {
        const std::string rp = member(path, "region");
        if (v->is_array() && v->size() != 4) {
            r.fail(rp, "expected [x0, y0, x1, y1], got " + std::to_string(v->size()) + " elements");
        }
        r.array(*v, rp, 4, "[x0, y0, x1, y1]");
        spec.x0 = r.number((*v)[0], element(rp, 0));
        spec.y0 = r.number((*v)[1], element(rp, 1));
        spec.x1 = r.number((*v)[2], element(rp, 2));
        spec.y1 = r.number((*v)[3], element(rp, 3));
        if (!(spec.x0 < spec.x1) || !(spec.y0 < spec.y1)) {
            r.fail(rp, "needs x0 < x1 and y0 < y1");
        }
        if (world.walls &&
            (spec.x0 < 0.0 || spec.y0 < 0.0 || spec.x1 > world.width || spec.y1 > world.height)) {
            r.fail(rp, "reaches outside the " + num(world.width) + " x " + num(world.height) +
                           " m box");
        }
    }

    const json* count = ValueReader::find(j, "count");
    const json* packing = ValueReader::find(j, "packing");
    if ((count != nullptr) == (packing != nullptr)) {
        r.fail(path, "needs exactly one of 'count' and 'packing'");
    }
    const std::uint64_t room = kMaxSceneParticles - out.size();
    std::string countPath;
    if (count) {
        countPath = member(path, "count");
        spec.count = static_cast<std::uint64_t>(
            r.integer(*count, countPath, 0, static_cast<std::int64_t>(kMaxSceneParticles)));
    } else {
        countPath = member(path, "packing");
        const double phi = r.number(*packing, countPath);
        if (phi < 0.0 || phi > kMaxPackingFraction) {
            r.fail(countPath, "must be from 0 to " + num(kMaxPackingFraction) +
                                  " (π/4, the densest a square lattice of discs can be; got " +
                                  num(phi) + ")");
        }
        const double area = (spec.x1 - spec.x0) * (spec.y1 - spec.y0);
        // A radius below ~1e-154 squares to 0, and so can a tiny region's area: 0 / 0 must
        // not give NaN, which the integer cast below would turn into undefined behaviour.
        const double n =
            (phi == 0.0 || area == 0.0)
                ? 0.0
                : std::floor(phi * area / (std::numbers::pi * spec.radius * spec.radius));
        if (!(n <= static_cast<double>(kMaxSceneParticles))) {
            // A count in digits while it has them exactly (below 2^53), then as a number.
            const std::string howMany =
                n < 0x1p53 ? std::to_string(static_cast<std::uint64_t>(n)) : num(n);
            r.fail(countPath, "gives " + howMany + " particles, more than the limit of " +
                                  std::to_string(kMaxSceneParticles));
        }
        spec.count = static_cast<std::uint64_t>(n);
    }
    if (spec.count > room) {
        r.fail(countPath, "the scene would hold " + std::to_string(out.size() + spec.count) +
                              " particles, more than the limit of " +
                              std::to_string(kMaxSceneParticles));
    }
    const std::uint64_t capacity = detail::latticeCapacity(spec);
    if (spec.count > capacity) {
        r.fail(countPath, std::to_string(spec.count) + " particles of radius " + num(spec.radius) +
                              " m do not fit in the region (at most " + std::to_string(capacity) +
                              ")");
    }

    const json* temperature = ValueReader::find(j, "temperature");
    const json* speed = ValueReader::find(j, "speed");
    if (temperature && speed) r.fail(path, "give at most one of 'temperature' and 'speed'");
    if (temperature) {
        const std::string tp = member(path, "temperature");
        spec.temperature = r.nonNegative(*temperature, tp);
        // Each velocity component is sqrt(kT/m) times a Box-Muller normal, which never exceeds
        // sqrt(-2 ln 2^-53) < 9 in size: a thermal speed of at most kMaxSceneMagnitude / 10
        // keeps every velocity within the limit (a huge kT over a tiny mass gave infinity).
        const double thermal = std::sqrt(*spec.temperature) / std::sqrt(spec.mass);
        if (!(thermal <= kMaxSceneMagnitude / 10.0)) {
            r.fail(tp, "gives a thermal speed sqrt(kT/m) of " + num(thermal) +
                           " m/s, above the limit of " + num(kMaxSceneMagnitude / 10.0) + " m/s");
        }
    }
    if (speed) spec.speed = r.nonNegative(*speed, member(path, "speed"));
    if (const json* v = ValueReader::find(j, "color"))
        spec.color = r.color(*v, member(path, "color"));
    if (const json* v = ValueReader::find(j, "seed")) {
        spec.seed = static_cast<std::uint64_t>(r.integer(*v, member(path, "seed"), 0, INT64_MAX));
    }

    bool fixedRotation = false;
    if (const json* v = ValueReader::find(j, "fixed_rotation")) {
        requireRotationVersion(r, member(path, "fixed_rotation"), version);
        fixedRotation = r.boolean(*v, member(path, "fixed_rotation"));
    }

    std::vector<ParticleDef> made = detail::generateParticles(spec);
    for (std::size_t k = 0; k < made.size(); ++k) {
        made[k].fixedRotation = fixedRotation;
        out.push_back(made[k]);
        origins.push_back({path, k});
    }
}

/// A periodic box must be at least two diameters of its largest particle (dropper balls
/// included) wide and high, and every obstacle must stay that particle's diameter inside every
/// edge (world/periodic_fit.hpp says why).
void checkPeriodic(const ValueReader& r, const Scene& s, const std::vector<Origin>& origins) {
    const WorldDef& w = s.world;
    double largest = 0.0;
    std::string whose;
    for (std::size_t i = 0; i < s.particles.size(); ++i) {
        if (s.particles[i].radius > largest) {
            largest = s.particles[i].radius;
            whose = describe(origins[i]);
        }
    }
    for (std::size_t k = 0; k < s.droppers.size(); ++k) {
        if (s.droppers[k].radius > largest) {
            largest = s.droppers[k].radius;
            whose = "the balls of " + element("droppers", k);
        }
    }
    const bool narrow = 4.0 * largest > w.width;
    if (narrow || 4.0 * largest > w.height) {
        const char* field = narrow ? "world.width" : "world.height";
        const double side = narrow ? w.width : w.height;
        r.fail(field, num(side) +
                          " m is too small for a periodic box holding a particle of radius " +
                          num(largest) + " m (" + whose +
                          "): a periodic box must be at least two diameters of its largest "
                          "particle, " +
                          num(4.0 * largest) + " m");
    }
    const double clearance = 2.0 * largest;
    for (std::size_t k = 0; k < w.obstacles.size(); ++k) {
        const Obstacle& o = w.obstacles[k];
        const double gap = std::min({std::min(o.a.x(), o.b.x()) - o.radius,
                                     w.width - (std::max(o.a.x(), o.b.x()) + o.radius),
                                     std::min(o.a.y(), o.b.y()) - o.radius,
                                     w.height - (std::max(o.a.y(), o.b.y()) + o.radius)});
        if (gap < clearance) {
            r.fail(element("obstacles", k),
                   "comes within " + num(std::max(gap, 0.0)) +
                       " m of an edge of the periodic box: obstacles do not act across the "
                       "edges, so each must stay the largest particle's diameter (" +
                       num(clearance) + " m) inside every edge");
        }
    }
}

void checkPlacement(const ValueReader& r, const Scene& s, const std::vector<Origin>& origins) {
    const WorldDef& w = s.world;
    if (w.walls) {
        for (std::size_t i = 0; i < s.particles.size(); ++i) {
            const ParticleDef& d = s.particles[i];
            const double x = d.position.x(), y = d.position.y(), rad = d.radius;
            // The wall stage's own test: the centre must lie in [r, extent - r].
            if (x < rad || x > w.width - rad || y < rad || y > w.height - rad) {
                r.fail(describe(origins[i]),
                       "not inside the " + num(w.width) + " x " + num(w.height) + " m box (x = " +
                           num(x) + ", y = " + num(y) + ", radius = " + num(rad) + ")");
            }
        }
    }
    if (s.allowOverlaps) return;
    if (const auto hit = detail::findObstacleOverlap(s.particles, w.obstacles)) {
        const Obstacle& o = w.obstacles[hit->obstacle];
        r.fail(describe(origins[hit->particle]),
               "overlaps obstacles[" + std::to_string(hit->obstacle) + "] (centre " +
                   num(hit->distance) + " m from its " + (o.isPeg() ? "centre" : "core line") +
                   ", " + num(s.particles[hit->particle].radius + o.radius) + " m needed)");
    }
    const auto pair = w.periodic ? detail::findOverlapPeriodic(s.particles, w.width, w.height)
                                 : detail::findOverlap(s.particles);
    if (pair) {
        const auto [i, k] = *pair;
        const ParticleDef &a = s.particles[i], &b = s.particles[k];
        const Vec2 direct = b.position - a.position;
        Vec2 apart = direct;
        if (w.periodic) {
            apart = {periodic::minimumImage(direct.x(), w.width),
                     periodic::minimumImage(direct.y(), w.height)};
        }
        r.fail(describe(origins[i]), "overlaps " + describe(origins[k]) + " (centres " +
                                         num(apart.norm()) + " m apart" +
                                         (apart != direct ? " across the box's edge" : "") +
                                         ", radii sum to " + num(a.radius + b.radius) + " m)");
    }
}

}  // namespace

Scene parseScene(std::string_view text, std::string_view source,
                 std::span<const SceneOverride> overrides) {
    if (text.size() > kMaxSceneFileBytes) {
        throw SceneError(std::string(source) + ": larger than the limit of " +
                         std::to_string(kMaxSceneFileBytes >> 20) + " MiB");
    }
    json root = detail::readJson(text, source);
    for (const SceneOverride& o : overrides)
        detail::applyOverride(root, o, source);
    const ValueReader r(source);
    r.object(root, "",
             {"version", "name", "description", "world", "solver", "particles", "generate",
              "allow_overlaps", "obstacles", "bins", "droppers"});

    Scene s;
    const json& version = r.require(root, "", "version");
    {
        const std::int64_t v = r.integer(version, "version", INT64_MIN, INT64_MAX);
        if (v < kFirstVersion || v > kVersion) {
            r.fail("version", "unsupported version " + std::to_string(v) +
                                  " (this build reads versions " + std::to_string(kFirstVersion) +
                                  " to " + std::to_string(kVersion) + ")");
        }
        s.version = static_cast<int>(v);
    }
    if (const json* v = ValueReader::find(root, "name")) s.name = r.string(*v, "name");
    if (const json* v = ValueReader::find(root, "description")) {
        s.description = r.string(*v, "description");
    }
    if (const json* v = ValueReader::find(root, "allow_overlaps")) {
        s.allowOverlaps = r.boolean(*v, "allow_overlaps");
    }
    if (const json* v = ValueReader::find(root, "world")) readWorld(r, *v, s.world, s.version);
    sizeBoxForPacking(r, root, s.world);
    if (const json* v = ValueReader::find(root, "solver")) readSolver(r, *v, s.solver, s.dt);
    if (const json* v = ValueReader::find(root, "obstacles")) {
        readObstacles(r, *v, s.version, s.world);
    }
    if (const json* v = ValueReader::find(root, "bins"))
        s.bins = readBins(r, *v, s.version, s.world);
    checkWorldAccepts(r, s.world, s.solver);

    std::vector<Origin> origins;
    if (const json* v = ValueReader::find(root, "particles")) {
        r.expectType(*v, "particles", v->is_array(), "an array");
        if (v->size() > kMaxSceneParticles) {
            r.fail("particles", "holds " + std::to_string(v->size()) +
                                    " particles, more than the limit of " +
                                    std::to_string(kMaxSceneParticles));
        }
        s.particles.reserve(v->size());
        for (std::size_t i = 0; i < v->size(); ++i) {
            bool trail = false;
            s.particles.push_back(
                readParticle(r, (*v)[i], element("particles", i), s.version, trail));
            if (trail) s.trails.push_back(i);
            origins.push_back({"particles", i});
        }
    }
    if (const json* v = ValueReader::find(root, "generate")) {
        if (v->is_array()) {
            for (std::size_t k = 0; k < v->size(); ++k) {
                readGenerate(r, (*v)[k], element("generate", k), s.world, s.version, s.particles,
                             origins);
            }
        } else {
            r.expectType(*v, "generate", v->is_object(), "an object or an array of objects");
            readGenerate(r, *v, "generate", s.world, s.version, s.particles, origins);
        }
    }
    if (const json* v = ValueReader::find(root, "droppers")) readDroppers(r, *v, s);
    if (s.world.periodic) checkPeriodic(r, s, origins);
    checkPlacement(r, s, origins);
    return s;
}

Scene loadScene(const std::filesystem::path& path, std::span<const SceneOverride> overrides) {
    const std::string source = path.string();
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) {
        throw SceneError(source + ": is a directory, not a scene file");
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) throw SceneError(source + ": cannot open (" + std::strerror(errno) + ")");
    std::string text;
    char buf[1 << 16];
    while (in.read(buf, sizeof buf) || in.gcount() > 0) {
        text.append(buf, static_cast<std::size_t>(in.gcount()));
        if (text.size() > kMaxSceneFileBytes) {
            throw SceneError(source + ": larger than the limit of " +
                             std::to_string(kMaxSceneFileBytes >> 20) + " MiB");
        }
    }
    if (in.bad()) throw SceneError(source + ": read error");
    return parseScene(text, source, overrides);
}

}  // namespace psb
