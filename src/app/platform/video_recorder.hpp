#pragma once
// A video recording in progress: the drawing thread captures frames, a thread of the recorder's
// own encodes them (VideoEncoder), so that encoding does not slow the frame rate.
//
// Frames wait in a short queue (kQueue). In real time (Pacing::RealTime) a frame arriving while
// the queue is full is left out and counted, the video holding the frame before: the window
// keeps its frame rate and the summary says how many were dropped. A frame is asked for only
// when a new slot of the video's frame rate has begun (due()), so a window drawing faster than
// that reads back no pixels it would not use. Pacing::EveryFrame (the benchmark) takes every
// frame, one slot each, and waits for room in the queue instead of dropping.
//
// The file is written as NAME.part and renamed to NAME when stop() has completed it: a NAME on
// disk is always a whole video. A failed encoding removes the part file.

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <filesystem>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "platform/video_encoder.hpp"

namespace psb::app {

/// What a finished recording wrote.
struct VideoSummary {
    std::filesystem::path file;  ///< absolute
    std::size_t frames = 0;      ///< in the file
    std::size_t dropped = 0;     ///< left out: the encoder was behind
    double seconds = 0.0;        ///< the video's length
    int width = 0;               ///< pixels, as encoded
    int height = 0;
};

class VideoRecorder {
  public:
    enum class Pacing { RealTime, EveryFrame };
    static constexpr std::size_t kQueue = 6;  ///< frames waiting for the encoder, at most

    /// Starts a recording into `file` (written as `file`.part until stop()) of frames `width` ×
    /// `height` RGBA pixels, `fps` a second. Throws VideoError when it cannot start.
    VideoRecorder(const std::filesystem::path& file, VideoFormat format, int width, int height,
                  int fps, Pacing pacing);
    VideoRecorder(const VideoRecorder&) = delete;
    VideoRecorder& operator=(const VideoRecorder&) = delete;
    /// Stops as stop() does, swallowing its errors.
    ~VideoRecorder();

    /// The frame slot for a frame drawn `seconds` after the recording started, or nullopt when
    /// no new slot is due yet (or the encoder has failed): capture only when one is.
    [[nodiscard]] std::optional<std::int64_t> due(double seconds);
    /// A buffer of width × height × 4 bytes for the next frame (one the encoder is done with
    /// when there is one).
    [[nodiscard]] std::vector<std::uint8_t> buffer();
    /// Hands over the frame for `slot` (from due()).
    void push(std::vector<std::uint8_t> rgba, std::int64_t slot);

    /// The encoder's error, once encoding has failed (the recording takes no more frames).
    [[nodiscard]] std::optional<std::string> failure() const;
    [[nodiscard]] int width() const { return width_; }
    [[nodiscard]] int height() const { return height_; }
    [[nodiscard]] VideoFormat format() const { return format_; }
    [[nodiscard]] const std::filesystem::path& file() const { return file_; }
    [[nodiscard]] std::size_t frames() const;
    [[nodiscard]] std::size_t dropped() const;

    /// Encodes the frames still queued, completes the file and gives it its name. Throws
    /// VideoError (the part file removed) when encoding failed at any point.
    VideoSummary stop();

  private:
    struct Frame {
        std::vector<std::uint8_t> rgba;
        std::int64_t slot = 0;
    };
    void encodeLoop();

    std::filesystem::path file_;
    std::filesystem::path part_;
    VideoFormat format_;
    int width_;
    int height_;
    int fps_;
    Pacing pacing_;
    VideoEncoder encoder_;

    mutable std::mutex mutex_;
    std::condition_variable wake_;  ///< the encoder: a frame, or the end
    std::condition_variable room_;  ///< EveryFrame: room in the queue
    std::deque<Frame> queue_;
    std::vector<std::vector<std::uint8_t>> spare_;
    std::optional<std::string> failure_;
    bool ending_ = false;
    bool stopped_ = false;
    std::size_t pushed_ = 0;
    std::size_t encoded_ = 0;
    std::size_t dropped_ = 0;
    std::int64_t lastSlot_ = -1;
    std::thread thread_;  ///< last: started once everything it uses is
};

}  // namespace psb::app
