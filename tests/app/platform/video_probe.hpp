#pragma once
// Reads a video file back through FFmpeg's libraries, for the tests: its frames' count, size,
// timestamps and the colour at one point of each, decoded as a player would.

#include <array>
#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libswscale/swscale.h>
}

namespace psb::app::test {

struct DecodedVideo {
    std::string codec;
    int width = 0;
    int height = 0;
    std::vector<double> seconds;                      ///< each frame's time
    std::vector<std::array<std::uint8_t, 3>> centre;  ///< each frame's RGB at (w/2, h/2)
};

inline DecodedVideo decodeVideo(const std::filesystem::path& file) {
    AVFormatContext* format = nullptr;
    if (avformat_open_input(&format, file.c_str(), nullptr, nullptr) < 0) {
        throw std::runtime_error("cannot open " + file.string());
    }
    DecodedVideo v;
    avformat_find_stream_info(format, nullptr);
    const int index = av_find_best_stream(format, AVMEDIA_TYPE_VIDEO, -1, -1, nullptr, 0);
    if (index < 0) {
        avformat_close_input(&format);
        throw std::runtime_error("no video stream in " + file.string());
    }
    AVStream* stream = format->streams[index];
    const AVCodec* decoder = avcodec_find_decoder(stream->codecpar->codec_id);
    AVCodecContext* codec = avcodec_alloc_context3(decoder);
    avcodec_parameters_to_context(codec, stream->codecpar);
    avcodec_open2(codec, decoder, nullptr);
    v.codec = decoder->name;
    v.width = codec->width;
    v.height = codec->height;
    AVPacket* packet = av_packet_alloc();
    AVFrame* frame = av_frame_alloc();
    SwsContext* sws = nullptr;
    std::vector<std::uint8_t> rgb;
    const auto take = [&] {
        while (avcodec_receive_frame(codec, frame) == 0) {
            v.seconds.push_back(static_cast<double>(frame->best_effort_timestamp) *
                                av_q2d(stream->time_base));
            sws = sws_getCachedContext(sws, frame->width, frame->height,
                                       static_cast<AVPixelFormat>(frame->format), frame->width,
                                       frame->height, AV_PIX_FMT_RGB24, SWS_POINT, nullptr, nullptr,
                                       nullptr);
            rgb.resize(static_cast<std::size_t>(frame->width) * frame->height * 3);
            std::uint8_t* dst[4] = {rgb.data(), nullptr, nullptr, nullptr};
            int stride[4] = {frame->width * 3, 0, 0, 0};
            sws_scale(sws, frame->data, frame->linesize, 0, frame->height, dst, stride);
            const std::size_t at =
                (static_cast<std::size_t>(frame->height / 2) * frame->width + frame->width / 2) * 3;
            v.centre.push_back({rgb[at], rgb[at + 1], rgb[at + 2]});
            av_frame_unref(frame);
        }
    };
    while (av_read_frame(format, packet) >= 0) {
        if (packet->stream_index == index) {
            avcodec_send_packet(codec, packet);
            take();
        }
        av_packet_unref(packet);
    }
    avcodec_send_packet(codec, nullptr);
    take();
    sws_freeContext(sws);
    av_frame_free(&frame);
    av_packet_free(&packet);
    avcodec_free_context(&codec);
    avformat_close_input(&format);
    return v;
}

}  // namespace psb::app::test
