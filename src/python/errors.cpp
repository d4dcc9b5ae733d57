// The core's exceptions as Python's: a wrong argument is a ValueError, a scene that cannot be
// read a SceneError (a ValueError too), a failed save an OSError; the message is the core's.

#include <exception>

#include <particle_sandbox/error.hpp>
#include <particle_sandbox/scene.hpp>

#include "bindings.hpp"
#include "run_options.hpp"

namespace psb::python {

void bindErrors(py::module_& m) {
    static py::exception<SceneError> sceneError(m, "SceneError", PyExc_ValueError);
    sceneError.doc() =
        "A scene that cannot be read or is not valid; the message names the file, the JSON "
        "path and the problem, e.g. 'gas.json: particles[3].mass: must be > 0 (got -1)'.";
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const SceneError& e) {
            PyErr_SetString(sceneError.ptr(), e.what());
        } catch (const InvalidArgument& e) {
            PyErr_SetString(PyExc_ValueError, e.what());
        } catch (const cli::UsageError& e) {
            PyErr_SetString(PyExc_ValueError, e.what());
        } catch (const SaveError& e) {
            PyErr_SetString(PyExc_OSError, e.what());
        }
    });
}

Vec2 toVec2(const py::handle& seq, const char* what) {
    const auto fail = [what, &seq] {
        return py::value_error(std::string(what) + ": expected two numbers (x, y), got " +
                               std::string(py::repr(seq)));
    };
    if (!py::isinstance<py::sequence>(seq) && !py::hasattr(seq, "__len__")) throw fail();
    if (py::len(seq) != 2) throw fail();
    try {
        return Vec2(py::float_(seq[py::int_(0)]).cast<double>(),
                    py::float_(seq[py::int_(1)]).cast<double>());
    } catch (const py::error_already_set&) {
        throw fail();
    }
}

}  // namespace psb::python
