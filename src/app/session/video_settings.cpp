#include "session/video_settings.hpp"

#include <algorithm>
#include <cctype>

namespace psb::app {

const char* toString(VideoFormat format) {
    switch (format) {
        case VideoFormat::Mp4:
            return "MP4";
        case VideoFormat::WebM:
            return "WebM";
        case VideoFormat::Gif:
            return "GIF";
    }
    return "MP4";
}

const char* extension(VideoFormat format) {
    switch (format) {
        case VideoFormat::Mp4:
            return ".mp4";
        case VideoFormat::WebM:
            return ".webm";
        case VideoFormat::Gif:
            return ".gif";
    }
    return ".mp4";
}

std::optional<VideoFormat> parseVideoFormat(std::string_view name) {
    std::string lower(name);
    std::transform(lower.begin(), lower.end(), lower.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (lower == "mp4") return VideoFormat::Mp4;
    if (lower == "webm") return VideoFormat::WebM;
    if (lower == "gif") return VideoFormat::Gif;
    return std::nullopt;
}

}  // namespace psb::app
