#pragma once
// A video file written frame by frame through FFmpeg's libraries: libavfilter turns the window's
// RGBA pixels into what the codec takes, libavcodec encodes them, libavformat writes the file.
//
//   MP4   H.264 (libx264, "superfast", constant quality 20), yuv420p, the index at the front
//         (faststart) so that slides and web pages play it at once
//   WebM  VP8 (libvpx, real-time speed, constrained quality 4 up to 16 Mbit/s), yuv420p: VP9's
//         real-time mode encodes a crowded box at a third of VP8's speed
//   GIF   at most 640 pixels wide, each frame's own 256-colour palette (palettegen in its
//         single-frame mode, then paletteuse), so a long clip needs no memory for a second pass
//
// The frames' timestamps count frames at the given rate; a frame left out (the caller was late)
// shows as the previous one held longer. yuv420p needs even sizes: an odd width or height loses
// its last column or row. Encoding runs on the caller's thread: VideoRecorder runs it on one of
// its own.

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include "session/video_settings.hpp"

namespace psb::app {

/// A video could not be written; the message says what failed and why.
class VideoError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

/// Why `format` cannot be written here (this build has no FFmpeg, or FFmpeg lacks the encoder);
/// nullopt when it can.
[[nodiscard]] std::optional<std::string> videoFormatProblem(VideoFormat format);

class VideoEncoder {
  public:
    /// Creates `file` (replacing it) for frames of `width` × `height` RGBA pixels, `fps` a
    /// second. Throws VideoError when the file, the encoder or the conversion cannot be set up.
    VideoEncoder(const std::filesystem::path& file, VideoFormat format, int width, int height,
                 int fps);
    VideoEncoder(const VideoEncoder&) = delete;
    VideoEncoder& operator=(const VideoEncoder&) = delete;
    /// Closes the file; one not finish()ed is left incomplete.
    ~VideoEncoder();

    /// Encodes one frame of RGBA pixels (rows `stride` bytes apart), shown from frame `index`
    /// on (a count at `fps`, greater than the last frame's). Throws VideoError.
    void add(const std::uint8_t* rgba, int stride, std::int64_t index);
    /// Encodes what the codec still holds and completes the file. Throws VideoError.
    void finish();

    /// The size of the frames in the file, pixels (after evening or scaling down).
    [[nodiscard]] int width() const;
    [[nodiscard]] int height() const;

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace psb::app
