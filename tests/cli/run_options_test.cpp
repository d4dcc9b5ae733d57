// particle-sim's command line: what it accepts and how it refuses the rest.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "build_info.hpp"
#include "run_options.hpp"

namespace psb::cli {
namespace {

RunOptions parse(std::vector<std::string> args) {
    args.insert(args.begin(), "particle-sim");
    return parseRunOptions(args);
}

std::string usageError(std::vector<std::string> args) {
    try {
        (void)parse(std::move(args));
    } catch (const UsageError& e) {
        return e.what();
    }
    return "(accepted)";
}

TEST(RunOptions, DefaultsLeaveTheScenesSolverAlone) {
    const RunOptions o = parse({"gas.json", "--duration", "2.5"});
    EXPECT_EQ(o.scene, "gas.json");
    EXPECT_EQ(o.duration, 2.5);
    EXPECT_FALSE(o.mode);
    EXPECT_FALSE(o.dt);
    EXPECT_FALSE(o.substeps);
    EXPECT_FALSE(o.broadphase);
    EXPECT_EQ(o.threads, 1);
    EXPECT_FALSE(o.report);
    EXPECT_FALSE(o.save);
    EXPECT_FALSE(o.progress);
}

TEST(RunOptions, ReadsEveryOption) {
    const RunOptions o = parse({"--mode", "substep", "--dt", "1e-3", "--substeps", "4",
                                "--broadphase", "all-pairs", "--threads", "2", "--report", "-",
                                "--save", "out.json", "--progress", "s.json", "--duration=10"});
    EXPECT_EQ(o.scene, "s.json");
    EXPECT_EQ(o.duration, 10.0);
    EXPECT_EQ(o.mode, StepMode::Substep);
    EXPECT_EQ(o.dt, 1e-3);
    EXPECT_EQ(o.substeps, 4);
    EXPECT_EQ(o.broadphase, BroadPhaseKind::AllPairs);
    EXPECT_EQ(o.threads, 2);
    EXPECT_EQ(o.report, "-");
    EXPECT_EQ(o.save, "out.json");
    EXPECT_TRUE(o.progress);
}

TEST(RunOptions, RefusesBadNumbersWithTheOptionNamed) {
    EXPECT_EQ(usageError({"s", "--duration", "abc"}), "--duration: expected a number, got 'abc'");
    EXPECT_EQ(usageError({"s", "--duration", "1s"}), "--duration: expected a number, got '1s'");
    EXPECT_EQ(usageError({"s", "--duration", "nan"}),
              "--duration: must be a finite number, got 'nan'");
    EXPECT_EQ(usageError({"s", "--duration", "inf"}),
              "--duration: must be a finite number, got 'inf'");
    EXPECT_EQ(usageError({"s", "--duration", "1e999"}),
              "--duration: must be a finite number, got '1e999'");
    EXPECT_EQ(usageError({"s", "--duration=-1"}), "--duration: must be >= 0, got '-1'");
    EXPECT_EQ(usageError({"s", "--duration", "1", "--dt", "0"}), "--dt: must be > 0, got '0'");
    EXPECT_EQ(usageError({"s", "--duration", "1", "--dt", "-nan"}),
              "--dt: must be a finite number, got '-nan'");
    EXPECT_EQ(usageError({"s", "--duration", "1", "--substeps", "0"}),
              "--substeps: must be in [1, 100000], got '0'");
    EXPECT_EQ(usageError({"s", "--duration", "1", "--threads", "0"}),
              "--threads: must be in [1, 1024], got '0'");
    EXPECT_EQ(usageError({"s", "--duration", "1", "--threads", "2.5"}),
              "--threads: expected an integer, got '2.5'");
    EXPECT_EQ(usageError({"s", "--duration", "1", "--threads", "99999999999999999999"}),
              "--threads: must be in [1, 1024], got '99999999999999999999'");
}

TEST(RunOptions, RefusesUnknownNamesAndOptions) {
    EXPECT_EQ(usageError({"s", "--duration", "1", "--mode", "fast"}),
              "--mode: unknown mode 'fast' (expected one of: discrete, substep, exact)");
    EXPECT_EQ(usageError({"s", "--duration", "1", "--broadphase", "octree"}),
              "--broadphase: unknown broadphase 'octree' (expected one of: auto, all-pairs, grid, "
              "quadtree)");
    EXPECT_EQ(usageError({"s", "--duration", "1", "--bogus"}), "unknown option '--bogus'");
    EXPECT_EQ(usageError({"s"}), "--duration is required");
    EXPECT_EQ(usageError({"--duration", "1"}), "SCENE is required");
}

TEST(RunOptions, AnUnknownOptionIsNamedWithTheNearestKnownOne) {
    EXPECT_EQ(usageError({"s", "--duration", "1", "--seve", "out.json"}),
              "unknown option '--seve' (did you mean '--save'?)");
    EXPECT_EQ(usageError({"s", "--duraton", "1"}),
              "unknown option '--duraton' (did you mean '--duration'?)");
    EXPECT_EQ(usageError({"s", "-d", "1", "--timeseries-evry=5"}),
              "unknown option '--timeseries-evry' (did you mean '--timeseries-every'?)");
    // Nothing near: the option alone (the runner points to --help after it).
    EXPECT_EQ(usageError({"s", "-d", "1", "--gr-bins", "3"}), "unknown option '--gr-bins'");
    // A new option is near its misspelling too.
    EXPECT_EQ(usageError({"s", "-d", "1", "--seeed", "3"}),
              "unknown option '--seeed' (did you mean '--seed'?)");
}

TEST(RunOptions, AStrayArgumentIsNamedWithTheSceneAlreadyGiven) {
    EXPECT_EQ(usageError({"a.json", "b.json", "--duration", "1"}),
              "unexpected argument 'b.json' (SCENE is 'a.json'; options start with '-')");
    EXPECT_EQ(usageError({"a.json", "--duration", "1", "2"}),
              "unexpected argument '2' (SCENE is 'a.json'; options start with '-')");
}

TEST(RunOptions, HelpIsNotAnError) {
    try {
        (void)parse({"--help"});
        FAIL();
    } catch (const HelpRequested& help) {
        const std::string text = help.what();
        for (const char* option : {"--duration", "--mode", "--dt", "--substeps", "--broadphase",
                                   "--threads", "--report", "--save", "--progress"}) {
            EXPECT_NE(text.find(option), std::string::npos) << option;
        }
    }
}

TEST(RunOptions, VersionNeedsNoSceneAndNamesTheProgramAndVersion) {
    try {
        (void)parse({"--version"});
        FAIL();
    } catch (const HelpRequested& version) {
        const std::string text = version.what();
        EXPECT_EQ(text.rfind("particle-sim " + std::string(psb::projectVersion()), 0), 0u) << text;
        EXPECT_EQ(text.back(), '\n');
    }
}

TEST(RunOptions, StepsCoverTheDurationWithoutAnExtraStepFromRounding) {
    EXPECT_EQ(stepsFor(1.0, 0.01), 100u);  // 1 / 0.01 = 100.00000000000001 in doubles
    EXPECT_EQ(stepsFor(10.0, 1.0 / 60.0), 600u);
    EXPECT_EQ(stepsFor(1.0, 0.3), 4u);  // 3.33 steps: round up so the duration is covered
    EXPECT_EQ(stepsFor(0.0, 0.01), 0u);
    EXPECT_THROW((void)stepsFor(1e300, 1e-300), UsageError);
}

}  // namespace
}  // namespace psb::cli
