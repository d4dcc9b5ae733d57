#include "output_check.hpp"

#include <system_error>

#include <particle_sandbox/atomic_file.hpp>

#include "time_series_csv.hpp"

namespace psb::cli {
namespace {

/// The file `path` names, for comparing two outputs: "runs/../a.csv" and "a.csv" are one file.
/// Called once each folder is known to exist, so the links in it resolve.
std::filesystem::path identity(const std::filesystem::path& path) {
    std::error_code ec;
    std::filesystem::path p = std::filesystem::weakly_canonical(path, ec);
    return ec ? path.lexically_normal() : p;
}

}  // namespace

std::vector<Output> outputsOf(const RunOptions& o) {
    std::vector<Output> out;
    if (o.report && *o.report != "-") out.push_back({"--report", *o.report});
    if (o.save) out.push_back({"--save", *o.save});
    if (o.timeseries) {
        out.push_back({"--timeseries", *o.timeseries});
        if (!o.track.empty()) out.push_back({"--track", trackPath(*o.timeseries)});
    }
    if (o.gr) out.push_back({"--gr", *o.gr});
    if (o.msd) out.push_back({"--msd", *o.msd});
    if (o.vacf) out.push_back({"--vacf", *o.vacf});
    return out;
}

void checkOutputs(const RunOptions& options) {
    const std::vector<Output> outputs = outputsOf(options);
    for (const Output& o : outputs) {
        if (const auto why = atomicWriteProblem(o.path))
            throw OutputError(o.option + ": cannot write " + o.path.string() + ": " + *why);
    }
    // Two options may share a device (--report /dev/null --save /dev/null), not a file.
    const auto isFile = [](const std::filesystem::path& p) {
        std::error_code ec;
        const auto status = std::filesystem::status(p, ec);
        return !std::filesystem::exists(status) || std::filesystem::is_regular_file(status);
    };
    for (std::size_t i = 0; i < outputs.size(); ++i) {
        if (!isFile(outputs[i].path)) continue;
        for (std::size_t k = 0; k < i; ++k) {
            if (identity(outputs[i].path) == identity(outputs[k].path)) {
                throw UsageError(outputs[k].option + " and " + outputs[i].option +
                                 " name the same file, " + outputs[i].path.string());
            }
        }
    }
}

}  // namespace psb::cli
