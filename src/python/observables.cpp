// The observables of a hard-disc gas (observables.hpp) for Python: World.measure runs a window
// of measurement, and Observables holds what it found, each value with its standard error.

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <particle_sandbox/observables.hpp>

#include "observables_dict.hpp"
#include "run_options.hpp"
#include "world_handle.hpp"

namespace psb::python {

namespace {

py::array_t<double> arrayOf(const std::vector<double>& v) {
    return py::array_t<double>(static_cast<py::ssize_t>(v.size()), v.data());
}

}  // namespace

const std::vector<std::pair<const char*, Measured ObservablesResult::*>>& measuredFields() {
    static const std::vector<std::pair<const char*, Measured ObservablesResult::*>> fields = {
        {"temperature", &ObservablesResult::temperature},
        {"rotational_temperature", &ObservablesResult::rotationalTemperature},
        {"pressure_virial", &ObservablesResult::pressureVirial},
        {"pressure_walls", &ObservablesResult::pressureWalls},
        {"compressibility_factor", &ObservablesResult::compressibilityFactor},
        {"contact_value", &ObservablesResult::contactValue},
        {"collision_rate", &ObservablesResult::collisionRate},
        {"wall_collision_rate", &ObservablesResult::wallCollisionRate},
        {"mean_free_path", &ObservablesResult::meanFreePath},
        {"diffusion_msd", &ObservablesResult::diffusionMsd},
        {"diffusion_vacf", &ObservablesResult::diffusionVacf},
    };
    return fields;
}

py::dict observablesRow(const ObservablesResult& r) {
    py::dict d;
    for (const auto& [name, member] : measuredFields()) {
        d[name] = (r.*member).value;
        d[(std::string(name) + "_error").c_str()] = (r.*member).error;
    }
    d["packing_fraction"] = r.packingFraction;
    d["particles"] = r.particles;
    d["blocks"] = r.blocks;
    d["henderson_compressibility_factor"] = r.hendersonZ;
    d["henderson_contact_value"] = r.hendersonContact;
    d["liu_compressibility_factor"] = r.liuZ;
    d["enskog_collision_rate"] = r.enskogCollisionRate;
    d["enskog_mean_free_path"] = r.enskogMeanFreePath;
    d["enskog_diffusion"] = r.enskogDiffusion;
    // What is missing or in doubt (a NaN's reason), one string: a table's cell holds it.
    std::string notes;
    for (const std::string& note : r.notes)
        notes += (notes.empty() ? "" : "; ") + note;
    d["notes"] = notes;
    return d;
}

void bindObservables(py::module_& m) {
    py::class_<Measured>(m, "Measured", "A measured value and its standard error (NaN: none).")
        .def_readonly("value", &Measured::value)
        .def_readonly("error", &Measured::error)
        .def("__iter__",
             [](const Measured& x) { return py::iter(py::make_tuple(x.value, x.error)); })
        .def("__repr__", [](const Measured& x) {
            return "Measured(value=" + py::repr(py::float_(x.value)).cast<std::string>() +
                   ", error=" + py::repr(py::float_(x.error)).cast<std::string>() + ")";
        });

    py::class_<ObservablesResult> o(m, "Observables", R"(What a window of measurement found.

Two dimensions: pressures are N/m, areas m^2; errors are standard errors by block averaging
(NaN with fewer than 8 blocks, said in notes). The conventions are the core's (docs/observables.md).)");
    for (const auto& [name, member] : measuredFields()) {
        const auto mp = member;
        o.def_property_readonly(name, [mp](const ObservablesResult& r) { return r.*mp; });
    }
    o.def_readonly("particles", &ObservablesResult::particles)
        .def_readonly("duration", &ObservablesResult::duration,
                      "simulated seconds the window spans")
        .def_readonly("blocks", &ObservablesResult::blocks, "full blocks the errors come from")
        .def_readonly("area", &ObservablesResult::area, "A', m^2")
        .def_readonly("density", &ObservablesResult::density, "N / A', 1/m^2")
        .def_readonly("packing_fraction", &ObservablesResult::packingFraction)
        .def_readonly("henderson_compressibility_factor", &ObservablesResult::hendersonZ)
        .def_readonly("henderson_contact_value", &ObservablesResult::hendersonContact)
        .def_readonly("liu_compressibility_factor", &ObservablesResult::liuZ,
                      "Liu's simulation-based Z of the hard-disc fluid (NaN past its range)")
        .def_readonly("enskog_collision_rate", &ObservablesResult::enskogCollisionRate)
        .def_readonly("enskog_mean_free_path", &ObservablesResult::enskogMeanFreePath)
        .def_readonly("enskog_diffusion", &ObservablesResult::enskogDiffusion)
        .def_property_readonly(
            "pair_r", [](const ObservablesResult& r) { return arrayOf(r.pairR); },
            "g(r)'s bin centres, metres")
        .def_property_readonly(
            "pair_g", [](const ObservablesResult& r) { return arrayOf(r.pairG); }, "g(r)")
        .def_property_readonly("lag_time",
                               [](const ObservablesResult& r) { return arrayOf(r.lagTime); })
        .def_property_readonly(
            "msd", [](const ObservablesResult& r) { return arrayOf(r.msd); },
            "mean-squared displacement, m^2")
        .def_property_readonly(
            "vacf", [](const ObservablesResult& r) { return arrayOf(r.vacf); },
            "velocity autocorrelation, m^2/s^2")
        .def_readonly("notes", &ObservablesResult::notes)
        .def("as_dict", &observablesRow,
             "The values as {name: value, name_error: error, ...} (a sweep's row).");

    auto world = py::reinterpret_borrow<py::class_<PyWorld>>(m.attr("World"));
    world.def(
        "measure",
        [](PyWorld& self, double duration, std::optional<double> dt, bool correlations,
           bool pairs) {
            const double d = dt.value_or(self.dt());
            if (!std::isfinite(d) || !(d > 0.0))
                throw py::value_error("dt: must be finite and > 0");
            if (!std::isfinite(duration) || !(duration > 0.0)) {
                throw py::value_error("duration: must be finite and > 0");
            }
            ObservablesWindow window(
                suggestedObservablesSettings(self.view(), d, correlations, pairs));
            World& w = self.world();
            window.open(w);
            const std::uint64_t steps = cli::stepsFor(duration, d);
            {
                PyWorld::Busy busy(self);
                py::gil_scoped_release release;
                for (std::uint64_t k = 0; k < steps; ++k) {
                    w.step(d);
                    window.sample(w);
                }
            }
            return window.close(w);
        },
        py::arg("duration"), py::arg("dt") = py::none(), py::arg("correlations") = true,
        py::arg("pairs") = false,
        R"(Runs `duration` seconds in steps of dt (default World.dt), sampling after each step, and
returns the Observables of that window, as particle-sim --observables measures them:
correlations adds the MSD and VACF, pairs g(r) and its contact value. Releases the GIL.)");
}

}  // namespace psb::python
