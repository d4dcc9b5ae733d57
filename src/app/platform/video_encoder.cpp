#include "platform/video_encoder.hpp"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <initializer_list>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavfilter/buffersink.h>
#include <libavfilter/buffersrc.h>
#include <libavformat/avformat.h>
#include <libavutil/opt.h>
}

namespace psb::app {

namespace {

std::string avError(int code) {
    char buf[AV_ERROR_MAX_STRING_SIZE] = {};
    av_strerror(code, buf, sizeof buf);
    return buf;
}

/// Throws VideoError("`what`: FFmpeg's reason") when `code` is an error.
int check(int code, const std::string& what) {
    if (code < 0) throw VideoError(what + ": " + avError(code));
    return code;
}

struct Recipe {
    const char* muxer;
    const char* const* encoders;  ///< by preference; nullptr-terminated
    /// From the RGBA frames ([in]) to what the encoder takes ([out]); a GIF's also takes its
    /// palette ([pal], one 16 × 16 frame made by `palette` from the first frame).
    std::string filters;
    const char* palette;  ///< nullptr: no palette
    AVPixelFormat pixels;
};

constexpr const char* kH264[] = {"libx264", nullptr};
constexpr const char* kVp8[] = {"libvpx", nullptr};
constexpr const char* kGif[] = {"gif", nullptr};
constexpr const char* kEven =
    "[in]crop=w=trunc(iw/2)*2:h=trunc(ih/2)*2:x=0:y=0,format=yuv420p[out]";
constexpr const char* kGifScale = "scale=w='min(640,iw)':h=-2:flags=lanczos";

Recipe recipe(VideoFormat format) {
    switch (format) {
        case VideoFormat::Mp4:
            return {"mp4", kH264, kEven, nullptr, AV_PIX_FMT_YUV420P};
        case VideoFormat::WebM:
            return {"webm", kVp8, kEven, nullptr, AV_PIX_FMT_YUV420P};
        case VideoFormat::Gif:
            // One palette for the clip, from its first frame: a palette a frame (palettegen's
            // single-frame mode) costs three times as much to apply, more than a frame's time.
            return {
                "gif", kGif,
                std::string("[in]") + kGifScale +
                    "[x];[x][pal]paletteuse=dither=bayer:bayer_scale=3:diff_mode=rectangle[out]",
                "palettegen=max_colors=256:reserve_transparent=0", AV_PIX_FMT_PAL8};
    }
    return recipe(VideoFormat::Mp4);
}

/// A buffer source for frames `width` × `height` of `pixels`, counted at `fps`.
AVFilterContext* source(AVFilterGraph* graph, const char* name, int width, int height,
                        AVPixelFormat pixels, int fps) {
    char args[160];
    std::snprintf(args, sizeof args, "video_size=%dx%d:pix_fmt=%d:time_base=1/%d:pixel_aspect=1/1",
                  width, height, static_cast<int>(pixels), fps);
    AVFilterContext* c = nullptr;
    check(avfilter_graph_create_filter(&c, avfilter_get_by_name("buffer"), name, args, nullptr,
                                       graph),
          "the video's frame source");
    return c;
}

/// A buffer sink giving frames of `pixels`.
AVFilterContext* sink(AVFilterGraph* graph, AVPixelFormat pixels) {
    AVFilterContext* c =
        avfilter_graph_alloc_filter(graph, avfilter_get_by_name("buffersink"), "out");
    if (c == nullptr) throw VideoError("the video's frame sink: out of memory");
    const AVPixelFormat formats[] = {pixels, AV_PIX_FMT_NONE};
    check(av_opt_set_int_list(c, "pix_fmts", formats, AV_PIX_FMT_NONE, AV_OPT_SEARCH_CHILDREN),
          "the video's pixel format");
    check(avfilter_init_str(c, nullptr), "the video's frame sink");
    return c;
}

/// Links `description` between the sources (by their names) and the sink "out", and checks
/// the whole graph.
void link(AVFilterGraph* graph, const char* description,
          std::initializer_list<AVFilterContext*> sources, AVFilterContext* out) {
    AVFilterInOut* outputs = nullptr;
    AVFilterInOut* inputs = avfilter_inout_alloc();
    if (inputs == nullptr) throw VideoError("out of memory for the video's filters");
    inputs->name = av_strdup("out");
    inputs->filter_ctx = out;
    for (AVFilterContext* s : sources) {
        AVFilterInOut* o = avfilter_inout_alloc();
        if (o == nullptr) {
            avfilter_inout_free(&outputs);
            avfilter_inout_free(&inputs);
            throw VideoError("out of memory for the video's filters");
        }
        o->name = av_strdup(s->name);
        o->filter_ctx = s;
        o->next = outputs;
        outputs = o;
    }
    const int parsed = avfilter_graph_parse_ptr(graph, description, &inputs, &outputs, nullptr);
    avfilter_inout_free(&outputs);
    avfilter_inout_free(&inputs);
    check(parsed, "the video's filters");
    check(avfilter_graph_config(graph, nullptr), "the video's filters");
}

const AVCodec* findEncoder(const Recipe& r) {
    for (const char* const* name = r.encoders; *name != nullptr; ++name) {
        if (const AVCodec* c = avcodec_find_encoder_by_name(*name)) return c;
    }
    return nullptr;
}

}  // namespace

std::optional<std::string> videoFormatProblem(VideoFormat format) {
    const Recipe r = recipe(format);
    if (findEncoder(r) == nullptr) {
        return std::string("this FFmpeg has no ") + r.encoders[0] + " encoder for " +
               toString(format);
    }
    if (av_guess_format(r.muxer, nullptr, nullptr) == nullptr) {
        return std::string("this FFmpeg cannot write ") + toString(format) + " files";
    }
    return std::nullopt;
}

struct VideoEncoder::Impl {
    std::string name;  ///< the file, for messages
    AVFormatContext* format = nullptr;
    AVCodecContext* codec = nullptr;
    AVStream* stream = nullptr;
    AVFilterGraph* graph = nullptr;
    AVFilterContext* source_ = nullptr;
    AVFilterContext* sink_ = nullptr;
    AVFilterContext* palette = nullptr;  ///< a GIF's [pal] source, until its palette is given
    AVFrame* in = nullptr;
    AVFrame* out = nullptr;
    AVPacket* packet = nullptr;
    VideoFormat format_ = VideoFormat::Mp4;
    int rate = 0;  ///< frames a second
    std::int64_t lastIndex = -1;
    bool finished = false;

