#pragma once
// What leaves the session for the user to take away: the tables (data_tables.hpp) written to a
// CSV file or put on the clipboard, the window's picture (a screenshot) and its video. The
// session keeps the choice and what the app is to do once (the text to copy, a screenshot to
// write, a video to start or stop); the app takes it and does it.

#include <filesystem>
#include <optional>
#include <string>

#include <particle_sandbox/axes.hpp>
#include <particle_sandbox/csv.hpp>
#include <particle_sandbox/world.hpp>

#include "session/command.hpp"
#include "session/data_recorder.hpp"
#include "session/video_settings.hpp"

namespace psb::app {

struct Document;
struct Instruments;
class Notices;
class SceneView;

/// `table` as text with `separator`, in `axes` (the y up option: what is pasted reads as
/// shown): the values of `world` now, or what `data` recorded; the time series' collision rate
/// counts over `rateWindow` seconds.
[[nodiscard]] std::string tableText(cmd::DataTable table, csv::Separator separator,
                                    const World& world, const DataRecorder& data, const Axes& axes,
                                    double rateWindow);

class DataOut {
  public:
    /// `exportDir`: where ExportTable writes a relative name; `inPage`: files written go to the
    /// browser's downloads, and messages name them so.
    DataOut(std::filesystem::path exportDir, bool inPage)
        : exportDir_(std::move(exportDir)), inPage_(inPage) {}

    /// What the tables are made of: the world (the document) and what was recorded (the
    /// instruments), in the axes shown (the view).
    struct Context {
        const Document& doc;
        const Instruments& instruments;
        const SceneView& view;
        Notices& notices;
    };
    void handle(const cmd::ExportTable& c, Context& x);
    void handle(const cmd::CopyTable& c, Context& x);
    void handle(const cmd::ClipboardResult& c, Context& x);
    void handle(const cmd::ToggleVideo& c, Context& x);
    void handle(const cmd::SetVideoSettings& c, Context& x);
    void handle(const cmd::Screenshot& c, Context& x);

    /// The folder ExportTable writes a relative name into (absolute).
    [[nodiscard]] std::filesystem::path exportDir() const;
    /// The file the last ExportTable wrote (absolute).
    [[nodiscard]] const std::optional<std::filesystem::path>& lastExport() const {
        return lastExport_;
    }
    /// Why the last export failed; empty once one succeeds.
    [[nodiscard]] const std::string& exportError() const { return exportError_; }
    /// The video settings last asked for (Ctrl+R records with them).
    [[nodiscard]] const VideoSettings& videoSettings() const { return videoSettings_; }

    /// True once after a Screenshot command: the app writes the next frame.
    [[nodiscard]] bool takeScreenshotRequest();
    /// The text a CopyTable command put on the clipboard, once: the app hands it to the system.
    [[nodiscard]] std::optional<std::string> takeClipboardText();
    /// The settings of a ToggleVideo command, once: the app starts a recording with them, or
    /// stops the one running.
    [[nodiscard]] std::optional<VideoSettings> takeVideoToggle();

  private:
    std::filesystem::path exportDir_;
    bool inPage_ = false;
    std::optional<std::filesystem::path> lastExport_;
    std::string exportError_;
    std::optional<std::string> clipboard_;
    /// What the last copy handed to the app holds, said once the app reports the result.
    struct PendingCopy {
        std::size_t rows = 0;
        cmd::DataTable table = cmd::DataTable::Values;
    };
    std::optional<PendingCopy> copying_;
    bool screenshotRequested_ = false;
    VideoSettings videoSettings_;
    std::optional<VideoSettings> videoToggle_;
};

}  // namespace psb::app
