// The app's part of video recording: Ctrl+R (a ToggleVideo command the session hands over)
// starts a VideoRecorder on the box's side of the window or on all of it; each rendered frame
// whose slot is due is read back and queued for the recorder's encoding thread; Ctrl+R again,
// quitting, a failure or a change of the recorded area's size completes the file and says where
// it is.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>

#include "app.hpp"
#include "render/screenshot.hpp"
#include "view/box_area.hpp"
#include "view/frame_view.hpp"

namespace psb::app {

namespace {

/// GIFs count time in hundredths of a second: 25 frames a second is 4 of them each.
constexpr int kGifFps = 25;

std::string sizeText(int w, int h) {
    return std::to_string(w) + "x" + std::to_string(h);
}

}  // namespace

SDL_Rect App::videoArea(const VideoSettings& settings) const {
    const SDL_Point out = sdl_->outputSize();
    if (settings.withPanel) return {0, 0, out.x, out.y};
    const int left = std::clamp(controlsInset(*session_, controls_), 0, std::max(0, out.x - 2));
    return {left, 0, out.x - left, out.y};
}

void App::toggleVideo(const VideoSettings& settings) {
    if (video_) {
        stopVideo();
    } else {
        startVideo(settings, VideoRecorder::Pacing::RealTime);
    }
}

void App::startVideo(const VideoSettings& settings, VideoRecorder::Pacing pacing) {
    const SDL_Rect area = videoArea(settings);
    int fps = kGifFps;
    if (settings.format != VideoFormat::Gif) {
        // The window's frame rate: the display's, which the loop keeps to.
        SDL_DisplayMode mode;
        fps = SDL_GetCurrentDisplayMode(0, &mode) == 0 && mode.refresh_rate > 0
                  ? std::clamp(mode.refresh_rate, 10, 120)
                  : 60;
    }
    const std::time_t t = std::time(nullptr);
    std::tm local{};
    localtime_r(&t, &local);
    const std::filesystem::path file =
        screenshotPath(options_.screenshotDir, local, extension(settings.format));
    try {
        video_ =
            std::make_unique<VideoRecorder>(file, settings.format, area.w, area.h, fps, pacing);
    } catch (const std::exception& e) {  // VideoError, or no thread to encode on
        tell(std::string("Cannot record video: ") + e.what(), Notice::Level::Error);
        return;
    }
    videoSettings_ = settings;
    videoArea_ = area;
    videoStart_ = now();
    tell(std::string("Recording video (") + toString(settings.format) + ", " +
         sizeText(area.w, area.h) + ", " + std::to_string(fps) + " frames/s) to " +
         video_->file().string() + ": " + videoStopHint(session_->touch()));
    updateVideoStatus();
}

void App::stopVideo(const std::string& why) {
    if (!video_) return;
    const std::unique_ptr<VideoRecorder> recorder = std::move(video_);
    try {
        const VideoSummary s = recorder->stop();
        char figures[160];
        std::snprintf(figures, sizeof figures, ": %.1f s, %zu frames, %s", s.seconds, s.frames,
                      sizeText(s.width, s.height).c_str());
        std::string text =
            why + (why.empty() ? "Saved video " : ": saved video ") + s.file.string() + figures;
        // A window drawing slower than the video's rate fills fewer slots: the video holds
        // each frame longer, and the message says how many a second it has.
        const double rate = s.seconds > 0.0 ? static_cast<double>(s.frames) / s.seconds : 0.0;
        if (s.seconds > 0.5 && rate < 0.9 * s.fps) {
            std::snprintf(figures, sizeof figures,
                          " (%.0f frames a second of %d: the window drew no faster)", rate, s.fps);
            text += figures;
        }
        if (s.dropped > 0) {
            text += ", " + std::to_string(s.dropped) +
                    " frames left out (the encoder fell behind; each held the one before)";
        }
        stats_.video.lastFile = s.file.string();
        tell(text);
    } catch (const std::exception& e) {
        tell((why.empty() ? std::string() : why + ": ") + "the video failed: " + e.what() +
                 " (nothing was kept)",
             Notice::Level::Error);
    }
    updateVideoStatus();
}

void App::captureVideo() {
    if (!video_) return;
    if (const auto failed = video_->failure()) {
        stopVideo("Recording stopped");
        return;
    }
    const SDL_Rect area = videoArea(videoSettings_);
    if (area.w != videoArea_.w || area.h != videoArea_.h) {
        stopVideo(
            "Recording stopped: the recorded area changed size from " +
            sizeText(videoArea_.w, videoArea_.h) + " to " + sizeText(area.w, area.h) +
            (session_->touch() ? " (Video: Record video records anew)" : " (Ctrl+R records anew)"));
        return;
    }
    videoArea_ = area;
    const std::optional<std::int64_t> slot = video_->due(now() - videoStart_);
    if (!slot) return;
    std::vector<std::uint8_t> pixels = video_->buffer();
    try {
        readPixels(sdl_->renderer(), area, pixels.data());
    } catch (const std::exception& e) {
        stopVideo(std::string("Recording stopped: ") + e.what());
        return;
    }
    video_->push(std::move(pixels), *slot);
}

void App::updateVideoStatus() {
    VideoStatus& v = stats_.video;
    v.recording = video_ != nullptr;
    if (!video_) return;
    v.format = video_->format();
    v.seconds = now() - videoStart_;
    v.frames = video_->frames();
    v.dropped = video_->dropped();
}

}  // namespace psb::app
