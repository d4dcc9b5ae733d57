#include "run_options.hpp"

#include <CLI/CLI.hpp>

#include <particle_sandbox/csv.hpp>

#include "build_info.hpp"
#include "parse_error_message.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>

namespace psb::cli {
namespace {

constexpr const char* kDescription =
    "Runs a Particle Sandbox scene without a window and reports what happened.\n"
    "Options given here override the scene's \"solver\" block. The report (JSON) goes to\n"
    "stdout unless --report names a file. Exit status: 0 done, 1 the scene or a file could\n"
    "not be read or written, 2 bad command line.";

constexpr const char* kFooter =
    "Report fields: mode, dt, substeps, broadphase (the one used), threads, particles, steps,\n"
    "sim_time, wall_seconds, collisions, wall_collisions, obstacles, obstacle_collisions,\n"
    "kinetic_energy {initial, final}, rotational_energy {initial, final}, with gravity\n"
    "potential_energy and mechanical_energy {initial, final} (height measured from the\n"
    "floor), momentum {initial, final}, angular_momentum {initial, final} (orbital + spin,\n"
    "about the top-left corner), wall_impulse, max_overlap, escaped; with bins, bins\n"
    "{counts, ..., chi_square}; with ball droppers, droppers [{released, left}]; with\n"
    "--warmup, warmup (seconds); with --observables, observables {temperature,\n"
    "pressure_virial, pressure_walls, compressibility_factor, collision_rate,\n"
    "wall_collision_rate, mean_free_path, diffusion_msd, diffusion_vacf: each {value,\n"
    "error}, ..., notes}. See\n"
    "docs/scenes.md and docs/observables.md.\n"
    "--timeseries columns: time_s, kinetic_energy_J, momentum_x_kg_m_per_s,\n"
    "momentum_y_kg_m_per_s, com_x_m, com_y_m, collisions, collision_rate_per_s; with gravity\n"
    "also potential_energy_J, mechanical_energy_J; with discs that turn also\n"
    "rotational_energy_J, angular_momentum_kg_m2_per_s.\n"
    "--track writes NAME-track.EXT beside the --timeseries file NAME.EXT, at the same rows:\n"
    "time_s, particle, x_m, y_m, vx_m_per_s, vy_m_per_s (the app's trajectory columns).";

std::string joined(std::initializer_list<std::string_view> names) {
    std::string s;
    for (auto n : names)
        s += (s.empty() ? "" : ", ") + std::string(n);
    return s;
}

}  // namespace

double parseFiniteNumber(const std::string& text, const std::string& option) {
    double v = 0.0;
    const char* first = text.data();
    const char* last = first + text.size();
    const auto [ptr, ec] = std::from_chars(first, last, v);
    if (text.empty() || ec == std::errc::invalid_argument || ptr != last) {
        throw UsageError(option + ": expected a number, got '" + text + "'");
    }
    if (ec == std::errc::result_out_of_range || !std::isfinite(v)) {
        throw UsageError(option + ": must be a finite number, got '" + text + "'");
    }
    return v;
}

std::int64_t parseInteger(const std::string& text, const std::string& option, std::int64_t lo,
                          std::int64_t hi) {
    std::int64_t v = 0;
    const char* first = text.data();
    const char* last = first + text.size();
    const auto [ptr, ec] = std::from_chars(first, last, v);
    if (text.empty() || ec == std::errc::invalid_argument || ptr != last) {
        throw UsageError(option + ": expected an integer, got '" + text + "'");
    }
    if (ec == std::errc::result_out_of_range || v < lo || v > hi) {
        throw UsageError(option + ": must be in [" + std::to_string(lo) + ", " +
                         std::to_string(hi) + "], got '" + text + "'");
    }
    return v;
}

std::vector<std::uint32_t> parseTrackList(const std::string& text) {
    std::vector<std::uint32_t> ids;
    if (text.empty()) throw UsageError("--track: needs particle numbers, e.g. --track 1,4");
    std::size_t start = 0;
    for (;;) {
        const std::size_t comma = text.find(',', start);
        const std::string item =
            text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        if (item.empty()) {
            throw UsageError("--track: an empty item in '" + text +
                             "' (particle numbers separated by commas, e.g. 1,4)");
        }
        const auto id = static_cast<std::uint32_t>(
            parseInteger(item, "--track", 1, std::numeric_limits<std::uint32_t>::max() - 1));
        if (std::find(ids.begin(), ids.end(), id) != ids.end())
            throw UsageError("--track: particle " + item + " is listed twice");
        ids.push_back(id);
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    return ids;
}

std::uint64_t stepsFor(double duration, double dt) {
    const double q = duration / dt;
    if (!(q <= 1e15)) {
        throw UsageError("--duration / --dt: " + csv::number(q) +
                         " steps is more than the limit of 1e15");
    }
    const double nearest = std::round(q);
    if (std::abs(q - nearest) <= 1e-9 * std::max(1.0, q))
        return static_cast<std::uint64_t>(nearest);
    return static_cast<std::uint64_t>(std::ceil(q));
}

RunOptions parseRunOptions(const std::vector<std::string>& args) {
    CLI::App app(kDescription, "particle-sim");
    app.footer(kFooter);
    app.set_help_flag("-h,--help", "Print this help and exit");
    app.set_version_flag("--version", versionLine("particle-sim"),
                         "Print the version (and git revision) and exit");

    std::string scene, duration, mode, dt, substeps, broadphase, threads, report, save;
    std::string timeseries, timeseriesEvery, track, seed, warmup, gr, msd, vacf, maxLag;
    bool observables = false;
    std::vector<std::string> sets;
    bool progress = false;
    app.add_option("SCENE", scene, "Scene file (JSON, see docs/scenes.md)")->required();
    app.add_option("--set", sets,
                   "Change the scene before it is read: the value at PATH (keys joined by dots, "
                   "array elements by index, e.g. world.restitution, generate[1].count) set to "
                   "VALUE (JSON; other text is a string); repeatable, later ones win")
        ->type_name("PATH=VALUE")
        ->allow_extra_args(false);
    app.add_option("--seed", seed,
                   "The generate block's random seed (as --set generate.seed=N; a scene with "
                   "several blocks says which with --set generate[K].seed=N)")
        ->type_name("N");
    app.add_option("-d,--duration", duration, "Simulated time to run, seconds (>= 0)")
        ->required()
        ->type_name("SECONDS");
    app.add_option("--mode", mode, "Step mode: " + joined({"discrete", "substep", "exact"}))
        ->type_name("M");
    app.add_option("--dt", dt, "Time step, seconds (> 0)")->type_name("S");
    app.add_option("--substeps", substeps, "Substeps per step for --mode substep (>= 1)")
        ->type_name("K");
    app.add_option("--broadphase", broadphase,
                   "Broadphase: " + joined({"auto", "all-pairs", "grid", "quadtree"}))
        ->type_name("B");
    app.add_option("--threads", threads, "Worker threads (>= 1; recorded in the report)")
        ->type_name("N");
    app.add_option("--report", report, "Write the JSON report to PATH, or '-' for stdout")
        ->type_name("PATH|-");
    app.add_option("--save", save, "Save the final state as a scene file")->type_name("PATH");
    app.add_option("--timeseries", timeseries,
                   "Write kinetic energy, momentum, centre of mass and collision rate against "
                   "simulated time as CSV to PATH")
        ->type_name("PATH");
    app.add_option("--timeseries-every", timeseriesEvery,
                   "A --timeseries row every N steps (default 1; the initial and final states "
                   "always)")
        ->type_name("N");
    app.add_option("--track", track,
                   "Also write these particles' positions and velocities at each --timeseries "
                   "row, to NAME-track.csv beside it (a particle's number is the app's: 1 for "
                   "the first in the scene's particle list)")
        ->type_name("ID,ID,...");
    app.add_option("--warmup", warmup,
                   "Run this many simulated seconds first (>= 0), then the --duration that is "
                   "measured and reported")
        ->type_name("SECONDS");
    app.add_flag("--observables", observables,
                 "Measure temperature, pressures, Z, collision rate, mean free path and "
                 "diffusion with their errors into the report's \"observables\" object");
    app.add_option("--gr", gr,
                   "Write the radial distribution function as CSV (r_m,g); "
                   "implies --observables")
        ->type_name("PATH");
    app.add_option("--msd", msd,
                   "Write the mean-squared displacement against lag time as CSV "
                   "(t_s,msd_m2); implies --observables")
        ->type_name("PATH");
    app.add_option("--vacf", vacf,
                   "Write the velocity autocorrelation against lag time as CSV "
                   "(t_s,vacf_m2_per_s2); implies --observables")
        ->type_name("PATH");
    app.add_option("--max-lag", maxLag,
                   "The MSD and VACF up to this lag time, seconds (> 0; default: 20 free times, "
                   "or less where a disc would diffuse an eighth of the box; with it, a time "
                   "origin every sixteenth of it); implies --observables")
        ->type_name("SECONDS");
    app.add_flag("--progress", progress,
                 "Show a progress bar on stderr (only when stderr is a terminal; long runs "
                 "show one anyway)");

    // CLI11 wants argv-style input in reverse order.
    std::vector<std::string> rest(args.size() > 1 ? args.begin() + 1 : args.end(), args.end());
    std::reverse(rest.begin(), rest.end());
    try {
        app.parse(rest);
    } catch (const CLI::CallForHelp&) {
        throw HelpRequested(app.help());
    } catch (const CLI::CallForVersion& version) {
        throw HelpRequested(std::string(version.what()) + "\n");
    } catch (const CLI::ParseError& e) {
        throw UsageError(parseErrorMessage(app, e));
    }

    RunOptions o;
    if (scene.empty()) throw UsageError("SCENE: the path is empty");
    o.scene = scene;
    for (const std::string& set : sets) {
        const std::size_t eq = set.find('=');
        if (eq == std::string::npos || eq == 0) {
            throw UsageError("--set: expected PATH=VALUE, as in world.restitution=0.9, got '" +
                             set + "'");
        }
        o.sets.push_back({set.substr(0, eq), set.substr(eq + 1)});
    }
    if (!seed.empty()) {
        const std::int64_t n =
            parseInteger(seed, "--seed", 0, std::numeric_limits<std::int64_t>::max());
        o.sets.push_back({"generate.seed", std::to_string(n), "--seed", false});
    }
    o.duration = parseFiniteNumber(duration, "--duration");
    if (o.duration < 0.0) throw UsageError("--duration: must be >= 0, got '" + duration + "'");
    if (!mode.empty()) {
        o.mode = parseStepMode(mode);
        if (!o.mode) {
            throw UsageError("--mode: unknown mode '" + mode + "' (expected one of: " +
                             joined({"discrete", "substep", "exact"}) + ")");
        }
    }
    if (!dt.empty()) {
        o.dt = parseFiniteNumber(dt, "--dt");
        if (!(*o.dt > 0.0)) throw UsageError("--dt: must be > 0, got '" + dt + "'");
    }
    if (!substeps.empty()) {
        o.substeps = static_cast<int>(parseInteger(substeps, "--substeps", 1, kMaxSubsteps));
    }
    if (!broadphase.empty()) {
        o.broadphase = parseBroadPhase(broadphase);
        if (!o.broadphase) {
            throw UsageError(
                "--broadphase: unknown broadphase '" + broadphase +
                "' (expected one of: " + joined({"auto", "all-pairs", "grid", "quadtree"}) + ")");
        }
    }
    if (!threads.empty()) o.threads = static_cast<int>(parseInteger(threads, "--threads", 1, 1024));
    if (app.count("--report") > 0) {
        if (report.empty()) throw UsageError("--report: needs a path or '-'");
        o.report = report;
    }
    if (app.count("--save") > 0) {
        if (save.empty()) throw UsageError("--save: needs a path");
        o.save = save;
    }
    if (app.count("--timeseries") > 0) {
        if (timeseries.empty()) throw UsageError("--timeseries: needs a path");
        o.timeseries = timeseries;
    }
    if (!timeseriesEvery.empty()) {
        o.timeseriesEvery = parseInteger(timeseriesEvery, "--timeseries-every", 1,
                                         std::numeric_limits<std::int64_t>::max());
        if (!o.timeseries) throw UsageError("--timeseries-every: needs --timeseries PATH");
    }
    if (app.count("--track") > 0) {
        o.track = parseTrackList(track);
        if (!o.timeseries) throw UsageError("--track: needs --timeseries PATH");
    }
    if (!warmup.empty()) {
        o.warmup = parseFiniteNumber(warmup, "--warmup");
        if (o.warmup < 0.0) throw UsageError("--warmup: must be >= 0, got '" + warmup + "'");
    }
    const auto path = [&app](const std::string& option,
                             const std::string& value) -> std::optional<std::filesystem::path> {
        if (app.count(option) == 0) return std::nullopt;
        if (value.empty()) throw UsageError(option + ": needs a path");
        return std::filesystem::path(value);
    };
    o.gr = path("--gr", gr);
    o.msd = path("--msd", msd);
    o.vacf = path("--vacf", vacf);
    if (!maxLag.empty()) {
        o.maxLag = parseFiniteNumber(maxLag, "--max-lag");
        if (!(*o.maxLag > 0.0)) throw UsageError("--max-lag: must be > 0, got '" + maxLag + "'");
    }
    o.observables = observables || o.gr || o.msd || o.vacf || o.maxLag;
    o.progress = progress;
    return o;
}

}  // namespace psb::cli
