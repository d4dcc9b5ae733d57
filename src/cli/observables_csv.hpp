#pragma once
// particle-sim --gr, --msd, --vacf: the observables' tables (observables.hpp) as CSV.

#include <string>

#include <particle_sandbox/observables.hpp>

namespace psb::cli {

/// "r_m,g" and one row per g(r) bin (its centre); only the header without g(r) snapshots.
[[nodiscard]] std::string pairDistributionCsv(const ObservablesResult& r);
/// "t_s,msd_m2" and one row per lag.
[[nodiscard]] std::string msdCsv(const ObservablesResult& r);
/// "t_s,vacf_m2_per_s2" and one row per lag.
[[nodiscard]] std::string vacfCsv(const ObservablesResult& r);

}  // namespace psb::cli
