// The recorder's pacing, its queue and its files: a part file while recording, the name once
// complete, every frame handed over in the file.

#include "platform/video_recorder.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "platform/video_probe.hpp"
#include "temp_dir_test.hpp"

namespace psb::app {
namespace {

class VideoRecorderTest : public TempDirTest {
  protected:
    VideoRecorderTest() : TempDirTest("psb-video-recorder") {}
    void SetUp() override {
        TempDirTest::SetUp();
        if (const auto why = videoFormatProblem(VideoFormat::Mp4)) GTEST_SKIP() << *why;
    }
};

TEST_F(VideoRecorderTest, ARealTimeSlotIsFilledOnceAndJitterLosesNoSlot) {
    VideoRecorder r(dir_ / "pace.mp4", VideoFormat::Mp4, 32, 32, 60,
                    VideoRecorder::Pacing::RealTime);
    // A window at 60 frames a second, each frame up to a third of a frame early or late.
    const double jitter[] = {0.0, 0.3, -0.3, 0.2, -0.1, 0.33, -0.33, 0.0};
    std::vector<std::int64_t> slots;
    for (int i = 0; i < 8; ++i) {
        const auto slot = r.due((i + jitter[i]) / 60.0);
        ASSERT_TRUE(slot) << "frame " << i;
        slots.push_back(*slot);
        r.push(r.buffer(), *slot);
        // A second frame in the same slot (a window drawing faster) is not due.
        EXPECT_FALSE(r.due((i + jitter[i] + 0.1) / 60.0)) << "frame " << i;
    }
    EXPECT_EQ(slots, (std::vector<std::int64_t>{0, 1, 2, 3, 4, 5, 6, 7}));
    // A window late by three frames leaves slots out.
    const auto late = r.due(11.0 / 60.0);
    ASSERT_TRUE(late);
    EXPECT_EQ(*late, 11);
    r.push(r.buffer(), *late);
    const VideoSummary s = r.stop();
    // Handed over faster than real time, some may wait in vain for room in the queue.
    EXPECT_EQ(s.frames + s.dropped, 9u);
    EXPECT_NEAR(s.seconds, 12.0 / 60.0, 1e-9);
}

TEST_F(VideoRecorderTest, EveryFramePacingKeepsEveryFrameInTheFile) {
    const auto file = dir_ / "every.mp4";
    VideoRecorder r(file, VideoFormat::Mp4, 96, 64, 30, VideoRecorder::Pacing::EveryFrame);
    for (int i = 0; i < 45; ++i) {
        const auto slot = r.due(0.0);  // the time does not matter
        ASSERT_TRUE(slot);
        EXPECT_EQ(*slot, i);
        std::vector<std::uint8_t> px = r.buffer();
        ASSERT_EQ(px.size(), 96u * 64u * 4u);
        std::fill(px.begin(), px.end(), static_cast<std::uint8_t>(i * 5));
        r.push(std::move(px), *slot);
    }
    // While recording the file is the part file; the name is taken only when complete.
    EXPECT_TRUE(std::filesystem::exists(dir_ / "every.mp4.part"));
    EXPECT_FALSE(std::filesystem::exists(file));
    const VideoSummary s = r.stop();
    EXPECT_EQ(s.file, std::filesystem::absolute(file));
    EXPECT_EQ(s.frames, 45u);
    EXPECT_EQ(s.dropped, 0u);
    EXPECT_EQ(s.width, 96);
    EXPECT_EQ(s.height, 64);
    EXPECT_TRUE(std::filesystem::exists(file));
    EXPECT_FALSE(std::filesystem::exists(dir_ / "every.mp4.part"));
    EXPECT_EQ(test::decodeVideo(file).seconds.size(), 45u);
}

TEST_F(VideoRecorderTest, FramesHandedOverAreEncodedOrCountedAsDropped) {
    // Real time, frames pushed as fast as the loop goes: the queue fills and frames are left
    // out, never lost silently.
    const auto file = dir_ / "fast.mp4";
    VideoRecorder r(file, VideoFormat::Mp4, 640, 480, 60, VideoRecorder::Pacing::RealTime);
    const int pushed = 120;
    for (int i = 0; i < pushed; ++i) {
        const auto slot = r.due(i / 60.0);
        ASSERT_TRUE(slot);
        r.push(r.buffer(), *slot);
    }
    const VideoSummary s = r.stop();
    EXPECT_EQ(s.frames + s.dropped, static_cast<std::size_t>(pushed));
    EXPECT_EQ(test::decodeVideo(file).seconds.size(), s.frames);
}

TEST_F(VideoRecorderTest, StopTwiceIsRefusedAndNoSlotIsDueAfterStop) {
    VideoRecorder r(dir_ / "twice.mp4", VideoFormat::Mp4, 32, 32, 30,
                    VideoRecorder::Pacing::RealTime);
    r.push(r.buffer(), *r.due(0.0));
    (void)r.stop();
    EXPECT_FALSE(r.due(10.0));
    EXPECT_THROW((void)r.stop(), VideoError);
}

TEST_F(VideoRecorderTest, AnUnwritableFolderIsRefusedAtTheStart) {
    EXPECT_THROW(VideoRecorder(dir_ / "no" / "x.mp4", VideoFormat::Mp4, 32, 32, 30,
                               VideoRecorder::Pacing::RealTime),
                 VideoError);
}

TEST_F(VideoRecorderTest, DestroyingARecorderCompletesItsFile) {
    const auto file = dir_ / "kept.webm";
    if (videoFormatProblem(VideoFormat::WebM)) GTEST_SKIP();
    {
        VideoRecorder r(file, VideoFormat::WebM, 64, 64, 30, VideoRecorder::Pacing::EveryFrame);
        for (int i = 0; i < 5; ++i)
            r.push(r.buffer(), *r.due(0.0));
    }
    EXPECT_EQ(test::decodeVideo(file).seconds.size(), 5u);
}

}  // namespace
}  // namespace psb::app
