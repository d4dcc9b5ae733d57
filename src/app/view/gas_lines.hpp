#pragma once
// The gas instruments' reading (session/gas_gauges.hpp) as the lines a person reads: a name, a
// value with its unit, and what it means. The panel's Readouts show them; the text F12 writes
// beside a screenshot lists them.

#include <string>
#include <vector>

#include "session/gas_gauges.hpp"

namespace psb::app {

struct GasLine {
    std::string name;   ///< "Pressure, measured"
    std::string value;  ///< "12.2 ± 0.21 N/m"
    std::string help;   ///< what it is, for a tooltip
};

[[nodiscard]] std::vector<GasLine> gasLines(const GasReading& reading);

}  // namespace psb::app
