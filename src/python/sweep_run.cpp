// One run of a sweep, made by particle-sim's own runner (src/cli/runner.hpp): the scene's text
// with the overrides applied, a warm-up, then the measured run with the observables window.
// A sweep's numbers are therefore the ones particle-sim --observables reports for the same
// scene and options.

#include <pybind11/stl.h>

#include <particle_sandbox/scene.hpp>

#include "observables_dict.hpp"
#include "runner.hpp"

namespace psb::python {

void bindSweepRun(py::module_& m) {
    m.def(
        "_run_scene",
        [](const std::string& text, const std::string& source,
           const std::vector<std::pair<std::string, std::string>>& overrides, double duration,
           double warmup, std::optional<std::uint64_t> seed, std::optional<std::string> mode,
           std::optional<double> dt, bool observables) {
            cli::RunOptions o;
            for (const auto& [path, value] : overrides)
                o.sets.push_back({path, value, path, true});
            // As particle-sim --seed: the generate block's seed, which must be there.
            if (seed) o.sets.push_back({"generate.seed", std::to_string(*seed), "seed", false});
            o.duration = duration;
            o.warmup = warmup;
            o.dt = dt;
            if (mode) {
                o.mode = parseStepMode(*mode);
                if (!o.mode) {
                    throw py::value_error("mode: expected 'discrete', 'substep' or 'exact' (got '" +
                                          *mode + "')");
                }
            }
            o.threads = 1;
            o.observables = observables;
            cli::RunReport report;
            {
                py::gil_scoped_release release;
                const Scene scene = parseScene(text, source, o.sets);
                World world;
                report = cli::runScene(scene, o, world);
            }
            py::dict row = report.observables ? observablesRow(*report.observables) : py::dict();
            if (report.bins) {
                // The scene's bins at the end (a Galton board's): counts left to right, and the
                // balls that missed them or have not come down yet.
                const BinCounts& b = report.bins->counts;
                row["bins"] = b.counts;
                row["bins_counted"] = b.counted();
                row["bins_outside"] = b.outside;
                row["bins_above"] = b.above;
            }
            // Particles when the measured part began (after the warm-up), as the report's.
            if (!report.observables) row["particles"] = report.particles;
            row["steps"] = report.steps;
            row["collisions"] = report.collisions;
            row["wall_collisions"] = report.wallCollisions;
            return row;
        },
        py::arg("text"), py::arg("source"), py::arg("overrides"), py::arg("duration"),
        py::arg("warmup"), py::arg("seed") = py::none(), py::arg("mode") = py::none(),
        py::arg("dt") = py::none(), py::arg("observables") = true,
        "One run as particle-sim (--observables) makes it; its observables, and the scene's bins "
        "when it has some, as a flat dict.");
}

}  // namespace psb::python