    ~Impl() {
        av_packet_free(&packet);
        av_frame_free(&out);
        av_frame_free(&in);
        avfilter_graph_free(&graph);
        avcodec_free_context(&codec);
        if (format != nullptr) {
            if ((format->oformat->flags & AVFMT_NOFILE) == 0) avio_closep(&format->pb);
            avformat_free_context(format);
        }
    }

    void buildFilters(const Recipe& r, int width, int height, int fps) {
        graph = avfilter_graph_alloc();
        if (graph == nullptr) throw VideoError("out of memory for the video's filters");
        graph->nb_threads = 1;
        source_ = source(graph, "in", width, height, AV_PIX_FMT_RGBA, fps);
        sink_ = sink(graph, r.pixels);
        if (r.palette != nullptr) {
            palette = source(graph, "pal", 16, 16, AV_PIX_FMT_RGB32, fps);
            link(graph, r.filters.c_str(), {source_, palette}, sink_);
        } else {
            link(graph, r.filters.c_str(), {source_}, sink_);
        }
    }

    /// A GIF's palette, from its first frame (`in`), handed to the [pal] source once.
    void makePalette(const Recipe& r, int fps) {
        AVFilterGraph* g = avfilter_graph_alloc();
        if (g == nullptr) throw VideoError("out of memory for the GIF's palette");
        AVFrame* made = av_frame_alloc();
        try {
            AVFilterContext* from = source(g, "in", in->width, in->height, AV_PIX_FMT_RGBA, fps);
            AVFilterContext* to = sink(g, AV_PIX_FMT_RGB32);
            const std::string description =
                std::string("[in]") + kGifScale + "," + r.palette + "[out]";
            link(g, description.c_str(), {from}, to);
            check(av_buffersrc_add_frame_flags(from, in, AV_BUFFERSRC_FLAG_KEEP_REF),
                  "the GIF's palette");
            check(av_buffersrc_add_frame_flags(from, nullptr, 0), "the GIF's palette");
            check(av_buffersink_get_frame(to, made), "the GIF's palette");
            made->pts = in->pts;
            check(av_buffersrc_add_frame_flags(palette, made, 0), "the GIF's palette");
            check(av_buffersrc_add_frame_flags(palette, nullptr, 0), "the GIF's palette");
        } catch (...) {
            av_frame_free(&made);
            avfilter_graph_free(&g);
            throw;
        }
        av_frame_free(&made);
        avfilter_graph_free(&g);
        palette = nullptr;  // given
    }

