#pragma once
// The work–precision sweep: standard scenes, each run in every mode at a range of step sizes,
// with cost and errors measured against the exact mode's run of the same scene.
//
// For each scene the exact mode runs once (the reference; its frames are the scene's dt, which
// does not change its trajectory). The discrete mode runs at dt = frame dt × each factor of the
// plan; the substep mode runs at the frame dt with each k of the plan. A substep row is run as
// k discrete steps of dt / k per frame, which is what World::step does in the substep mode, so
// that every discrete move can be checked for missed collisions (accuracy_metrics.hpp). The
// cost is the wall time inside World::step only; the checks between steps are not counted.

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <particle_sandbox/scene.hpp>

#include "accuracy_metrics.hpp"

namespace psb::cli {

/// A standard scene of the sweep: a scene file and how long to run it.
struct AccuracyScene {
    std::string name;            ///< short name for tables ("dilute-gas")
    std::filesystem::path file;  ///< scene file; its dt (Scene::dt) is the frame dt
    double duration = 1.0;       ///< simulated seconds
};

/// The standard scenes (the six of the issue, a bullet at 10^4 times the speed of a row, three
/// under gravity, two of a rolling disc);
/// `root` is the source tree (files under assets/scenes, bench/scenes).
[[nodiscard]] std::vector<AccuracyScene> standardScenes(const std::filesystem::path& root);

/// Which step sizes to try.
struct SweepPlan {
    std::vector<double> dtFactors;  ///< discrete dt = frame dt × factor
    std::vector<int> substeps;      ///< substep k at the frame dt
    double durationScale = 1.0;     ///< scales every scene's duration (a quick smoke run)
    /// Each run is timed this many times and the fastest kept (the machine is shared; the
    /// fastest is the least disturbed), short runs more often, until 0.1 s of
    /// them were timed (at most 50). Only the first run checks the moves.
    int repeats = 1;
};

/// The sweep docs/accuracy.md reports: dt from 4 frames down to 1/16 frame, k from 2 to 32,
/// each run timed 3 times.
[[nodiscard]] SweepPlan fullPlan();
/// Two discrete dt, one k, 5 % of the durations: a smoke run of a few seconds.
[[nodiscard]] SweepPlan quickPlan();

/// One row of the table.
struct AccuracyRow {
    std::string scene;
    StepMode mode = StepMode::Discrete;
    double dt = 0.0;  ///< seconds per World::step call (a frame)
    int substeps = 1;
    RunTotals totals;
    ErrorMeasures errors;
};

/// Runs `scene` in `mode` (Discrete, Substep or Exact) with frames of dt and k substeps (only
/// for Substep) for `duration` simulated seconds, and measures it. With `checkMoves` false the
/// missed collisions and the overlap are not measured (a timing-only repeat). Throws what
/// makeWorld throws.
[[nodiscard]] RunTotals runMeasured(const Scene& scene, StepMode mode, double dt, int substeps,
                                    double duration, bool checkMoves = true);

/// Called once per finished row, for progress output.
using RowFn = std::function<void(const AccuracyRow&)>;

/// Loads every scene (throws SceneError) and runs the plan; rows grouped by scene, exact first.
[[nodiscard]] std::vector<AccuracyRow> runSweep(const std::vector<AccuracyScene>& scenes,
                                                const SweepPlan& plan, const RowFn& onRow = {});

/// The rows as CSV (header line first; NaN written as an empty field).
[[nodiscard]] std::string accuracyCsv(const std::vector<AccuracyRow>& rows);
/// The rows as a Markdown table, three significant digits, NaN as "—".
[[nodiscard]] std::string accuracyMarkdown(const std::vector<AccuracyRow>& rows);

}  // namespace psb::cli
