// NumPy views of the world's structure-of-arrays storage: no copy, read-only, valid while the
// count of particles is unchanged (see PyWorld for what keeps them valid).
//
// positions and velocities are (N, 2) over two separate vectors (x and y): axis 0 steps one
// double, axis 1 steps the byte distance from x's buffer to y's, so row i is (x[i], y[i]).
// NumPy takes any byte strides, negative too; both buffers hold doubles, so the distance is a
// multiple of their alignment and the view is aligned.

#include <cstdint>

#include <pybind11/numpy.h>

#include "world_handle.hpp"

namespace psb::python {

namespace {

/// What angles and spins read in a world that keeps no rotation (every particle at 0): one
/// zero, repeated by a stride of 0.
const double kZero = 0.0;

py::array readOnly(py::array a) {
    py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
    return a;
}

py::array column(const double* data, std::size_t n, std::ptrdiff_t stride, py::handle base) {
    const std::vector<py::ssize_t> shape{static_cast<py::ssize_t>(n)};
    const std::vector<py::ssize_t> strides{static_cast<py::ssize_t>(stride)};
    return readOnly(py::array(py::dtype::of<double>(), shape, strides, data, base));
}

py::array pairs(const std::vector<double>& x, const std::vector<double>& y, py::handle base) {
    const std::size_t n = x.size();
    if (n == 0) {
        // An empty (0, 2) array has no buffer to point into.
        return readOnly(py::array(py::dtype::of<double>(), std::vector<py::ssize_t>{0, 2}));
    }
    const auto between = static_cast<py::ssize_t>(reinterpret_cast<std::intptr_t>(y.data()) -
                                                  reinterpret_cast<std::intptr_t>(x.data()));
    const std::vector<py::ssize_t> shape{static_cast<py::ssize_t>(n), 2};
    const std::vector<py::ssize_t> strides{sizeof(double), between};
    return readOnly(py::array(py::dtype::of<double>(), shape, strides, x.data(), base));
}

}  // namespace

StorageLease::StorageLease(py::object owner) : owner_(std::move(owner)) {
    owner_.cast<PyWorld&>().leaseOpened();
}

StorageLease::~StorageLease() {
    owner_.cast<PyWorld&>().leaseClosed();
}

py::array particleView(const py::object& owner, Field field) {
    PyWorld& w = owner.cast<PyWorld&>();
    w.world();  // refuses while another thread steps it
    // The lease first: the first one reserves the droppers' balls, which may move the storage.
    py::object lease = py::cast(new StorageLease(owner), py::return_value_policy::take_ownership);
    const ParticleArrays& p = w.view().particles();
    const std::size_t n = p.size();
    switch (field) {
        case Field::Positions:
            return pairs(p.x, p.y, lease);
        case Field::Velocities:
            return pairs(p.vx, p.vy, lease);
        case Field::Masses:
            return column(p.mass.data(), n, sizeof(double), lease);
        case Field::Radii:
            return column(p.radius.data(), n, sizeof(double), lease);
        case Field::Angles:
            return p.rotation ? column(p.angle.data(), n, sizeof(double), lease)
                              : column(&kZero, n, 0, lease);
        case Field::Spins:
            return p.rotation ? column(p.omega.data(), n, sizeof(double), lease)
                              : column(&kZero, n, 0, lease);
        case Field::Ids: {
            static_assert(sizeof(ParticleId) == sizeof(std::uint64_t));
            const std::vector<py::ssize_t> shape{static_cast<py::ssize_t>(n)};
            const std::vector<py::ssize_t> strides{sizeof(std::uint64_t)};
            return readOnly(
                py::array(py::dtype::of<std::uint64_t>(), shape, strides, p.id.data(), lease));
        }
    }
    throw std::logic_error("particleView: unknown field");
}

void bindArrays(py::module_& m) {
    py::class_<StorageLease>(m, "_StorageLease",
                             "Keeps a World alive while a view of its storage lives.");
}

}  // namespace psb::python
