// Data out: the tables a user takes away (data_tables.hpp), written to a CSV file or put on the
// clipboard, the screenshot and the video the app is asked for.

#include "session/data_out.hpp"

#include <algorithm>
#include <utility>

#include <particle_sandbox/atomic_file.hpp>
#include <particle_sandbox/data_tables.hpp>

#include "session/document.hpp"
#include "session/instruments.hpp"
#include "session/monitor.hpp"
#include "session/notices.hpp"
#include "session/scene_io.hpp"
#include "session/scene_view.hpp"
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

std::string tableText(cmd::DataTable table, csv::Separator separator, const World& world,
                      const DataRecorder& data, const Axes& axes, double rateWindow) {
    switch (table) {
        case cmd::DataTable::Values:
            return valuesTable(world, separator, axes);
        case cmd::DataTable::TimeSeries:
            return timeSeriesTable(data.run(), !world.def().gravity.isZero(), separator,
                                   world.rotationInUse(), axes, rateWindow);
        case cmd::DataTable::Trajectories:
        case cmd::DataTable::Collisions:
            break;
    }
    // In the box they were recorded in: a scene opened since keeps them (y up counts from
    // their floor, not the new box's).
    const Axes recorded{axes.yUp, data.recordedHeight()};
    if (table == cmd::DataTable::Trajectories) {
        return trajectoryTable(data.trajectory(), separator, data.recordedRotation(), recorded);
    }
    return collisionTable(data.collisions(), separator, recorded);
}

namespace {

/// `table` of what `x` holds, as text with `separator`.
std::string textOf(cmd::DataTable table, csv::Separator separator, const DataOut::Context& x) {
    const World& world = x.doc.world;
    return tableText(table, separator, world, x.instruments.data, x.view.axes(world.def()),
                     Monitor::rateWindow(x.doc.meta.dt));
}

}  // namespace

std::filesystem::path DataOut::exportDir() const {
    std::error_code ec;
    const std::filesystem::path dir = std::filesystem::absolute(exportDir_, ec);
    return (ec ? exportDir_ : dir).lexically_normal();
}

void DataOut::handle(const cmd::ExportTable& c, Context& x) {
    const std::string text = textOf(c.table, csv::Separator::Comma, x);
    const std::size_t rows = rowsOf(text);
    if (rows == 0) {
        exportError_ = fmt("Export: no %s yet", tableName(c.table));
        if (c.table == cmd::DataTable::Trajectories || c.table == cmd::DataTable::Collisions) {
            exportError_ += ": record some first (Record, or X)";
        }
        x.notices.say(exportError_, Notice::Level::Warning);
        return;
    }
    std::string why;
    const std::filesystem::path typed = c.path.empty() ? defaultFile(c.table) : c.path;
    const std::optional<std::filesystem::path> named = saveFileName(typed, why, ".csv");
    if (!named) {
        exportError_ = "Export: " + why;
        x.notices.say(exportError_, Notice::Level::Warning);
        return;
    }
    const std::filesystem::path path =
        freeSavePath(named->is_absolute() ? *named : exportDir_ / *named).lexically_normal();
    try {
        writeFileAtomically(path, text);
    } catch (const std::exception& e) {  // SaveError: nothing was written, no file replaced
        exportError_ = std::string("Export failed: ") + e.what();
        x.notices.say(exportError_, Notice::Level::Error);
        return;
    }
    exportError_.clear();
    lastExport_ = path;
    x.notices.say(fmt("Exported %zu row%s of %s %s %s", rows, rows == 1 ? "" : "s",
                      tableName(c.table), inPage_ ? "as" : "to",
                      (inPage_ ? path.filename() : path).string().c_str()));
}

void DataOut::handle(const cmd::CopyTable& c, Context& x) {
    std::string text = textOf(c.table, csv::Separator::Tab, x);
    const std::size_t rows = rowsOf(text);
    if (rows == 0) {
        x.notices.say(fmt("Copy: no %s yet", tableName(c.table)), Notice::Level::Warning);
        return;
    }
    clipboard_ = std::move(text);
    // "Copied" only once the app says the text is on the clipboard: a page's browser may refuse
    // (no permission, no user gesture), and says so later.
    copying_ = PendingCopy{rows, c.table};
}

void DataOut::handle(const cmd::ClipboardResult& c, Context& x) {
    const std::optional<PendingCopy> copy = std::exchange(copying_, std::nullopt);
    if (!copy) return;
    const char* plural = copy->rows == 1 ? "" : "s";
    if (c.copied) {
        x.notices.say(
            fmt("Copied %zu row%s of %s to the clipboard (tab-separated: paste into a spreadsheet)",
                copy->rows, plural, tableName(copy->table)));
        return;
    }
    const std::string why = c.why.empty() ? std::string() : " (" + c.why + ")";
    x.notices.say(fmt("Could not copy the %s to the clipboard%s: Export gives the table as a CSV "
                      "file%s instead",
                      tableName(copy->table), why.c_str(), inPage_ ? " (a download)" : ""),
                  Notice::Level::Warning);
}

void DataOut::handle(const cmd::ToggleVideo& c, Context&) {
    if (c.settings) videoSettings_ = *c.settings;
    videoToggle_ = videoSettings_;
}

void DataOut::handle(const cmd::SetVideoSettings& c, Context&) {
    videoSettings_ = c.settings;
}

std::optional<VideoSettings> DataOut::takeVideoToggle() {
    std::optional<VideoSettings> toggle;
    toggle.swap(videoToggle_);
    return toggle;
}

void DataOut::handle(const cmd::Screenshot&, Context&) {
    screenshotRequested_ = true;
}

bool DataOut::takeScreenshotRequest() {
    const bool r = screenshotRequested_;
    screenshotRequested_ = false;
    return r;
}

std::optional<std::string> DataOut::takeClipboardText() {
    std::optional<std::string> text;
    text.swap(clipboard_);
    return text;
}

}  // namespace psb::app
