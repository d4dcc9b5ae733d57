#pragma once
// The runner's JSON report.

#include <string>

#include "runner.hpp"

namespace psb::cli {

/// The report as pretty-printed JSON (doubles in shortest round-trip form), ending in a newline.
[[nodiscard]] std::string reportJson(const RunReport& report);

}  // namespace psb::cli
