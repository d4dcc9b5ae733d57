#pragma once
// The Python module's parts, one per concept of the core; module.cpp calls each in turn.

#include <bit>
#include <cstdint>
#include <utility>

#include <vector>

#include <pybind11/pybind11.h>
#include <pybind11/stl_bind.h>

#include <particle_sandbox/dropper.hpp>
#include <particle_sandbox/math.hpp>
#include <particle_sandbox/obstacle.hpp>
#include <particle_sandbox/particle.hpp>
#include <particle_sandbox/particle_id.hpp>

// Lists of the core's records are bound as Python sequences over the C++ vectors (so that
// scene.particles[3].mass = 2 changes the scene), in every file that uses them.
PYBIND11_MAKE_OPAQUE(std::vector<psb::ParticleDef>)
PYBIND11_MAKE_OPAQUE(std::vector<psb::Obstacle>)
PYBIND11_MAKE_OPAQUE(std::vector<psb::Dropper>)

namespace psb::python {

namespace py = pybind11;

/// Exceptions: the core's InvalidArgument as ValueError, SceneError as SceneError (a
/// ValueError), SaveError as OSError, each with the core's message.
void bindErrors(py::module_& m);
/// Scene, WorldDef, SolverSettings, ParticleDef, Obstacle, Dropper, load_scene, parse_scene.
void bindScene(py::module_& m);
/// World and its array views.
void bindWorld(py::module_& m);
/// Observables, Measured, ObservablesSettings.
void bindObservables(py::module_& m);
/// World.record_collisions, World.take_collisions (a NumPy structured array).
void bindCollisions(py::module_& m);
/// run_scene: one run as particle-sim makes it (the sweep's unit of work).
void bindSweepRun(py::module_& m);

/// A particle id as Python holds it: the 64 bits of ParticleId read as one unsigned integer,
/// the same number `World.ids` shows (an opaque handle; World.number gives the one people read).
inline std::uint64_t toPython(ParticleId id) {
    return std::bit_cast<std::uint64_t>(id);
}
inline ParticleId fromPython(std::uint64_t v) {
    return std::bit_cast<ParticleId>(v);
}

/// (x, y) as a tuple, and a sequence of two numbers as a Vec2.
inline py::tuple toTuple(const Vec2& v) {
    return py::make_tuple(v.x(), v.y());
}
Vec2 toVec2(const py::handle& seq, const char* what);

}  // namespace psb::python
