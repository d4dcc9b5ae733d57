// The collision log for Python: World.record_collisions starts it, World.take_collisions
// hands over what was recorded as a NumPy structured array, one row per collision.

#include <cstdint>
#include <optional>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <particle_sandbox/collision_log.hpp>

#include "world_handle.hpp"

namespace psb::python {

/// One row of the array take_collisions returns (its dtype's fields, in order).
struct CollisionRow {
    double time;          ///< s
    std::uint8_t with;    ///< 0 particle, 1 wall, 2 obstacle
    std::uint64_t a;      ///< id
    std::uint64_t b;      ///< id, or World.NO_PARTICLE
    std::uint32_t where;  ///< wall side (0 left, 1 right, 2 top, 3 bottom) or obstacle index
    double a_before[2];   ///< m/s
    double a_after[2];    ///< m/s
    double b_before[2];   ///< m/s
    double b_after[2];    ///< m/s
    double impulse[2];    ///< N s, on a
};

namespace {

void put(double (&out)[2], const Vec2& v) {
    out[0] = v.x();
    out[1] = v.y();
}

}  // namespace

void bindCollisions(py::module_& m) {
    PYBIND11_NUMPY_DTYPE(CollisionRow, time, with, a, b, where, a_before, a_after, b_before,
                         b_after, impulse);
    auto world = py::reinterpret_borrow<py::class_<PyWorld>>(m.attr("World"));
    world.attr("NO_PARTICLE") = toPython(kNullParticle);
    world
        .def(
            "record_collisions",
            [](PyWorld& self, std::optional<std::vector<std::uint64_t>> ids) {
                if (!ids) {
                    self.world().recordCollisions();
                    return;
                }
                std::vector<ParticleId> chosen;
                for (const std::uint64_t id : *ids)
                    chosen.push_back(fromPython(id));
                self.world().recordCollisions(CollisionLog(std::move(chosen)));
            },
            py::arg("ids") = py::none(),
            "Starts recording the collisions of the next steps: all, or only those involving one "
            "of `ids`. Recording or not, the steps' results are bit-identical.")
        .def("stop_recording_collisions",
             [](PyWorld& self) { self.world().stopRecordingCollisions(); })
        .def(
            "take_collisions",
            [](PyWorld& self) {
                const std::vector<Collision> records = self.world().takeCollisions();
                py::array_t<CollisionRow> out(static_cast<py::ssize_t>(records.size()));
                CollisionRow* row = out.mutable_data();
                for (const Collision& c : records) {
                    row->time = c.time;
                    row->with = static_cast<std::uint8_t>(c.with);
                    row->a = toPython(c.a);
                    row->b = toPython(c.b);
                    row->where = c.where;
                    put(row->a_before, c.aBefore);
                    put(row->a_after, c.aAfter);
                    put(row->b_before, c.bBefore);
                    put(row->b_after, c.bAfter);
                    put(row->impulse, c.impulse);
                    ++row;
                }
                return out;
            },
            R"(The collisions recorded since recording started or the last call, in the order the
steps resolved them, leaving the log empty: a NumPy structured array with fields time (s), with
(0 particle, 1 wall, 2 obstacle), a, b (ids; b is World.NO_PARTICLE but for pairs), where (wall:
0 left, 1 right, 2 top, 3 bottom; obstacle: its index), a_before, a_after, b_before, b_after
(m/s, shape (2,)) and impulse (N s on a, shape (2,)). Empty when not recording.)");
}

}  // namespace psb::python