    void openCodec(const Recipe& r, VideoFormat kind, int fps) {
        const AVCodec* encoder = findEncoder(r);
        if (encoder == nullptr) throw VideoError(*videoFormatProblem(kind));
        codec = avcodec_alloc_context3(encoder);
        if (codec == nullptr) throw VideoError("out of memory for the video encoder");
        codec->width = av_buffersink_get_w(sink_);
        codec->height = av_buffersink_get_h(sink_);
        codec->pix_fmt = static_cast<AVPixelFormat>(av_buffersink_get_format(sink_));
        codec->sample_aspect_ratio = {1, 1};
        codec->time_base = {1, fps};
        codec->framerate = {fps, 1};
        if (kind == VideoFormat::Mp4) {
            codec->gop_size = 2 * fps;
            av_opt_set(codec->priv_data, "preset", "superfast", 0);
            av_opt_set(codec->priv_data, "crf", "20", 0);
        } else if (kind == VideoFormat::WebM) {
            // Constrained quality: near-lossless for a few discs, capped for a crowded box.
            codec->gop_size = 2 * fps;
            codec->bit_rate = 16'000'000;
            codec->qmin = 0;
            codec->qmax = 40;
            av_opt_set(codec->priv_data, "deadline", "realtime", 0);
            av_opt_set(codec->priv_data, "cpu-used", "16", 0);
            av_opt_set(codec->priv_data, "crf", "4", 0);
        }
        if ((format->oformat->flags & AVFMT_GLOBALHEADER) != 0) {
            codec->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
        }
        check(avcodec_open2(codec, encoder, nullptr),
              std::string("the ") + encoder->name + " encoder");
    }

    /// Hands the filters' output to the encoder, and the encoder's output to the file.
    void drain(bool flushing) {
        for (;;) {
            const int got = av_buffersink_get_frame(sink_, out);
            if (got == AVERROR(EAGAIN) || got == AVERROR_EOF) break;
            check(got, "converting a frame");
            out->pict_type = AV_PICTURE_TYPE_NONE;
            const int sent = avcodec_send_frame(codec, out);
            av_frame_unref(out);
            check(sent, "encoding a frame");
            writePackets();
        }
        if (flushing) {
            check(avcodec_send_frame(codec, nullptr), "finishing the encoding");
            writePackets();
        }
    }

