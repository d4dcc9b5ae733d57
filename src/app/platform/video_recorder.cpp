#include "platform/video_recorder.hpp"

#include <algorithm>
#include <cmath>
#include <system_error>
#include <utility>

namespace psb::app {

namespace {

std::filesystem::path partOf(const std::filesystem::path& file) {
    std::filesystem::path part = file;
    part += ".part";
    return part;
}

}  // namespace

VideoRecorder::VideoRecorder(const std::filesystem::path& file, VideoFormat format, int width,
                             int height, int fps, Pacing pacing)
    : file_(std::filesystem::absolute(file).lexically_normal()),
      part_(partOf(file_)),
      format_(format),
      width_(width),
      height_(height),
      fps_(fps),
      pacing_(pacing),
      encoder_(part_, format, width, height, fps),
      thread_([this] { encodeLoop(); }) {}

VideoRecorder::~VideoRecorder() {
    try {
        if (!stopped_) stop();
    } catch (...) {  // NOLINT(bugprone-empty-catch): a destructor reports nothing
    }
}

std::optional<std::int64_t> VideoRecorder::due(double seconds) {
    const std::lock_guard lock(mutex_);
    if (failure_ || ending_) return std::nullopt;
    if (pacing_ == Pacing::EveryFrame) return lastSlot_ + 1;
    // Real time: the slot nearest the moment, once at least half a slot has passed since the
    // last frame. A window drawing at the video's rate fills every slot in spite of its jitter;
    // a faster one gives no slot two frames; a slower one leaves slots out (the frame before is
    // held through them).
    const double at = seconds * fps_;
    if (at < static_cast<double>(lastSlot_) + 0.5) return std::nullopt;
    return std::max(lastSlot_ + 1, static_cast<std::int64_t>(std::llround(at)));
}

std::vector<std::uint8_t> VideoRecorder::buffer() {
    const std::lock_guard lock(mutex_);
    const auto bytes = static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_) * 4;
    if (!spare_.empty()) {
        std::vector<std::uint8_t> b = std::move(spare_.back());
        spare_.pop_back();
        b.resize(bytes);
        return b;
    }
    return std::vector<std::uint8_t>(bytes);
}

void VideoRecorder::push(std::vector<std::uint8_t> rgba, std::int64_t slot) {
    std::unique_lock lock(mutex_);
    if (failure_ || ending_ || slot <= lastSlot_) return;
    lastSlot_ = slot;
    if (pacing_ == Pacing::EveryFrame) {
        room_.wait(lock, [this] { return queue_.size() < kQueue || failure_.has_value(); });
        if (failure_) return;
    } else if (queue_.size() >= kQueue) {
        ++dropped_;
        spare_.push_back(std::move(rgba));
        return;
    }
    queue_.push_back({std::move(rgba), slot});
    ++pushed_;
    wake_.notify_one();
}

std::optional<std::string> VideoRecorder::failure() const {
    const std::lock_guard lock(mutex_);
    return failure_;
}

std::size_t VideoRecorder::frames() const {
    const std::lock_guard lock(mutex_);
    return pushed_;
}

std::size_t VideoRecorder::dropped() const {
    const std::lock_guard lock(mutex_);
    return dropped_;
}

void VideoRecorder::encodeLoop() {
    for (;;) {
        Frame frame;
        {
            std::unique_lock lock(mutex_);
            wake_.wait(lock, [this] { return !queue_.empty() || ending_; });
            if (queue_.empty()) return;  // ending, and nothing left
            frame = std::move(queue_.front());
            queue_.pop_front();
            room_.notify_one();
            if (failure_) continue;  // drain the queue without encoding
        }
        try {
            encoder_.add(frame.rgba.data(), width_ * 4, frame.slot);
        } catch (const std::exception& e) {
            const std::lock_guard lock(mutex_);
            failure_ = e.what();
            room_.notify_all();
            continue;
        }
        const std::lock_guard lock(mutex_);
        ++encoded_;
        if (spare_.size() < kQueue) spare_.push_back(std::move(frame.rgba));
    }
}

VideoSummary VideoRecorder::stop() {
    {
        const std::lock_guard lock(mutex_);
        if (stopped_) throw VideoError("the recording of " + file_.string() + " has stopped");
        stopped_ = true;
        ending_ = true;
    }
    wake_.notify_all();
    room_.notify_all();
    if (thread_.joinable()) thread_.join();
    std::error_code ec;
    try {
        if (failure_) throw VideoError(*failure_);
        encoder_.finish();
    } catch (const VideoError&) {
        std::filesystem::remove(part_, ec);
        throw;
    }
    std::filesystem::rename(part_, file_, ec);
    if (ec) {
        throw VideoError("cannot name the video " + file_.string() + ": " + ec.message() +
                         " (it is kept as " + part_.string() + ")");
    }
    VideoSummary s;
    s.file = file_;
    s.frames = encoded_;
    s.dropped = dropped_;
    s.seconds = static_cast<double>(lastSlot_ + 1) / fps_;
    s.width = encoder_.width();
    s.height = encoder_.height();
    return s;
}

}  // namespace psb::app
