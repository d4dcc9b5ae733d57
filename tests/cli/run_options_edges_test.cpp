// particle-sim's command line at its edges: repeated options, options without their value, and
// step counts that a valid --duration and --dt still make impossible.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "run_options.hpp"

namespace psb::cli {
namespace {

std::string usageError(std::vector<std::string> args) {
    args.insert(args.begin(), "particle-sim");
    try {
        (void)parseRunOptions(args);
    } catch (const UsageError& e) {
        return e.what();
    }
    return "(accepted)";
}

TEST(RunOptionsEdges, AnOptionGivenTwiceIsRefusedNamingIt) {
    EXPECT_EQ(usageError({"s", "--duration", "1", "--dt", "1", "--dt", "2"}),
              "--dt: At Most 1 required but received 2");
    EXPECT_EQ(usageError({"s", "--duration", "1", "--duration", "2"}),
              "--duration: At Most 1 required but received 2");
}

TEST(RunOptionsEdges, AnEmptySceneIsRefused) {
    // Found by the run_options fuzzer: `particle-sim "" -d 2` was accepted.
    EXPECT_EQ(usageError({"", "-d", "2"}), "SCENE: the path is empty");
}

TEST(RunOptionsEdges, AnOptionWithoutItsValueIsRefusedNamingIt) {
    EXPECT_EQ(usageError({"s", "--duration", "1", "--dt"}), "--dt: 1 required S missing");
    EXPECT_EQ(usageError({"s", "--duration", "1", "--mode="}), "--mode: 1 required M missing");
}

TEST(RunOptionsEdges, NumbersAreWholeDecimalTextsOnly) {
    EXPECT_EQ(usageError({"s", "--duration", " 1"}), "--duration: expected a number, got ' 1'");
    EXPECT_EQ(usageError({"s", "--duration", "0x10"}), "--duration: expected a number, got '0x10'");
    EXPECT_EQ(usageError({"s", "--duration", ""}), "--duration: expected a number, got ''");
    EXPECT_EQ(usageError({"s", "--duration", "1", "--dt", "-inf"}),
              "--dt: must be a finite number, got '-inf'");
    EXPECT_EQ(usageError({"s", "--duration", "1", "--substeps", "100001"}),
              "--substeps: must be in [1, 100000], got '100001'");
    EXPECT_EQ(usageError({"s", "--duration", "1", "--threads", "-1"}),
              "--threads: must be in [1, 1024], got '-1'");
}

TEST(RunOptionsEdges, TooManyStepsAreCountedInTheMessageInShortestForm) {
    try {
        (void)stepsFor(1e21, 1.0);
        ADD_FAILURE() << "accepted 1e21 steps";
    } catch (const UsageError& e) {
        EXPECT_STREQ(e.what(), "--duration / --dt: 1e+21 steps is more than the limit of 1e15");
    }
}

TEST(RunOptionsEdges, ATimeStepTooSmallForTheDurationIsRefused) {
    // Both numbers are valid alone; together they ask for more steps than could ever finish.
    EXPECT_THROW((void)stepsFor(1.0, 5e-324), UsageError);
    EXPECT_THROW((void)stepsFor(1e300, 1e-300), UsageError);
    EXPECT_EQ(stepsFor(0.0, 5e-324), 0u);
}

}  // namespace
}  // namespace psb::cli
