// The video files, read back as a player reads them: frame counts, sizes, times and colours.

#include "platform/video_encoder.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "platform/video_probe.hpp"
#include "temp_dir_test.hpp"

namespace psb::app {
namespace {

/// A w × h RGBA frame of one colour with a white square at x0 (so that frames differ).
std::vector<std::uint8_t> frame(int w, int h, std::uint8_t r, std::uint8_t g, std::uint8_t b,
                                int x0 = -100) {
    std::vector<std::uint8_t> px(static_cast<std::size_t>(w) * h * 4);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const bool square = x >= x0 && x < x0 + 8 && y < 8;
            std::uint8_t* p = &px[(static_cast<std::size_t>(y) * w + x) * 4];
            p[0] = square ? 255 : r;
            p[1] = square ? 255 : g;
            p[2] = square ? 255 : b;
            p[3] = 255;
        }
    }
    return px;
}

class VideoEncoderTest : public TempDirTest, public ::testing::WithParamInterface<VideoFormat> {
  protected:
    VideoEncoderTest() : TempDirTest("psb-video-encoder") {}
};

TEST_P(VideoEncoderTest, EveryFrameIsInTheFileAtItsTime) {
    const VideoFormat f = GetParam();
    if (const auto why = videoFormatProblem(f)) GTEST_SKIP() << *why;
    const auto file = dir_ / (std::string("clip") + extension(f));
    const int w = 160, h = 120, fps = 25, n = 30;
    {
        VideoEncoder e(file, f, w, h, fps);
        for (int i = 0; i < n; ++i) {
            const auto px = frame(w, h, 200, 30, 40, 4 * i);
            e.add(px.data(), w * 4, i);
        }
        e.finish();
        EXPECT_EQ(e.width(), w);
        EXPECT_EQ(e.height(), h);
    }
    const test::DecodedVideo v = test::decodeVideo(file);
    EXPECT_EQ(v.width, w);
    EXPECT_EQ(v.height, h);
    ASSERT_EQ(v.seconds.size(), static_cast<std::size_t>(n)) << v.codec;
    for (int i = 0; i < n; ++i)
        EXPECT_NEAR(v.seconds[i] - v.seconds[0], i / double(fps), 0.011) << "frame " << i;
    // The colour comes back (lossy codecs within a few levels).
    for (const auto& c : v.centre) {
        EXPECT_NEAR(c[0], 200, 12);
        EXPECT_NEAR(c[1], 30, 12);
        EXPECT_NEAR(c[2], 40, 12);
    }
}

INSTANTIATE_TEST_SUITE_P(Formats, VideoEncoderTest,
                         ::testing::Values(VideoFormat::Mp4, VideoFormat::WebM, VideoFormat::Gif),
                         [](const auto& param) { return std::string(toString(param.param)); });

class VideoEncoderFileTest : public TempDirTest {
  protected:
    VideoEncoderFileTest() : TempDirTest("psb-video-encoder-file") {}
};

TEST_F(VideoEncoderFileTest, CodecsAreTheOnesNamed) {
    for (const VideoFormat f : {VideoFormat::Mp4, VideoFormat::WebM, VideoFormat::Gif}) {
        if (videoFormatProblem(f)) continue;
        const auto file = dir_ / (std::string("c") + extension(f));
        VideoEncoder e(file, f, 64, 48, 30);
        const auto px = frame(64, 48, 10, 20, 30);
        e.add(px.data(), 64 * 4, 0);
        e.finish();
        const std::string codec = test::decodeVideo(file).codec;
        const std::string expected = f == VideoFormat::Mp4    ? "h264"
                                     : f == VideoFormat::WebM ? "vp8"
                                                              : "gif";
        EXPECT_NE(codec.find(expected), std::string::npos) << codec;
    }
}

