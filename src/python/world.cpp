// World for Python: the core's World with snake_case names, ids as integers, NumPy views of
// its storage, and steps that release the GIL.

#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <string>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <particle_sandbox/diagnostics.hpp>
#include <particle_sandbox/error.hpp>
#include <particle_sandbox/observables.hpp>
#include <particle_sandbox/scene.hpp>

#include "run_options.hpp"
#include "scene_handle.hpp"
#include "world_handle.hpp"

namespace psb::python {

// --- PyWorld -------------------------------------------------------------------------------

void PyWorld::checkIdle() const {
    if (busy_) {
        throw std::runtime_error(
            "World: busy stepping in another thread; wait for its step() or run() to return");
    }
}

World& PyWorld::world() {
    checkIdle();
    return world_;
}

const World& PyWorld::view() const {
    checkIdle();
    return world_;
}

void PyWorld::setDt(double dt) {
    if (!std::isfinite(dt) || !(dt > 0.0)) {
        throw InvalidArgument("World.dt: must be finite and > 0 (got " + std::to_string(dt) + ")");
    }
    dt_ = dt;
}

std::size_t PyWorld::pendingBalls() const {
    std::size_t n = 0;
    for (const Dropper& d : world_.droppers())
        n += d.balls;
    return n;
}

std::size_t PyWorld::capacity() const {
    const ParticleArrays& p = world_.particles();
    std::size_t c = std::min({p.x.capacity(), p.y.capacity(), p.vx.capacity(), p.vy.capacity(),
                              p.mass.capacity(), p.radius.capacity(), p.id.capacity()});
    if (p.rotation) c = std::min({c, p.angle.capacity(), p.omega.capacity()});
    return c;
}

void PyWorld::ensureRoom(std::size_t extra, const char* what) {
    const std::size_t need = world_.size() + extra;
    if (need <= capacity() || views_ == 0) return;
    throw py::buffer_error(
        std::string(what) + ": the particle storage is full (" + std::to_string(capacity()) +
        " particles) and a NumPy view of it is alive; growing would move the storage under the "
        "view. Delete the views first (del positions, ...), or call World.reserve(n) before "
        "taking them");
}

void PyWorld::leaseOpened() {
    // Steps release the droppers' balls with World::add: make room for them now, so that no
    // step moves the storage under this view. Only vectors below `need` move, and none a live
    // view reads is: each had room for `need` when its view was taken, and while views live
    // `need` grows only through ensureRoom. (Rotation arrays a step made since then, with room
    // for the particles alone, are read by no view yet.)
    const std::size_t need = world_.size() + pendingBalls();
    if (need > capacity()) world_.reserve(need);
    ++views_;
}

PyWorld::Busy::Busy(PyWorld& w) : w_(w) {
    w.checkIdle();
    w.busy_ = true;
}

// --- helpers -------------------------------------------------------------------------------

namespace {

std::size_t stepCount(double duration, double dt, const char* where) {
    if (!std::isfinite(duration) || duration < 0.0) {
        throw InvalidArgument(std::string(where) + ": duration must be finite and >= 0 (got " +
                              std::to_string(duration) + ")");
    }
    if (!(duration / dt <= 1e15)) {
        throw InvalidArgument(std::string(where) + ": duration / dt is more than 1e15 steps");
    }
    // particle-sim's rule: a quotient within 1e-9 of an integer counts as that integer.
    return static_cast<std::size_t>(cli::stepsFor(duration, dt));
}

/// Steps `w` `steps` times by `dt` with the GIL released, looking for Ctrl+C every so often.
/// `after` runs after each step (still without the GIL).
template <typename After>
void stepMany(PyWorld& self, std::size_t steps, double dt, After after) {
    World& world = self.world();
    PyWorld::Busy busy(self);
    {
        py::gil_scoped_release release;
        // Ctrl+C is looked for between steps, 256 steps apart (a few microseconds each time).
        constexpr std::size_t kSignalEvery = 256;
        for (std::size_t k = 0; k < steps; ++k) {
            world.step(dt);
            after();
            if ((k + 1) % kSignalEvery == 0 && k + 1 < steps) {
                py::gil_scoped_acquire acquire;
                if (PyErr_CheckSignals() != 0) throw py::error_already_set();
            }
        }
    }
    // Views read the arrays: let them see the state of an exact step now, not on the next read.
    if (self.views() > 0) (void)world.particles();
}

void applySolver(World& world, const std::optional<std::string>& mode,
                 const std::optional<int>& substeps) {
    if (!mode && !substeps) return;
    SolverSettings s = world.solver();
    if (mode) {
        const std::optional<StepMode> m = parseStepMode(*mode);
        if (!m) {
            throw py::value_error("mode: expected 'discrete', 'substep' or 'exact' (got '" + *mode +
                                  "')");
        }
        s.mode = *m;
    }
    if (substeps) s.substeps = *substeps;
    world.setSolver(s);
}

ParticleId idArg(std::uint64_t id) {
    return fromPython(id);
}

Color toColor(const py::handle& c) {
    const auto fail = [&c] {
        return py::value_error("color: expected three integers 0..255 (r, g, b), got " +
                               std::string(py::repr(c)));
    };
    if (py::len(c) != 3) throw fail();
    int v[3];
    for (int k = 0; k < 3; ++k) {
        v[k] = py::int_(c[py::int_(k)]).cast<int>();
        if (v[k] < 0 || v[k] > 255) throw fail();
    }
    return Color{static_cast<std::uint8_t>(v[0]), static_cast<std::uint8_t>(v[1]),
                 static_cast<std::uint8_t>(v[2])};
}

const char* const kAddDoc = R"(Adds a particle and returns its id.

position: centre (x, y), metres; velocity: m/s; mass: kg (finite, > 0); radius: metres (> 0);
angle: radians; spin: angular velocity, rad/s (positive turns +x toward +y); inertia_factor: k in
I = k m r^2 (0.001 to 1); fixed_rotation: never turns; color: (r, g, b), 0..255.
Overlaps are allowed (the next step separates them). Raises ValueError with the core's message
for a value out of range, BufferError if the storage is full while a view of it lives.)";

}  // namespace

