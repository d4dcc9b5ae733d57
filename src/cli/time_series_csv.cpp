#include "time_series_csv.hpp"

#include <particle_sandbox/data_tables.hpp>

namespace psb::cli {

std::string timeSeriesCsv(const TimeSeries& series, bool gravity, bool rotation) {
    return timeSeriesTable(samplesOf(series), gravity, csv::Separator::Comma, rotation);
}

std::filesystem::path trackPath(const std::filesystem::path& timeseries) {
    std::filesystem::path track = timeseries;
    track.replace_filename(timeseries.stem().string() + "-track" + timeseries.extension().string());
    return track;
}

}  // namespace psb::cli
