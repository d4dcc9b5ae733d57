#include "observables_csv.hpp"

#include <vector>

#include <particle_sandbox/csv.hpp>

namespace psb::cli {
namespace {

std::string table(const char* header, const std::vector<double>& x, const std::vector<double>& y) {
    std::string out = std::string(header) + "\n";
    for (std::size_t k = 0; k < x.size() && k < y.size(); ++k)
        out += csv::number(x[k]) + "," + csv::number(y[k]) + "\n";
    return out;
}

}  // namespace

std::string pairDistributionCsv(const ObservablesResult& r) {
    return table("r_m,g", r.pairR, r.pairG);
}

std::string msdCsv(const ObservablesResult& r) {
    return table("t_s,msd_m2", r.lagTime, r.msd);
}

std::string vacfCsv(const ObservablesResult& r) {
    return table("t_s,vacf_m2_per_s2", r.lagTime, r.vacf);
}

}  // namespace psb::cli
