// Data out: the tables a user takes away (data_tables.hpp), written to a CSV file or put on the
// clipboard, and the recording of the particles' paths and collisions (data_recorder.hpp).

#include <algorithm>

#include <particle_sandbox/atomic_file.hpp>
#include <particle_sandbox/data_tables.hpp>

#include "session/session.hpp"
#include "session/session_text.hpp"

namespace psb::app {
namespace {

/// The table in words, for messages: "values", "time series", ...
const char* tableName(cmd::DataTable table) {
    switch (table) {
        case cmd::DataTable::Values:
            return "values";
        case cmd::DataTable::TimeSeries:
            return "time series";
        case cmd::DataTable::Trajectories:
            return "trajectories";
        case cmd::DataTable::Collisions:
            break;
    }
    return "collisions";
}

/// The file an export without a name writes (in the export folder).
const char* defaultFile(cmd::DataTable table) {
    switch (table) {
        case cmd::DataTable::Values:
            return "values.csv";
        case cmd::DataTable::TimeSeries:
            return "time-series.csv";
        case cmd::DataTable::Trajectories:
            return "trajectories.csv";
        case cmd::DataTable::Collisions:
            break;
    }
    return "collisions.csv";
}

/// Rows of a table's text: its lines less the header.
std::size_t rowsOf(const std::string& text) {
    const auto lines = static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
    return lines > 0 ? lines - 1 : 0;
}

}  // namespace

std::string Session::tableText(cmd::DataTable table, csv::Separator separator) const {
    switch (table) {
        // In the axes the window shows (the y up option), so what is pasted reads as shown.
        case cmd::DataTable::Values:
            return valuesTable(doc_.world, separator, axes());
        case cmd::DataTable::TimeSeries:
            return timeSeriesTable(data_.run(), !doc_.world.def().gravity.isZero(), separator,
                                   doc_.world.rotationInUse(), axes(), rateWindow());
        case cmd::DataTable::Trajectories:
            return trajectoryTable(data_.trajectory(), separator, doc_.world.rotationInUse(),
                                   axes());
        case cmd::DataTable::Collisions:
            break;
    }
    return collisionTable(data_.collisions(), separator, axes());
}

std::filesystem::path Session::exportDir() const {
    std::error_code ec;
    const std::filesystem::path dir = std::filesystem::absolute(options_.exportDir, ec);
    return (ec ? options_.exportDir : dir).lexically_normal();
}

void Session::handle(const cmd::ExportTable& c) {
    const std::string text = tableText(c.table, csv::Separator::Comma);
    const std::size_t rows = rowsOf(text);
    if (rows == 0) {
        exportError_ = fmt("Export: no %s yet", tableName(c.table));
        if (c.table == cmd::DataTable::Trajectories || c.table == cmd::DataTable::Collisions) {
            exportError_ += ": record some first (Record, or X)";
        }
        notices_.say(exportError_, Notice::Level::Warning);
        return;
    }
    std::string why;
    const std::filesystem::path typed = c.path.empty() ? defaultFile(c.table) : c.path;
    const std::optional<std::filesystem::path> named = saveFileName(typed, why, ".csv");
    if (!named) {
        exportError_ = "Export: " + why;
        notices_.say(exportError_, Notice::Level::Warning);
        return;
    }
    const std::filesystem::path path =
        freeSavePath(named->is_absolute() ? *named : options_.exportDir / *named)
            .lexically_normal();
    try {
        writeFileAtomically(path, text);
    } catch (const std::exception& e) {  // SaveError: nothing was written, no file replaced
        exportError_ = std::string("Export failed: ") + e.what();
        notices_.say(exportError_, Notice::Level::Error);
        return;
    }
    exportError_.clear();
    lastExport_ = path;
    notices_.say(fmt("Exported %zu row%s of %s %s %s", rows, rows == 1 ? "" : "s",
                     tableName(c.table), options_.inPage ? "as" : "to",
                     (options_.inPage ? path.filename() : path).string().c_str()));
}

void Session::handle(const cmd::CopyTable& c) {
    std::string text = tableText(c.table, csv::Separator::Tab);
    const std::size_t rows = rowsOf(text);
    if (rows == 0) {
        notices_.say(fmt("Copy: no %s yet", tableName(c.table)), Notice::Level::Warning);
        return;
    }
    clipboard_ = std::move(text);
    notices_.say(
        fmt("Copied %zu row%s of %s to the clipboard (tab-separated: paste into a spreadsheet)",
            rows, rows == 1 ? "" : "s", tableName(c.table)));
}

void Session::handle(const cmd::ToggleVideo& c) {
    if (c.settings) videoSettings_ = *c.settings;
    videoToggle_ = videoSettings_;
}

void Session::handle(const cmd::SetVideoSettings& c) {
    videoSettings_ = c.settings;
}

std::optional<VideoSettings> Session::takeVideoToggle() {
    std::optional<VideoSettings> toggle;
    toggle.swap(videoToggle_);
    return toggle;
}

void Session::handle(const cmd::SetRecording& c) {
    if (!c.on) {
        if (!data_.recording()) return;
        data_.stop();
        listenForCollisions();
        const std::size_t hits = data_.collisions().size();
        notices_.say(
            fmt("Recording stopped: %zu samples, %zu collision%s (Data section: Export or Copy)",
                data_.trajectory().samples().size(), hits, hits == 1 ? "" : "s"));
        return;
    }
    if (data_.recording()) return;
    std::vector<ParticleId> ids;
    if (const auto id = tools_.selection.id(); id && doc_.world.contains(*id)) {
        ids.push_back(*id);
    } else if (doc_.world.size() > DataRecorder::kMaxAllParticles) {
        notices_.say(fmt("Not recording: select a particle first (recording all %zu particles is "
                         "limited to %zu)",
                         doc_.world.size(), DataRecorder::kMaxAllParticles),
                     Notice::Level::Warning);
        return;
    } else {
        ids = doc_.world.ids();
        std::sort(ids.begin(), ids.end(),
                  [](ParticleId a, ParticleId b) { return a.slot < b.slot; });
    }
    if (ids.empty()) {
        notices_.say("Not recording: the box is empty", Notice::Level::Warning);
        return;
    }
    data_.start(doc_.world, ids, c.every > 0 ? c.every : data_.every());
    listenForCollisions();
    const std::string who =
        ids.size() == 1
            ? fmt("particle %llu", static_cast<unsigned long long>(particleNumber(ids[0])))
            : fmt("all %zu particles", ids.size());
    notices_.say(fmt("Recording %s every %d step%s (X stops)", who.c_str(), data_.every(),
                     data_.every() == 1 ? "" : "s"));
}

}  // namespace psb::app
