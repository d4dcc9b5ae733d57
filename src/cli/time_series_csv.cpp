#include "time_series_csv.hpp"

#include <cstdio>

namespace psb::cli {

std::string timeSeriesCsv(const TimeSeries& series, bool gravity) {
    std::string csv = kTimeSeriesCsvHeader;
    if (gravity) csv += kTimeSeriesCsvGravityColumns;
    csv += '\n';
    csv.reserve(csv.size() + series.size() * 160);
    char row[320];
    for (std::size_t k = 0; k < series.size(); ++k) {
        const ObservablesSample& s = series[k];
        const int n = std::snprintf(
            row, sizeof row, "%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%llu,%.17g\n", s.time,
            s.kineticEnergy, s.momentum.x(), s.momentum.y(), s.centreOfMass.x(), s.centreOfMass.y(),
            static_cast<unsigned long long>(s.collisions), s.collisionRate);
        csv.append(row, static_cast<std::size_t>(n));
        if (gravity) {
            csv.pop_back();  // the newline
            const int m = std::snprintf(row, sizeof row, ",%.17g,%.17g\n", s.potentialEnergy,
                                        s.kineticEnergy + s.potentialEnergy);
            csv.append(row, static_cast<std::size_t>(m));
        }
    }
    return csv;
}

}  // namespace psb::cli
