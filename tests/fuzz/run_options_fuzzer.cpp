// libFuzzer target for particle-sim's command line (psb::cli::parseRunOptions).
//
// The input is split at NUL bytes into arguments. Any argument list is either parsed into
// RunOptions whose values are all in range, or refused with UsageError (or HelpRequested);
// nothing else may escape and nothing may crash.

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "run_options.hpp"

namespace {

[[noreturn]] void violated(const char* what) {
    std::fprintf(stderr, "run_options_fuzzer: accepted %s\n", what);
    std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::vector<std::string> args{"particle-sim"};
    std::string current;
    for (std::size_t i = 0; i < size; ++i) {
        if (data[i] == 0) {
            args.push_back(current);
            current.clear();
        } else {
            current += static_cast<char>(data[i]);
        }
    }
    args.push_back(current);
    if (args.size() > 64) return 0;

    psb::cli::RunOptions o;
    try {
        o = psb::cli::parseRunOptions(args);
    } catch (const psb::cli::UsageError&) {
        return 0;
    } catch (const psb::cli::HelpRequested&) {
        return 0;
    }
    if (!std::isfinite(o.duration) || o.duration < 0.0) violated("a bad duration");
    if (o.dt && !(std::isfinite(*o.dt) && *o.dt > 0.0)) violated("a bad dt");
    if (o.substeps && *o.substeps < 1) violated("a bad substep count");
    if (o.threads < 1) violated("a bad thread count");
    if (o.scene.empty()) violated("no scene");
    if (o.dt) {
        try {
            (void)psb::cli::stepsFor(o.duration, *o.dt);
        } catch (const psb::cli::UsageError&) {
        }
    }
    return 0;
}
