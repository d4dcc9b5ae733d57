#pragma once
// The files a run will write, checked before it starts: a run of hours must not end in "cannot
// save" because of a typo in a folder name.

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "run_options.hpp"

namespace psb::cli {

/// A file the run will write, and the option that asked for it.
struct Output {
    std::string option;  ///< "--report", "--save", "--timeseries", "--track", "--gr", ...
    std::filesystem::path path;
};

/// The files `options` asks for, in the order of --help: --report (unless it is '-'), --save,
/// --timeseries, --track's file beside the time series (trackPath), --gr, --msd, --vacf.
[[nodiscard]] std::vector<Output> outputsOf(const RunOptions& options);

/// An output that cannot be written; what() names the option, the path and why.
class OutputError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

/// Checks every output of `options` as writeFileAtomically will write it (atomicWriteProblem:
/// the folder exists and takes a new file, no directory is in the way, a device can be opened),
/// touching nothing that exists. Throws OutputError for the first that cannot be written, and
/// UsageError when two options name the same file (the second would overwrite the first).
void checkOutputs(const RunOptions& options);

}  // namespace psb::cli
