#pragma once
// What a video recording is asked to be: its file format and whether it shows the control
// panel. The session keeps the last choice (Ctrl+R records with it); the app's recorder
// (platform/video_recorder.hpp) does the writing.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace psb::app {

enum class VideoFormat : std::uint8_t {
    Mp4,   ///< H.264 in MP4: plays everywhere, slides included
    WebM,  ///< VP8 in WebM: for web pages
    Gif,   ///< an animated GIF, 25 frames a second, at most 640 pixels wide: for slides
};

struct VideoSettings {
    VideoFormat format = VideoFormat::Mp4;
    bool withPanel = false;  ///< the whole window; otherwise the box's side of it only

    bool operator==(const VideoSettings&) const = default;
};

/// "MP4", "WebM", "GIF": as the panel and the messages name it.
[[nodiscard]] const char* toString(VideoFormat format);
/// The file extension, with its dot: ".mp4", ".webm", ".gif".
[[nodiscard]] const char* extension(VideoFormat format);
/// The format named `name` ("mp4", "webm" or "gif", any case); nullopt for any other name.
[[nodiscard]] std::optional<VideoFormat> parseVideoFormat(std::string_view name);

}  // namespace psb::app