void bindWorld(py::module_& m) {
    bindArrays(m);

    py::class_<Particle>(m, "Particle", "A copy of one particle's state (World.get).")
        .def_property_readonly("id", [](const Particle& p) { return toPython(p.id); })
        .def_property_readonly(
            "position", [](const Particle& p) { return toTuple(p.position); },
            "centre (x, y), metres")
        .def_property_readonly(
            "velocity", [](const Particle& p) { return toTuple(p.velocity); }, "m/s")
        .def_readonly("mass", &Particle::mass, "kg")
        .def_readonly("radius", &Particle::radius, "metres")
        .def_readonly("angle", &Particle::angle, "radians")
        .def_readonly("spin", &Particle::angularVelocity, "angular velocity, rad/s")
        .def_readonly("inertia_factor", &Particle::inertiaFactor, "k in I = k m r^2")
        .def_readonly("fixed_rotation", &Particle::fixedRotation)
        .def_property_readonly(
            "color",
            [](const Particle& p) { return py::make_tuple(p.color.r, p.color.g, p.color.b); })
        .def("__repr__", [](const Particle& p) {
            return "Particle(position=(" + std::to_string(p.position.x()) + ", " +
                   std::to_string(p.position.y()) + "), velocity=(" +
                   std::to_string(p.velocity.x()) + ", " + std::to_string(p.velocity.y()) +
                   "), mass=" + std::to_string(p.mass) + ", radius=" + std::to_string(p.radius) +
                   ")";
        });

    py::class_<PyWorld> w(m, "World",
                          R"(The particle world: a box, its laws, its particles, and the step.

World(scene) builds the scene's world (its box, laws, solver settings, particles and droppers);
the scene's dt is the world's default step (World.dt). Particles are named by integer ids that
stay valid while the particle lives; positions, velocities, angles, spins, masses, radii and
ids are read-only NumPy views of the world's storage (row i of each is the same particle).)");

    w.def(py::init([](const PyScene& scene) {
              checkScene(scene);
              return new PyWorld(makeWorld(scene), scene.dt);
          }),
          py::arg("scene"),
          "Builds the world the scene describes. Raises SceneError (a ValueError) with the "
          "scene file's message for a value out of range.");

    w.def("__repr__", [](PyWorld& self) {
        const World& world = self.view();
        std::ostringstream s;
        s << "World(" << world.size() << " particles, time " << world.time() << " s, "
          << toString(world.solver().mode) << ", box " << world.def().width << " x "
          << world.def().height << " m)";
        return s.str();
    });

    // --- time -----------------------------------------------------------------------------
    w.def(
         "step",
         [](PyWorld& self, std::optional<double> dt) {
             const double d = dt.value_or(self.dt());
             double done = 0.0;
             World& world = self.world();
             {
                 PyWorld::Busy busy(self);
                 py::gil_scoped_release release;
                 done = world.step(d);
             }
             if (self.views() > 0) (void)world.particles();
             return done;
         },
         py::arg("dt") = py::none(),
         "Advances the world by dt seconds (default World.dt) in its mode; returns the seconds "
         "simulated. Releases the GIL.")
        .def(
            "run",
            [](PyWorld& self, double duration, std::optional<std::string> mode,
               std::optional<double> dt, std::optional<int> substeps) {
                if (dt) self.setDt(*dt);
                applySolver(self.world(), mode, substeps);
                const std::size_t steps = stepCount(duration, self.dt(), "World.run");
                stepMany(self, steps, self.dt(), [] {});
                return steps;
            },
            py::arg("duration"), py::arg("mode") = py::none(), py::arg("dt") = py::none(),
            py::arg("substeps") = py::none(),
            R"(Runs the world for `duration` seconds in steps of dt, as particle-sim --duration does
(duration / dt steps, rounded up; a quotient within 1e-9 of an integer is that integer). mode
('discrete', 'substep', 'exact'), dt and substeps, when given, become the world's own settings
first. Returns the number of steps. Releases the GIL; Ctrl+C stops it between steps.)")
        .def_property_readonly(
            "time", [](PyWorld& self) { return self.view().time(); },
            "simulated seconds since the world was made")
        .def_property(
            "dt", [](const PyWorld& self) { return self.dt(); }, &PyWorld::setDt,
            "the default step length, seconds (the scene's dt)")
        .def_property(
            "mode", [](PyWorld& self) { return std::string(toString(self.view().solver().mode)); },
            [](PyWorld& self, const std::string& mode) {
                applySolver(self.world(), mode, std::nullopt);
            },
            "'discrete', 'substep' or 'exact'")
        .def_property(
            "substeps", [](PyWorld& self) { return self.view().solver().substeps; },
            [](PyWorld& self, int n) { applySolver(self.world(), std::nullopt, n); },
            "steps of dt / substeps in the substep mode")
        .def_property(
            "broadphase",
            [](PyWorld& self) { return std::string(toString(self.view().solver().broadphase)); },
            [](PyWorld& self, const std::string& name) {
                const std::optional<BroadPhaseKind> k = parseBroadPhase(name);
                if (!k) {
                    throw py::value_error(
                        "broadphase: expected 'auto', 'all-pairs', 'grid' or 'quadtree' (got '" +
                        name + "')");
                }
                SolverSettings s = self.world().solver();
                s.broadphase = *k;
                self.world().setSolver(s);
            })
        .def_property(
            "threads", [](PyWorld& self) { return self.view().threads(); },
            [](PyWorld& self, int n) { self.world().setThreads(n); },
            "threads a step may use (0: one per hardware thread); results are the same for any")
        .def_property(
            "exact_event_budget", [](PyWorld& self) { return self.view().exactEventBudget(); },
            [](PyWorld& self, std::uint64_t n) { self.world().setExactEventBudget(n); },
            "exact mode: most events per particle a step may process (0: no limit)");

    // --- box and laws -----------------------------------------------------------------------
    w.def_property(
         "box",
         [](PyWorld& self) {
             return py::make_tuple(self.view().def().width, self.view().def().height);
         },
         [](PyWorld& self, const py::sequence& wh) {
             const Vec2 v = toVec2(wh, "box");
             self.world().setBox(v.x(), v.y());
         },
         "(width, height), metres")
        .def_property(
            "walls", [](PyWorld& self) { return self.view().def().walls; },
            [](PyWorld& self, bool on) { self.world().setWalls(on); })
        .def_property(
            "periodic", [](PyWorld& self) { return self.view().def().periodic; },
            [](PyWorld& self, bool on) { self.world().setPeriodic(on); },
            "whether the box's opposite edges are joined")
        .def_property(
            "gravity", [](PyWorld& self) { return toTuple(self.view().def().gravity); },
            [](PyWorld& self, const py::sequence& g) {
                self.world().setGravity(toVec2(g, "gravity"));
            },
            "(gx, gy), m/s^2; y points down")
        .def_property(
            "restitution", [](PyWorld& self) { return self.view().def().restitution; },
            [](PyWorld& self, double e) { self.world().setRestitution(e); }, "e in [0, 1]")
        .def_property(
            "friction", [](PyWorld& self) { return self.view().def().friction; },
            [](PyWorld& self, double mu) { self.world().setFriction(mu); },
            "Coulomb coefficient, >= 0")
        .def_property(
            "tangential_restitution",
            [](PyWorld& self) { return self.view().def().tangentialRestitution; },
            [](PyWorld& self, double b) { self.world().setTangentialRestitution(b); },
            "beta in [-1, 1]")
        .def_property(
            "obstacles", [](PyWorld& self) { return self.view().obstacles(); },
            [](PyWorld& self, std::vector<Obstacle> o) { self.world().setObstacles(std::move(o)); },
            "the fixed pegs and segments (a copy; assign a list to change them)")
        .def(
            "add_obstacle",
            [](PyWorld& self, const Obstacle& o) { return self.world().addObstacle(o); },
            py::arg("obstacle"), "Appends an obstacle; returns its index.")
        .def(
            "remove_obstacle",
            [](PyWorld& self, std::size_t index) { self.world().removeObstacle(index); },
            py::arg("index"))
        .def_property(
            "droppers", [](PyWorld& self) { return self.view().droppers(); },
            [](PyWorld& self, std::vector<Dropper> d) {
                std::size_t balls = 0;
                for (const Dropper& x : d)
                    balls += x.balls;
                self.ensureRoom(balls, "World.droppers");
                self.world().setDroppers(std::move(d));
            },
            "the ball droppers and how far each has got (a copy; assign a list to change them)")
        .def_property_readonly(
            "rotation_in_use", [](PyWorld& self) { return self.view().rotationInUse(); },
            "whether the world keeps rotation state (angles, spins)");

    // --- particles --------------------------------------------------------------------------
    w.def(
         "add",
         [](PyWorld& self, const py::sequence& position, const py::sequence& velocity, double mass,
            double radius, double angle, double spin, double inertiaFactor, bool fixedRotation,
            const py::sequence& color) {
             ParticleDef d;
             d.position = toVec2(position, "position");
             d.velocity = toVec2(velocity, "velocity");
             d.mass = mass;
             d.radius = radius;
             d.angle = angle;
             d.angularVelocity = spin;
             d.inertiaFactor = inertiaFactor;
             d.fixedRotation = fixedRotation;
             d.color = toColor(color);
             self.ensureRoom(1, "World.add");
             return toPython(self.world().add(d));
         },
         py::arg("position"), py::arg("velocity") = py::make_tuple(0.0, 0.0), py::arg("mass") = 1.0,
         py::arg("radius") = 1.0, py::arg("angle") = 0.0, py::arg("spin") = 0.0,
         py::arg("inertia_factor") = kDefaultInertiaFactor, py::arg("fixed_rotation") = false,
         py::arg("color") = py::make_tuple(255, 255, 255), kAddDoc)
        .def(
            "add_many",
            [](PyWorld& self,
               const py::array_t<double, py::array::c_style | py::array::forcecast>& positions,
               const std::optional<py::array_t<double, py::array::c_style | py::array::forcecast>>&
                   velocities,
               const py::array_t<double, py::array::forcecast>& masses,
               const py::array_t<double, py::array::forcecast>& radii) {
                if (positions.ndim() != 2 || positions.shape(1) != 2) {
                    throw py::value_error("positions: expected shape (N, 2)");
                }
                const auto n = static_cast<std::size_t>(positions.shape(0));
                if (velocities &&
                    (velocities->ndim() != 2 || velocities->shape(0) != positions.shape(0) ||
                     velocities->shape(1) != 2)) {
                    throw py::value_error("velocities: expected shape (N, 2) like positions");
                }
                const auto perParticle = [n](const py::array_t<double, py::array::forcecast>& a,
                                             const char* what) {
                    if (a.ndim() == 0) return false;
                    if (a.ndim() != 1 || static_cast<std::size_t>(a.shape(0)) != n) {
                        throw py::value_error(std::string(what) +
                                              ": expected one number or shape (N,)");
                    }
                    return true;
                };
                const bool eachMass = perParticle(masses, "masses");
                const bool eachRadius = perParticle(radii, "radii");
                self.ensureRoom(n, "World.add_many");
                World& world = self.world();
                py::array_t<std::uint64_t> ids(static_cast<py::ssize_t>(n));
                auto out = ids.mutable_unchecked<1>();
                const auto pos = positions.unchecked<2>();
                std::size_t k = 0;
                try {
                    for (; k < n; ++k) {
                        ParticleDef d;
                        d.position = Vec2(pos(k, 0), pos(k, 1));
                        if (velocities) {
                            const auto vel = velocities->unchecked<2>();
                            d.velocity = Vec2(vel(k, 0), vel(k, 1));
                        }
                        d.mass = eachMass ? masses.at(k) : *masses.data();
                        d.radius = eachRadius ? radii.at(k) : *radii.data();
                        out(k) = toPython(world.add(d));
                    }
                } catch (const InvalidArgument& e) {
                    // All or nothing: the ones added before the bad one go again.
                    for (std::size_t j = 0; j < k; ++j)
                        world.remove(fromPython(out(j)));
                    throw InvalidArgument("particle " + std::to_string(k) + ": " + e.what());
                }
                return ids;
            },
            py::arg("positions"), py::arg("velocities") = py::none(), py::arg("masses") = 1.0,
            py::arg("radii") = 1.0,
            "Adds N particles from arrays (positions (N, 2) m, velocities (N, 2) m/s, masses and "
            "radii one number or (N,)); returns their ids. All or none: a bad value raises "
            "ValueError naming the particle's row and adds nothing.")
        .def(
            "remove",
            [](PyWorld& self, std::uint64_t id) { return self.world().remove(idArg(id)); },
            py::arg("id"), "Removes a particle; returns False if the id names no live particle.")
        .def(
            "clear",
            [](PyWorld& self) {
                World& world = self.world();
                if (self.views() == 0) {
                    world.clear();
                    return;
                }
                // World::clear frees the storage a view reads: remove one by one instead.
                for (const ParticleId id : world.ids())
                    world.remove(id);
            },
            "Removes every particle (obstacles and droppers stay).")
        .def(
            "reserve",
            [](PyWorld& self, std::size_t n) {
                if (n > self.world().size())
                    self.ensureRoom(n - self.world().size(), "World.reserve");
                self.world().reserve(n);
            },
            py::arg("n"), "Reserves storage for n particles, so that adding up to n moves nothing.")
        .def("__len__", [](PyWorld& self) { return self.view().size(); })
        .def("__contains__",
             [](PyWorld& self, std::uint64_t id) { return self.view().contains(idArg(id)); })
        .def(
            "get", [](PyWorld& self, std::uint64_t id) { return self.view().get(idArg(id)); },
            py::arg("id"), "A copy of the particle's state; ValueError for an id of no particle.")
        .def(
            "number",
            [](PyWorld& self, std::uint64_t id) {
                if (!self.view().contains(idArg(id))) {
                    throw py::value_error("World.number: no live particle has id " +
                                          std::to_string(id));
                }
                return particleNumber(idArg(id));
            },
            py::arg("id"),
            "The number people read for the particle (1 for the scene's first), as the app and "
            "particle-sim show it.")
        .def(
            "index_of",
            [](PyWorld& self, std::uint64_t id) { return self.view().indexOf(idArg(id)); },
            py::arg("id"),
            "The particle's row in the arrays (valid until the next add, remove or step), or None.")
        .def(
            "pick",
            [](PyWorld& self, const py::sequence& point) -> std::optional<std::uint64_t> {
                const std::optional<ParticleId> id = self.view().pick(toVec2(point, "point"));
                if (!id) return std::nullopt;
                return toPython(*id);
            },
            py::arg("point"), "The id of the topmost particle containing the point, or None.")
        .def(
            "unwrapped_position",
            [](PyWorld& self, std::uint64_t id) {
                return toTuple(self.view().unwrappedPosition(idArg(id)));
            },
            py::arg("id"), "The centre as if a periodic box's edges had never wrapped it, metres.");

    // Setters, each validated by the core.
    const auto setVec = [&w](const char* name, void (World::*set)(ParticleId, const Vec2&),
                             const char* doc) {
        w.def(
            name,
            [set, name](PyWorld& self, std::uint64_t id, const py::sequence& v) {
                (self.world().*set)(idArg(id), toVec2(v, name));
            },
            py::arg("id"), py::arg("value"), doc);
    };
    setVec("set_position", &World::setPosition, "Moves the particle's centre, metres.");
    setVec("set_velocity", &World::setVelocity, "Sets the particle's velocity, m/s.");
    const auto setNumber = [&w](const char* name, void (World::*set)(ParticleId, double),
                                const char* doc) {
        w.def(
            name,
            [set](PyWorld& self, std::uint64_t id, double v) { (self.world().*set)(idArg(id), v); },
            py::arg("id"), py::arg("value"), doc);
    };
    setNumber("set_mass", &World::setMass, "kg, finite and > 0");
    setNumber("set_radius", &World::setRadius, "metres, finite and > 0");
    setNumber("set_angle", &World::setAngle, "radians, finite");
    setNumber("set_spin", &World::setAngularVelocity, "angular velocity, rad/s, finite");
    setNumber("set_inertia_factor", &World::setInertiaFactor, "k in I = k m r^2, 0.001 to 1");
    w.def(
         "set_fixed_rotation",
         [](PyWorld& self, std::uint64_t id, bool on) {
             self.world().setFixedRotation(idArg(id), on);
         },
         py::arg("id"), py::arg("value"))
        .def(
            "set_kinematic",
            [](PyWorld& self, std::uint64_t id, bool on) {
                self.world().setKinematic(idArg(id), on);
            },
            py::arg("id"), py::arg("value"),
            "A kinematic (held) particle pushes others as if its mass were infinite.")
        .def(
            "set_color",
            [](PyWorld& self, std::uint64_t id, const py::sequence& c) {
                self.world().setColor(idArg(id), toColor(c));
            },
            py::arg("id"), py::arg("value"));

    // --- arrays -----------------------------------------------------------------------------
    const auto view = [&w](const char* name, Field f, const char* doc) {
        w.def_property_readonly(
            name, [f](const py::object& self) { return particleView(self, f); }, doc);
    };
    view("positions", Field::Positions,
         "(N, 2) centres, metres: a read-only view of the world's storage (no copy), valid while "
         "the count is unchanged. Change a particle with set_position.");
    view("velocities", Field::Velocities, "(N, 2) velocities, m/s: a read-only view.");
    view("masses", Field::Masses, "(N,) masses, kg: a read-only view.");
    view("radii", Field::Radii, "(N,) radii, metres: a read-only view.");
    view("angles", Field::Angles,
         "(N,) angles, radians: a read-only view (zeros, stride 0, while the world keeps no "
         "rotation: rotation_in_use).");
    view("spins", Field::Spins, "(N,) angular velocities, rad/s: a read-only view (as angles).");
    view("ids", Field::Ids,
         "(N,) ids (uint64) of the particles in storage order: a read-only view.");

    // --- diagnostics ------------------------------------------------------------------------
    w.def_property_readonly(
         "kinetic_energy", [](PyWorld& self) { return kineticEnergy(self.view()); },
         "translational, joules")
        .def_property_readonly(
            "rotational_energy", [](PyWorld& self) { return rotationalEnergy(self.view()); },
            "joules")
        .def_property_readonly(
            "potential_energy", [](PyWorld& self) { return potentialEnergy(self.view()); },
            "gravitational, joules (0 without gravity)")
        .def_property_readonly(
            "momentum", [](PyWorld& self) { return toTuple(momentum(self.view())); }, "kg m/s")
        .def_property_readonly(
            "counters",
            [](PyWorld& self) {
                const StepCounters& c = self.view().counters();
                py::dict d;
                d["steps"] = c.steps;
                d["collisions"] = c.collisions;
                d["wall_collisions"] = c.wallCollisions;
                d["obstacle_collisions"] = c.obstacleCollisions;
                d["wall_impulse"] = c.wallImpulse;
                d["max_overlap"] = c.maxOverlap;
                d["events"] = c.events;
                d["cut_short"] = c.cutShort;
                return d;
            },
            "what the steps did since the world was made or reset_counters()")
        .def("reset_counters", [](PyWorld& self) { self.world().resetCounters(); })
        .def(
            "to_scene",
            [](PyWorld& self, const std::string& name) {
                PyScene s;
                static_cast<Scene&>(s) = sceneFromWorld(self.view(), self.dt(), name);
                s.source = "<world>";
                return s;
            },
            py::arg("name") = "",
            "A scene of the world's current state (stepped by World.dt): save it, or make "
            "another World from it.");
}

}  // namespace psb::python
