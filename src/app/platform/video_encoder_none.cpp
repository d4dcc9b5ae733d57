// The video encoder of a build without FFmpeg (PSB_VIDEO off, the web page): every format says
// why it cannot be written, and opening one throws that reason.

#include "platform/video_encoder.hpp"

namespace psb::app {

std::optional<std::string> videoFormatProblem(VideoFormat /*format*/) {
    return "this build records no video (it was built without FFmpeg)";
}

struct VideoEncoder::Impl {};

VideoEncoder::VideoEncoder(const std::filesystem::path& /*file*/, VideoFormat format, int /*width*/,
                           int /*height*/, int /*fps*/) {
    throw VideoError(*videoFormatProblem(format));
}

VideoEncoder::~VideoEncoder() = default;

void VideoEncoder::add(const std::uint8_t* /*rgba*/, int /*stride*/, std::int64_t /*index*/) {}

void VideoEncoder::finish() {}

int VideoEncoder::width() const {
    return 0;
}
int VideoEncoder::height() const {
    return 0;
}

}  // namespace psb::app
