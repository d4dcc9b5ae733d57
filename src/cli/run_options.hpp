#pragma once
// The runner's command line: what particle-sim was asked to do, checked.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <particle_sandbox/scene.hpp>
#include <particle_sandbox/solver_settings.hpp>

namespace psb::cli {

/// Everything the command line says. Solver fields left empty keep the scene's values.
struct RunOptions {
    std::filesystem::path scene;
    /// --set PATH=VALUE in order, then --seed N as generate.seed: applied to the scene's JSON
    /// before it is read (SceneOverride).
    std::vector<SceneOverride> sets;
    double duration = 0.0;  ///< simulated seconds, finite and >= 0
    std::optional<StepMode> mode;
    std::optional<double> dt;  ///< seconds, finite and > 0
    std::optional<int> substeps;
    std::optional<BroadPhaseKind> broadphase;
    int threads = 1;                    ///< requested worker threads, >= 1
    std::optional<std::string> report;  ///< a path, or "-" for stdout; stdout when empty
    std::optional<std::filesystem::path> save;
    /// Where to write the observables as CSV (see time_series_csv.hpp); none: not written.
    std::optional<std::filesystem::path> timeseries;
    /// A --timeseries row every this many steps (>= 1); the first and the last step always.
    std::int64_t timeseriesEvery = 1;
    /// --track: the numbers of the particles whose paths are written beside the time series
    /// (particleNumber: 1 for the first in the scene's particle list), in the order given;
    /// empty: none.
    std::vector<std::uint32_t> track;
    bool progress = false;
    /// --warmup: simulated seconds run before the measured --duration (finite, >= 0); the
    /// report's counts and energies cover the measured part only.
    double warmup = 0.0;
    /// --observables: measure the observables over the run (observables.hpp) into the report's
    /// `observables` object; --gr, --msd and --vacf imply it.
    bool observables = false;
    std::optional<std::filesystem::path> gr;    ///< --gr: g(r) as CSV (r_m,g)
    std::optional<std::filesystem::path> msd;   ///< --msd: t_s,msd_m2
    std::optional<std::filesystem::path> vacf;  ///< --vacf: t_s,vacf_m2_per_s2
    /// --max-lag: the MSD's and VACF's longest lag, seconds (> 0); implies `observables`.
    std::optional<double> maxLag;
};

/// A command line that cannot be run; what() says which option and why.
class UsageError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

/// `--help` or `--version` was given; what() is the text to print (on stdout, exit status 0).
class HelpRequested : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

/// Parses argv (argv[0] is the program name). Throws UsageError or HelpRequested.
[[nodiscard]] RunOptions parseRunOptions(const std::vector<std::string>& args);

/// Strict number parsing for options: the whole text must be a finite number (no NaN, no
/// infinity, no overflow such as 1e999). Throws UsageError naming `option`.
[[nodiscard]] double parseFiniteNumber(const std::string& text, const std::string& option);
/// The whole text must be a decimal integer in [lo, hi]. Throws UsageError naming `option`.
[[nodiscard]] std::int64_t parseInteger(const std::string& text, const std::string& option,
                                        std::int64_t lo, std::int64_t hi);

/// --track's list: particle numbers (decimal integers >= 1) separated by commas, none twice.
/// Throws UsageError naming the item that is wrong.
[[nodiscard]] std::vector<std::uint32_t> parseTrackList(const std::string& text);

/// Steps of `dt` that cover `duration`: duration / dt rounded up, except that a quotient
/// within 1e-9 (relative) of an integer counts as that integer, so 1 s at 0.01 s is 100 steps
/// although 1 / 0.01 is 100.00000000000001 in doubles. Throws UsageError above 1e15 steps.
[[nodiscard]] std::uint64_t stepsFor(double duration, double dt);

}  // namespace psb::cli
