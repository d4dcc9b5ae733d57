#include "cli_app.hpp"

#include <particle_sandbox/atomic_file.hpp>
#include <particle_sandbox/data_tables.hpp>
#include <particle_sandbox/error.hpp>
#include <particle_sandbox/scene.hpp>

#include "observables_csv.hpp"
#include "output_check.hpp"
#include "progress_bar.hpp"
#include "report.hpp"
#include "run_options.hpp"
#include "runner.hpp"
#include "time_series_csv.hpp"

namespace psb::cli {

int runCli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err,
           bool errIsTerminal) {
    RunOptions options;
    try {
        options = parseRunOptions(args);
    } catch (const HelpRequested& help) {
        out << help.what();
        return kExitOk;
    } catch (const UsageError& e) {
        err << "particle-sim: error: " << e.what() << "\nRun 'particle-sim --help' for usage.\n";
        return kExitUsage;
    }

    try {
        // Before the scene is read and long before the last step: a bad output path costs
        // nothing yet.
        checkOutputs(options);
        const Scene scene = loadScene(options.scene, options.sets);
        World world;
        RunReport report;
        TimeSeries series(1);
        Trajectory track;
        {
            ProgressBar bar(err, errIsTerminal, options.progress);
            report = runScene(
                scene, options, world,
                [&bar](std::uint64_t done, std::uint64_t total) { bar.update(done, total); },
                options.timeseries ? &series : nullptr, options.track.empty() ? nullptr : &track);
        }
        if (options.timeseries) {
            writeFileAtomically(*options.timeseries,
                                timeSeriesCsv(series, report.gravity, report.rotation));
        }
        if (!options.track.empty()) {
            writeFileAtomically(trackPath(*options.timeseries),
                                trajectoryTable(track, csv::Separator::Comma, report.rotation));
        }
        if (report.observables) {
            if (options.gr)
                writeFileAtomically(*options.gr, pairDistributionCsv(*report.observables));
            if (options.msd) writeFileAtomically(*options.msd, msdCsv(*report.observables));
            if (options.vacf) writeFileAtomically(*options.vacf, vacfCsv(*report.observables));
        }
        if (options.save) {
            // The frame length the run stepped by (--dt's, if given) goes with the state.
            Scene saved = sceneFromWorld(world, report.dt, scene.name, scene.description);
            saved.bins = scene.bins;
            saveScene(saved, *options.save);
        }
        const std::string json = reportJson(report);
        if (!options.report || *options.report == "-") {
            out << json << std::flush;
        } else {
            writeFileAtomically(*options.report, json);
        }
        if (report.cutShort > 0) {
            // Not the run asked for: its state lags the time asked (the report says by how much).
            err << "particle-sim: error: " << report.cutShort
                << " exact step(s) ended before their end; the run reached t = " << report.simTime
                << " s, not the whole duration\n";
            return kExitFailure;
        }
        return kExitOk;
    } catch (const UsageError& e) {
        err << "particle-sim: error: " << e.what() << "\n";
        return kExitUsage;
    } catch (const SceneError& e) {
        err << "particle-sim: error: " << e.what() << "\n";
        return kExitFailure;
    } catch (const OutputError& e) {
        err << "particle-sim: error: " << e.what() << "\n";
        return kExitFailure;
    } catch (const SaveError& e) {
        err << "particle-sim: error: " << e.what() << "\n";
        return kExitFailure;
    } catch (const std::exception& e) {
        err << "particle-sim: error: " << e.what() << "\n";
        return kExitFailure;
    }
}

}  // namespace psb::cli
