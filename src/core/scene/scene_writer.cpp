// Writing scene files: serializeScene and saveScene.
//
// Doubles are written in the shortest form that reads back as the same double
// (std::to_chars), always with a '.' or an exponent so that a JSON reader takes them as floats:
// "-0.0" keeps the sign of a negative zero, which "-0" (an integer) would lose. Save then load
// therefore reproduces every bit of the state. One particle per line keeps files diffable.

#include <algorithm>
#include <charconv>
#include <cmath>
#include <string>

#include <nlohmann/json.hpp>
#include <particle_sandbox/atomic_file.hpp>
#include <particle_sandbox/detail/float_chars.hpp>
#include <particle_sandbox/error.hpp>
#include <particle_sandbox/scene.hpp>

namespace psb {
namespace {

/// A number that JSON cannot hold, at `path` (the scene file's JSON path); serializeScene
/// refuses the scene with it.
struct NotFinite {
    std::string path;
};

void appendNumber(std::string& out, double v, const char* what) {
    if (!std::isfinite(v)) throw NotFinite{what};
    char buf[40];
    const auto r = detail::toChars(buf, buf + sizeof buf, v);
    const std::string_view text(buf, static_cast<std::size_t>(r.ptr - buf));
    out += text;
    if (text.find_first_of(".e") == std::string_view::npos) out += ".0";
}

/// Appends `prefix` (the text before the value: separator and key) and then the number.
void appendField(std::string& out, const char* prefix, double v, const char* what) {
    out += prefix;
    appendNumber(out, v, what);
}

/// Runs `append` for item `index` of the scene's list `list`, naming the item in a refusal:
/// field `vx` becomes `particles[3].vx`.
template <class Append>
void appendItem(const char* list, std::size_t index, Append&& append) {
    try {
        append();
    } catch (const NotFinite& e) {
        throw NotFinite{std::string(list) + "[" + std::to_string(index) + "]." + e.path};
    }
}

void appendString(std::string& out, const std::string& s) {
    // nlohmann escapes control characters and quotes; invalid UTF-8 is replaced, not thrown.
    out += nlohmann::json(s).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

void appendColor(std::string& out, Color c) {
    out +=
        '[' + std::to_string(c.r) + ", " + std::to_string(c.g) + ", " + std::to_string(c.b) + ']';
}

/// `"obstacles": [...]`, one per line, after a separator; nothing for a scene without any.
void appendObstacles(std::string& out, const Obstacles& obstacles) {
    if (obstacles.empty()) return;
    out += ",\n  \"obstacles\": [";
    for (std::size_t i = 0; i < obstacles.size(); ++i) {
        const Obstacle& o = obstacles[i];
        out += i == 0 ? "\n    " : ",\n    ";
        appendItem("obstacles", i, [&] {
            if (o.isPeg()) {
                appendField(out, "{\"type\": \"peg\", \"x\": ", o.a.x(), "x");
                appendField(out, ", \"y\": ", o.a.y(), "y");
                appendField(out, ", \"radius\": ", o.radius, "radius");
            } else {
                appendField(out, "{\"type\": \"segment\", \"from\": [", o.a.x(), "from");
                appendField(out, ", ", o.a.y(), "from");
                appendField(out, "], \"to\": [", o.b.x(), "to");
                appendField(out, ", ", o.b.y(), "to");
                appendField(out, "], \"thickness\": ", o.thickness(), "thickness");
            }
        });
        out += '}';
    }
    out += "\n  ]";
}

/// `"bins": {...}` after a separator; nothing for a scene without bins.
void appendBins(std::string& out, const std::optional<Bins>& bins) {
    if (!bins) return;
    out += ",\n  \"bins\": {\"edges\": [";
    for (std::size_t i = 0; i < bins->edges.size(); ++i)
        appendField(out, i == 0 ? "" : ", ", bins->edges[i], "bins.edges");
    appendField(out, "], \"top\": ", bins->top, "bins.top");
    if (const auto& b = bins->binomial) {
        out += ", \"expected\": {\"binomial\": {\"trials\": " + std::to_string(b->trials);
        appendField(out, ", \"p\": ", b->p, "bins.expected.binomial.p");
        out += "}}";
    }
    out += '}';
}

/// `"droppers": [...]`, one per line, after a separator; nothing for a scene without any.
void appendDroppers(std::string& out, const Droppers& droppers) {
    if (droppers.empty()) return;
    out += ",\n  \"droppers\": [";
    for (std::size_t i = 0; i < droppers.size(); ++i) {
        const Dropper& d = droppers[i];
        appendItem("droppers", i, [&] {
            appendField(out, i == 0 ? "\n    {\"x\": " : ",\n    {\"x\": ", d.position.x(), "x");
            appendField(out, ", \"y\": ", d.position.y(), "y");
            out += ", \"balls\": " + std::to_string(d.balls);
            appendField(out, ", \"interval\": ", d.interval, "interval");
            appendField(out, ", \"radius\": ", d.radius, "radius");
            appendField(out, ", \"mass\": ", d.mass, "mass");
            out += ", \"color\": ";
            appendColor(out, d.color);
            appendField(out, ", \"vx\": ", d.velocity.x(), "vx");
            appendField(out, ", \"vy\": ", d.velocity.y(), "vy");
            appendField(out, ", \"spread\": ", d.spread, "spread");
            out += ", \"seed\": " + std::to_string(d.seed);
            out += ", \"released\": " + std::to_string(d.released);
            appendField(out, ", \"next_ball_in\": ", d.nextIn, "next_ball_in");
        });
        out += '}';
    }
    out += "\n  ]";
}

/// The scene's JSON text; throws NotFinite.
std::string serializeFields(const Scene& s) {
    std::string out;
    out.reserve(512 + 160 * s.particles.size());
    out += "{\n  \"name\": ";
    appendString(out, s.name);
    out += ",\n  \"description\": ";
    appendString(out, s.description);
    // The lowest version that has everything the scene uses, so that older builds read it.
    int version = s.world.obstacles.empty() ? s.version : std::max(s.version, 2);
    if (s.bins) version = std::max(version, 3);
    if (!s.droppers.empty()) version = std::max(version, 4);
    const bool rotation =
        s.world.tangentialRestitution != 0.0 ||
        std::any_of(s.particles.begin(), s.particles.end(), [](const ParticleDef& p) {
            return p.angle != 0.0 || p.angularVelocity != 0.0 ||
                   p.inertiaFactor != kDefaultInertiaFactor || p.fixedRotation;
        });
    if (rotation) version = std::max(version, 5);
    if (s.world.periodic) version = std::max(version, 6);
    out += ",\n  \"version\": " + std::to_string(version);

    const WorldDef& w = s.world;
    appendField(out, ",\n  \"world\": {\"width\": ", w.width, "world.width");
    appendField(out, ", \"height\": ", w.height, "world.height");
    // A periodic box has no walls; its file says only that it is periodic (version 6).
    if (w.periodic) {
        out += ", \"periodic\": true";
    } else {
        out += w.walls ? ", \"walls\": true" : ", \"walls\": false";
    }
    appendField(out, ", \"gravity\": [", w.gravity.x(), "world.gravity");
    appendField(out, ", ", w.gravity.y(), "world.gravity");
    appendField(out, "], \"restitution\": ", w.restitution, "world.restitution");
    appendField(out, ", \"friction\": ", w.friction, "world.friction");
    if (w.tangentialRestitution != 0.0) {
        appendField(out, ", \"tangential_restitution\": ", w.tangentialRestitution,
                    "world.tangential_restitution");
    }
    out += "}";

    const SolverSettings& v = s.solver;
    out += ",\n  \"solver\": {\"mode\": \"";
    out += toString(v.mode);
    out += "\", \"dt\": ";
    appendNumber(out, s.dt, "solver.dt");
    out += ", \"substeps\": " + std::to_string(v.substeps) + ", \"broadphase\": \"";
    out += toString(v.broadphase);
    out += "\"}";
    if (s.allowOverlaps) out += ",\n  \"allow_overlaps\": true";

    appendObstacles(out, w.obstacles);
    appendBins(out, s.bins);
    appendDroppers(out, s.droppers);

    out += ",\n  \"particles\": [";
    for (std::size_t i = 0; i < s.particles.size(); ++i) {
        const ParticleDef& p = s.particles[i];
        appendItem("particles", i, [&] {
            appendField(out, i == 0 ? "\n    {\"x\": " : ",\n    {\"x\": ", p.position.x(), "x");
            appendField(out, ", \"y\": ", p.position.y(), "y");
            appendField(out, ", \"vx\": ", p.velocity.x(), "vx");
            appendField(out, ", \"vy\": ", p.velocity.y(), "vy");
            appendField(out, ", \"mass\": ", p.mass, "mass");
            appendField(out, ", \"radius\": ", p.radius, "radius");
            out += ", \"color\": ";
            appendColor(out, p.color);
            if (std::find(s.trails.begin(), s.trails.end(), i) != s.trails.end()) {
                out += ", \"trail\": true";
            }
            // Rotation only where it differs from the defaults: a scene without it stays as
            // it was.
            if (p.angle != 0.0) appendField(out, ", \"angle\": ", p.angle, "angle");
            if (p.angularVelocity != 0.0) {
                appendField(out, ", \"angular_velocity\": ", p.angularVelocity, "angular_velocity");
            }
            if (p.inertiaFactor != kDefaultInertiaFactor) {
                appendField(out, ", \"inertia_factor\": ", p.inertiaFactor, "inertia_factor");
            }
            if (p.fixedRotation) out += ", \"fixed_rotation\": true";
        });
        out += '}';
    }
    out += s.particles.empty() ? "]\n}\n" : "\n  ]\n}\n";
    return out;
}

}  // namespace

std::string serializeScene(const Scene& s) {
    try {
        return serializeFields(s);
    } catch (const NotFinite& e) {
        throw InvalidArgument(e.path + " is not finite");
    }
}

void saveScene(const Scene& scene, const std::filesystem::path& path) {
    std::string text;
    try {
        text = serializeScene(scene);
    } catch (const InvalidArgument& e) {
        throw SaveError("cannot save " + path.string() + ": " + e.what());
    }
    writeFileAtomically(path, text);
}

}  // namespace psb
