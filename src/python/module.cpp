// particle_sandbox._core: the core library as a Python module. The package around it
// (python/particle_sandbox) re-exports these names and adds plot and sweep.

#include "bindings.hpp"

PYBIND11_MODULE(_core, m) {
    m.doc() = "The particle world, its scenes and observables (the C++ core of particle_sandbox).";
    psb::python::bindErrors(m);
    psb::python::bindScene(m);
    psb::python::bindWorld(m);
    psb::python::bindObservables(m);
    psb::python::bindCollisions(m);
    psb::python::bindSweepRun(m);
}
