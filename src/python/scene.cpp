// Scenes for Python: load_scene and parse_scene (the core's one loader, overrides included),
// and the scene's parts as objects whose fields can be changed (scene.world.restitution = 0.9).
// A changed scene is checked as a file is when a World is made from it (checkScene).

#include <fstream>
#include <iterator>
#include <sstream>

#include <pybind11/operators.h>
#include <pybind11/stl.h>

#include <particle_sandbox/error.hpp>
#include <particle_sandbox/scene.hpp>

#include "bindings.hpp"
#include "scene_handle.hpp"

namespace psb::python {

namespace {

std::vector<SceneOverride> toOverrides(const std::vector<std::pair<std::string, std::string>>& o) {
    std::vector<SceneOverride> out;
    for (const auto& [path, value] : o)
        out.push_back({path, value, "override " + path, true});
    return out;
}

std::vector<std::pair<std::string, std::string>> fromOverrides(
    const std::vector<SceneOverride>& o) {
    std::vector<std::pair<std::string, std::string>> out;
    for (const SceneOverride& s : o)
        out.emplace_back(s.path, s.value);
    return out;
}

PyScene parsed(std::string text, std::string source, std::vector<SceneOverride> overrides) {
    PyScene s;
    static_cast<Scene&>(s) = parseScene(text, source, overrides);
    s.source = std::move(source);
    s.text = std::move(text);
    s.overrides = std::move(overrides);
    return s;
}

py::tuple colorTuple(const Color& c) {
    return py::make_tuple(c.r, c.g, c.b);
}

Color colorOf(const py::sequence& c) {
    if (py::len(c) != 3) throw py::value_error("color: expected (r, g, b), each 0..255");
    int v[3];
    for (int k = 0; k < 3; ++k) {
        v[k] = c[py::int_(k)].cast<int>();
        if (v[k] < 0 || v[k] > 255) throw py::value_error("color: expected (r, g, b), each 0..255");
    }
    return Color{static_cast<std::uint8_t>(v[0]), static_cast<std::uint8_t>(v[1]),
                 static_cast<std::uint8_t>(v[2])};
}

/// A Vec2 member as an (x, y) tuple property.
template <typename T>
void vecProperty(py::class_<T>& c, const char* name, Vec2 T::*member, const char* doc) {
    c.def_property(
        name, [member](const T& t) { return toTuple(t.*member); },
        [member, name](T& t, const py::sequence& v) { t.*member = toVec2(v, name); }, doc);
}

}  // namespace

void checkScene(const PyScene& scene) {
    // The file's checks, with the file's messages: what a scene file can get wrong, a scene
    // changed from Python can too.
    std::string text;
    try {
        text = serializeScene(scene);
    } catch (const InvalidArgument& e) {  // a number JSON cannot hold: "particles[3].vx is ..."
        throw SceneError(scene.source + ": " + e.what());
    }
    (void)parseScene(text, scene.source);
}

void bindScene(py::module_& m) {
    py::class_<ParticleDef> pd(m, "ParticleDef", "A particle as a scene lists it.");
    pd.def(py::init<>());
    vecProperty(pd, "position", &ParticleDef::position, "centre (x, y), metres");
    vecProperty(pd, "velocity", &ParticleDef::velocity, "m/s");
    pd.def_readwrite("mass", &ParticleDef::mass, "kg, > 0")
        .def_readwrite("radius", &ParticleDef::radius, "metres, > 0")
        .def_readwrite("angle", &ParticleDef::angle, "radians")
        .def_readwrite("spin", &ParticleDef::angularVelocity, "angular velocity, rad/s")
        .def_readwrite("inertia_factor", &ParticleDef::inertiaFactor, "k in I = k m r^2")
        .def_readwrite("fixed_rotation", &ParticleDef::fixedRotation)
        .def_property(
            "color", [](const ParticleDef& d) { return colorTuple(d.color); },
            [](ParticleDef& d, const py::sequence& c) { d.color = colorOf(c); });
    py::bind_vector<std::vector<ParticleDef>>(m, "ParticleDefList");

    py::class_<Obstacle> ob(m, "Obstacle",
                            "A fixed peg or segment: Obstacle.peg(centre, radius) or "
                            "Obstacle.segment(a, b, thickness), metres.");
    ob.def_static(
          "peg",
          [](const py::sequence& centre, double radius) {
              return Obstacle::peg(toVec2(centre, "centre"), radius);
          },
          py::arg("centre"), py::arg("radius"))
        .def_static(
            "segment",
            [](const py::sequence& a, const py::sequence& b, double thickness) {
                return Obstacle::segment(toVec2(a, "a"), toVec2(b, "b"), thickness);
            },
            py::arg("a"), py::arg("b"), py::arg("thickness"))
        .def_property_readonly("kind",
                               [](const Obstacle& o) { return o.isPeg() ? "peg" : "segment"; })
        .def_property_readonly(
            "a", [](const Obstacle& o) { return toTuple(o.a); },
            "a peg's centre or a segment's first end, metres")
        .def_property_readonly(
            "b", [](const Obstacle& o) { return toTuple(o.b); },
            "a segment's second end (a peg's centre), metres")
        .def_readonly("radius", &Obstacle::radius, "a peg's radius or half a segment's thickness")
        .def(py::self == py::self)
        .def("__repr__", [](const Obstacle& o) {
            std::ostringstream s;
            if (o.isPeg()) {
                s << "Obstacle.peg((" << o.a.x() << ", " << o.a.y() << "), " << o.radius << ")";
            } else {
                s << "Obstacle.segment((" << o.a.x() << ", " << o.a.y() << "), (" << o.b.x() << ", "
                  << o.b.y() << "), " << o.thickness() << ")";
            }
            return s.str();
        });
    py::bind_vector<std::vector<Obstacle>>(m, "ObstacleList");

    py::class_<Dropper> dr(m, "Dropper", "A ball dropper (a Galton board's funnel).");
    dr.def(py::init<>());
    vecProperty(dr, "position", &Dropper::position, "where a ball's centre starts, metres");
    vecProperty(dr, "velocity", &Dropper::velocity, "each ball's velocity when released, m/s");
    dr.def_readwrite("balls", &Dropper::balls, "balls still to drop")
        .def_readwrite("interval", &Dropper::interval, "seconds between balls")
        .def_readwrite("radius", &Dropper::radius, "each ball's radius, metres")
        .def_readwrite("mass", &Dropper::mass, "each ball's mass, kg")
        .def_readwrite("spread", &Dropper::spread, "release points within +-spread of x, metres")
        .def_readwrite("seed", &Dropper::seed, "picks the offsets within the spread")
        .def_readwrite("released", &Dropper::released, "balls dropped so far")
        .def_property(
            "color", [](const Dropper& d) { return colorTuple(d.color); },
            [](Dropper& d, const py::sequence& c) { d.color = colorOf(c); });
    py::bind_vector<std::vector<Dropper>>(m, "DropperList");

    py::class_<WorldDef> wd(m, "WorldDef", "The box, its obstacles and the material laws.");
    wd.def(py::init<>())
        .def_readwrite("width", &WorldDef::width, "metres, > 0")
        .def_readwrite("height", &WorldDef::height, "metres, > 0")
        .def_readwrite("walls", &WorldDef::walls)
        .def_readwrite("periodic", &WorldDef::periodic, "opposite edges joined")
        .def_readwrite("restitution", &WorldDef::restitution, "e in [0, 1]")
        .def_readwrite("friction", &WorldDef::friction, "Coulomb coefficient, >= 0")
        .def_readwrite("tangential_restitution", &WorldDef::tangentialRestitution,
                       "beta in [-1, 1]")
        .def_readwrite("obstacles", &WorldDef::obstacles, "the fixed pegs and segments");
    vecProperty(wd, "gravity", &WorldDef::gravity, "(gx, gy), m/s^2; y points down");

    py::class_<SolverSettings> ss(m, "SolverSettings", "How a world steps.");
    ss.def(py::init<>())
        .def_property(
            "mode", [](const SolverSettings& s) { return std::string(toString(s.mode)); },
            [](SolverSettings& s, const std::string& name) {
                const std::optional<StepMode> mode = parseStepMode(name);
                if (!mode) {
                    throw py::value_error("mode: expected 'discrete', 'substep' or 'exact' (got '" +
                                          name + "')");
                }
                s.mode = *mode;
            },
            "'discrete', 'substep' or 'exact'")
        .def_readwrite("substeps", &SolverSettings::substeps)
        .def_property(
            "broadphase",
            [](const SolverSettings& s) { return std::string(toString(s.broadphase)); },
            [](SolverSettings& s, const std::string& name) {
                const std::optional<BroadPhaseKind> k = parseBroadPhase(name);
                if (!k) {
                    throw py::value_error(
                        "broadphase: expected 'auto', 'all-pairs', 'grid' or 'quadtree' (got '" +
                        name + "')");
                }
                s.broadphase = *k;
            });

    py::class_<PyScene>(m, "Scene", R"(A scene: a world, how to step it, and its particles.

Its fields can be changed (scene.world.restitution = 0.9, scene.particles[3].mass = 2.0,
scene.solver.mode = 'exact', scene.dt = 0.005); World(scene) checks them as a scene file is
checked and raises SceneError with the file's message for a value out of range.)")
        .def(py::init<>(), "An empty scene (the default 700 m box, no particles).")
        .def_readwrite("name", &PyScene::name)
        .def_readwrite("description", &PyScene::description)
        .def_readwrite("dt", &PyScene::dt, "the frame length, seconds: World.dt")
        .def_readonly("version", &PyScene::version)
        .def_readwrite("world", &PyScene::world)
        .def_readwrite("solver", &PyScene::solver)
        .def_readwrite("particles", &PyScene::particles)
        .def_readwrite("droppers", &PyScene::droppers)
        .def_readwrite("allow_overlaps", &PyScene::allowOverlaps)
        .def_readonly("source", &PyScene::source, "the file or text it came from, for messages")
        .def_readonly("file_text", &PyScene::text,
                      "the JSON it was read from (generate blocks unexpanded), or None")
        .def_property_readonly(
            "overrides", [](const PyScene& s) { return fromOverrides(s.overrides); },
            "the (path, JSON value) overrides applied when it was read")
        .def(
            "to_json", [](const PyScene& s) { return serializeScene(s); },
            "The scene as scene-file JSON (doubles read back bit for bit).")
        .def(
            "save", [](const PyScene& s, const std::string& path) { saveScene(s, path); },
            py::arg("path"), "Writes the scene file atomically; OSError saying why on failure.")
        .def("check", &checkScene,
             "Raises SceneError if the scene, as changed, would not be a valid scene file.")
        .def("__copy__", [](const PyScene& s) { return PyScene(s); })
        .def("__deepcopy__", [](const PyScene& s, const py::dict&) { return PyScene(s); })
        .def(py::pickle(
            [](const PyScene& s) {
                return py::make_tuple(serializeScene(s), s.source, s.text,
                                      fromOverrides(s.overrides));
            },
            [](const py::tuple& t) {
                PyScene s = parsed(t[0].cast<std::string>(), t[1].cast<std::string>(), {});
                s.text = t[2].cast<std::optional<std::string>>();
                s.overrides =
                    toOverrides(t[3].cast<std::vector<std::pair<std::string, std::string>>>());
                return s;
            }));

    m.def(
        "_load_scene",
        [](const std::string& path, const std::vector<std::pair<std::string, std::string>>& o) {
            const std::vector<SceneOverride> overrides = toOverrides(o);
            PyScene s;
            static_cast<Scene&>(s) = loadScene(path, overrides);  // its checks and messages
            std::ifstream in(path, std::ios::binary);
            s.text = std::string(std::istreambuf_iterator<char>(in), {});
            s.source = path;
            s.overrides = overrides;
            return s;
        },
        py::arg("path"), py::arg("overrides"));
    m.def(
        "_parse_scene",
        [](const std::string& text, const std::string& source,
           const std::vector<std::pair<std::string, std::string>>& o) {
            return parsed(text, source, toOverrides(o));
        },
        py::arg("text"), py::arg("source"), py::arg("overrides"));
}

}  // namespace psb::python