TEST_F(VideoEncoderFileTest, OddSizesLoseTheirLastRowAndColumnInMp4) {
    if (const auto why = videoFormatProblem(VideoFormat::Mp4)) GTEST_SKIP() << *why;
    const auto file = dir_ / "odd.mp4";
    VideoEncoder e(file, VideoFormat::Mp4, 101, 75, 30);
    EXPECT_EQ(e.width(), 100);
    EXPECT_EQ(e.height(), 74);
    const auto px = frame(101, 75, 0, 0, 255);
    e.add(px.data(), 101 * 4, 0);
    e.finish();
    const auto v = test::decodeVideo(file);
    EXPECT_EQ(v.width, 100);
    EXPECT_EQ(v.height, 74);
    EXPECT_EQ(v.seconds.size(), 1u);
}

TEST_F(VideoEncoderFileTest, AWideGifIsScaledTo640Pixels) {
    if (const auto why = videoFormatProblem(VideoFormat::Gif)) GTEST_SKIP() << *why;
    const auto file = dir_ / "wide.gif";
    VideoEncoder e(file, VideoFormat::Gif, 1280, 720, 25);
    EXPECT_EQ(e.width(), 640);
    EXPECT_EQ(e.height(), 360);
    const auto px = frame(1280, 720, 0, 128, 0);
    e.add(px.data(), 1280 * 4, 0);
    e.finish();
    const auto v = test::decodeVideo(file);
    EXPECT_EQ(v.width, 640);
    EXPECT_EQ(v.height, 360);
    ASSERT_EQ(v.centre.size(), 1u);
    EXPECT_NEAR(v.centre[0][1], 128, 8);
}

TEST_F(VideoEncoderFileTest, ASkippedSlotHoldsTheFrameBefore) {
    if (const auto why = videoFormatProblem(VideoFormat::Mp4)) GTEST_SKIP() << *why;
    const auto file = dir_ / "gap.mp4";
    VideoEncoder e(file, VideoFormat::Mp4, 64, 64, 10);
    for (const int slot : {0, 1, 5, 6}) {
        const auto px = frame(64, 64, 50, 50, 50, slot * 4);
        e.add(px.data(), 64 * 4, slot);
    }
    e.finish();
    const auto v = test::decodeVideo(file);
    ASSERT_EQ(v.seconds.size(), 4u);
    EXPECT_NEAR(v.seconds[2] - v.seconds[0], 0.5, 1e-6);
    EXPECT_NEAR(v.seconds[3] - v.seconds[0], 0.6, 1e-6);
}

TEST_F(VideoEncoderFileTest, FramesOutOfOrderOrAfterTheEndAreRefused) {
    if (const auto why = videoFormatProblem(VideoFormat::Mp4)) GTEST_SKIP() << *why;
    VideoEncoder e(dir_ / "order.mp4", VideoFormat::Mp4, 32, 32, 30);
    const auto px = frame(32, 32, 1, 2, 3);
    e.add(px.data(), 32 * 4, 3);
    EXPECT_THROW(e.add(px.data(), 32 * 4, 3), VideoError);
    EXPECT_THROW(e.add(px.data(), 32 * 4, 2), VideoError);
    e.finish();
    EXPECT_THROW(e.add(px.data(), 32 * 4, 9), VideoError);
}

TEST_F(VideoEncoderFileTest, AFolderThatIsNotThereIsNamed) {
    if (const auto why = videoFormatProblem(VideoFormat::Mp4)) GTEST_SKIP() << *why;
    const auto file = dir_ / "missing" / "x.mp4";
    try {
        VideoEncoder e(file, VideoFormat::Mp4, 32, 32, 30);
        FAIL() << "opened " << file;
    } catch (const VideoError& err) {
        EXPECT_NE(std::string(err.what()).find(file.string()), std::string::npos) << err.what();
    }
}

TEST_F(VideoEncoderFileTest, TooSmallOrNoFrameRateIsRefused) {
    EXPECT_THROW(VideoEncoder(dir_ / "a.mp4", VideoFormat::Mp4, 1, 10, 30), VideoError);
    EXPECT_THROW(VideoEncoder(dir_ / "b.mp4", VideoFormat::Mp4, 10, 10, 0), VideoError);
}

}  // namespace
}  // namespace psb::app
