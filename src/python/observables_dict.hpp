#pragma once
// The observables as a flat row (a sweep's DataFrame row, Observables.as_dict).

#include <utility>
#include <vector>

#include <particle_sandbox/observables.hpp>

#include "bindings.hpp"

namespace psb::python {

/// The measured quantities by their report names (particle-sim's `observables` object).
const std::vector<std::pair<const char*, Measured ObservablesResult::*>>& measuredFields();

/// {name: value, name_error: error} for each measured quantity, then the packing fraction,
/// the particle count, the blocks and theory's values (NaN where none).
py::dict observablesRow(const ObservablesResult& r);

}  // namespace psb::python