    void writePackets() {
        for (;;) {
            const int got = avcodec_receive_packet(codec, packet);
            if (got == AVERROR(EAGAIN) || got == AVERROR_EOF) return;
            check(got, "encoding a frame");
            av_packet_rescale_ts(packet, codec->time_base, stream->time_base);
            packet->stream_index = stream->index;
            check(av_interleaved_write_frame(format, packet), "writing " + name);
        }
    }
};

VideoEncoder::VideoEncoder(const std::filesystem::path& file, VideoFormat kind, int width,
                           int height, int fps)
    : impl_(std::make_unique<Impl>()) {
    if (width < 2 || height < 2 || fps < 1) {
        throw VideoError("a video needs at least 2 × 2 pixels and 1 frame a second");
    }
    av_log_set_level(AV_LOG_ERROR);
    Impl& m = *impl_;
    m.name = file.string();
    m.format_ = kind;
    m.rate = fps;
    const Recipe r = recipe(kind);
    check(avformat_alloc_output_context2(&m.format, nullptr, r.muxer, m.name.c_str()),
          std::string("the ") + toString(kind) + " writer");
    m.buildFilters(r, width, height, fps);
    m.openCodec(r, kind, fps);
    m.stream = avformat_new_stream(m.format, nullptr);
    if (m.stream == nullptr) throw VideoError("out of memory for the video stream");
    m.stream->time_base = m.codec->time_base;
    m.stream->avg_frame_rate = {fps, 1};
    m.stream->sample_aspect_ratio = m.codec->sample_aspect_ratio;
    check(avcodec_parameters_from_context(m.stream->codecpar, m.codec), "the video stream");
    check(avio_open(&m.format->pb, m.name.c_str(), AVIO_FLAG_WRITE), "cannot create " + m.name);
    AVDictionary* options = nullptr;
    if (kind == VideoFormat::Mp4) av_dict_set(&options, "movflags", "+faststart", 0);
    const int header = avformat_write_header(m.format, &options);
    av_dict_free(&options);
    check(header, "writing " + m.name);

    m.in = av_frame_alloc();
    m.out = av_frame_alloc();
    m.packet = av_packet_alloc();
    if (m.in == nullptr || m.out == nullptr || m.packet == nullptr) {
        throw VideoError("out of memory for the video's frames");
    }
    m.in->format = AV_PIX_FMT_RGBA;
    m.in->width = width;
    m.in->height = height;
    m.in->sample_aspect_ratio = {1, 1};
    check(av_frame_get_buffer(m.in, 0), "a video frame");
}

VideoEncoder::~VideoEncoder() = default;

void VideoEncoder::add(const std::uint8_t* rgba, int stride, std::int64_t index) {
    Impl& m = *impl_;
    if (m.finished) throw VideoError("the video " + m.name + " is already complete");
    if (index <= m.lastIndex) throw VideoError("video frames out of order");
    check(av_frame_make_writable(m.in), "a video frame");
    const auto row = static_cast<std::size_t>(m.in->width) * 4;
    for (int y = 0; y < m.in->height; ++y) {
        std::memcpy(m.in->data[0] + static_cast<std::ptrdiff_t>(y) * m.in->linesize[0],
                    rgba + static_cast<std::ptrdiff_t>(y) * stride, row);
    }
    m.in->pts = index;
    m.lastIndex = index;
    if (m.palette != nullptr) m.makePalette(recipe(m.format_), m.rate);
    check(av_buffersrc_add_frame_flags(m.source_, m.in, AV_BUFFERSRC_FLAG_KEEP_REF),
          "converting a frame");
    m.drain(false);
}

void VideoEncoder::finish() {
    Impl& m = *impl_;
    if (m.finished) return;
    m.finished = true;
    if (m.lastIndex < 0) throw VideoError("the video " + m.name + " has no frame");
    check(av_buffersrc_add_frame_flags(m.source_, nullptr, 0), "finishing the video");
    m.drain(true);
    check(av_write_trailer(m.format), "completing " + m.name);
    check(avio_closep(&m.format->pb), "closing " + m.name);
}

int VideoEncoder::width() const {
    return impl_->codec->width;
}
int VideoEncoder::height() const {
    return impl_->codec->height;
}

}  // namespace psb::app
