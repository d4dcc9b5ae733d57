#pragma once
// particle-sim as a function, so that tests can run it without a process.

#include <ostream>
#include <string>
#include <vector>

namespace psb::cli {

/// Exit statuses of particle-sim.
enum ExitCode : int {
    kExitOk = 0,
    kExitFailure = 1,  ///< the scene, or a file to write, was refused
    kExitUsage = 2,    ///< bad command line
};

/// Runs particle-sim with `args` (args[0] is the program name). The report goes to `out` or a
/// file, messages and the progress bar to `err`; `errIsTerminal` enables the bar.
[[nodiscard]] int runCli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err,
                         bool errIsTerminal);

}  // namespace psb::cli
