#include "replay/VideoWriter.h"

#include "common/PngImage.h"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/error.h>
#include <libavutil/imgutils.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

#include <algorithm>

namespace nprgl {

struct VideoWriter::State {
    AVFormatContext* format = nullptr;
    AVCodecContext* codec = nullptr;
    AVStream* stream = nullptr;
    AVFrame* frame = nullptr;
    AVFrame* rgba = nullptr; // the picture, padded as swscale reads it (whole SIMD blocks)
    AVPacket* packet = nullptr;
    SwsContext* convert = nullptr;
    int width = 0; // of the frames given
    int height = 0;
    int fps = 0;
    bool live = false;
    const char* encoder = nullptr;
    bool webm = false;
    bool headerWritten = false;
    bool finished = false;
    std::string path;

    ~State()
    {
        sws_freeContext(convert);
        av_packet_free(&packet);
        av_frame_free(&frame);
        av_frame_free(&rgba);
        avcodec_free_context(&codec);
        if (format) {
            if (format->pb) avio_closep(&format->pb);
            avformat_free_context(format);
        }
    }
};

namespace {

std::string avError(int code)
{
    char text[AV_ERROR_MAX_STRING_SIZE] = {};
    av_strerror(code, text, sizeof text);
    return text;
}

} // namespace

VideoWriter::VideoWriter() = default;

VideoWriter::~VideoWriter() = default;

bool VideoWriter::open(const std::string& path, int fps, std::string& error, Speed speed)
{
    mState = std::make_unique<State>();
    State& s = *mState;
    s.path = path;
    s.fps = fps;
    s.live = speed == Speed::Live;
    // The encoders' statistics are not nprgl's to print; their errors still are.
    av_log_set_level(AV_LOG_ERROR);
    if (fps < 1 || fps > 1000) {
        error = "--fps: " + std::to_string(fps) + " is not a frame rate from 1 to 1000";
        return false;
    }
    const AVOutputFormat* container = av_guess_format(nullptr, path.c_str(), nullptr);
    if (!container) {
        error = path + ": no video container for this name (use .mp4, .mkv, .mov or .webm)";
        return false;
    }
    // VP9 where the container is WebM (which takes no H.264), else H.264: both are in
    // Debian's FFmpeg without non-free parts.
    s.webm = std::string(container->name).find("webm") != std::string::npos;
    s.encoder = s.webm ? "libvpx-vp9" : "libx264";
    if (!avcodec_find_encoder_by_name(s.encoder)) {
        error = path + ": this FFmpeg has no " + s.encoder + " encoder";
        return false;
    }
    return true;
}

bool VideoWriter::start(int width, int height, std::string& error)
{
    State& s = *mState;
    const std::string& path = s.path;
    s.width = width;
    s.height = height;
    const int w = width & ~1, h = height & ~1;
    if (w < 2 || h < 2) {
        error = path + ": cannot encode " + std::to_string(width) + "x" +
                std::to_string(height) + " frames";
        return false;
    }
    int rc = avformat_alloc_output_context2(&s.format, nullptr, nullptr, path.c_str());
    if (rc < 0 || !s.format) {
        error = path + ": " + avError(rc);
        return false;
    }
    const AVCodec* encoder = avcodec_find_encoder_by_name(s.encoder);
    s.codec = avcodec_alloc_context3(encoder);
    s.stream = avformat_new_stream(s.format, nullptr);
    s.frame = av_frame_alloc();
    s.rgba = av_frame_alloc();
    s.packet = av_packet_alloc();
    if (!s.codec || !s.stream || !s.frame || !s.rgba || !s.packet) {
        error = path + ": out of memory";
        return false;
    }
    s.codec->width = w;
    s.codec->height = h;
    s.codec->time_base = AVRational{1, s.fps};
    s.codec->framerate = AVRational{s.fps, 1};
    s.codec->pix_fmt = AV_PIX_FMT_YUV420P;
    s.codec->gop_size = s.fps * 2;
    s.codec->color_range = AVCOL_RANGE_MPEG;
    s.codec->colorspace = AVCOL_SPC_SMPTE170M; // swscale's RGB to YUV is BT.601
    s.codec->color_primaries = AVCOL_PRI_SMPTE170M;
    s.codec->color_trc = AVCOL_TRC_SMPTE170M;
    // Constant quality, near transparent: a stylised frame's ink lines and flat tones are
    // what a low bit rate smears first.
    if (s.webm) {
        s.codec->bit_rate = 0;
        av_opt_set(s.codec->priv_data, "crf", "20", 0);
        av_opt_set(s.codec->priv_data, "deadline", s.live ? "realtime" : "good", 0);
        av_opt_set(s.codec->priv_data, "cpu-used", s.live ? "8" : "4", 0);
        av_opt_set(s.codec->priv_data, "row-mt", "1", 0);
    } else {
        av_opt_set(s.codec->priv_data, "crf", "16", 0);
        av_opt_set(s.codec->priv_data, "preset", s.live ? "veryfast" : "medium", 0);
    }
    if (s.format->oformat->flags & AVFMT_GLOBALHEADER) {
        s.codec->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
    }
    if ((rc = avcodec_open2(s.codec, encoder, nullptr)) < 0) {
        error = path + ": cannot open the " + s.encoder + " encoder: " + avError(rc);
        return false;
    }
    s.stream->time_base = s.codec->time_base;
    avcodec_parameters_from_context(s.stream->codecpar, s.codec);
    s.frame->format = s.codec->pix_fmt;
    s.frame->width = w;
    s.frame->height = h;
    s.rgba->format = AV_PIX_FMT_RGBA;
    s.rgba->width = w;
    s.rgba->height = h;
    if ((rc = av_frame_get_buffer(s.frame, 0)) < 0 || (rc = av_frame_get_buffer(s.rgba, 0)) < 0) {
        error = path + ": " + avError(rc);
        return false;
    }
    s.convert = sws_getContext(w, h, AV_PIX_FMT_RGBA, w, h, AV_PIX_FMT_YUV420P, SWS_BICUBIC,
                               nullptr, nullptr, nullptr);
    if (!s.convert) {
        error = path + ": cannot convert RGBA frames to YUV 4:2:0";
        return false;
    }
    if ((rc = avio_open(&s.format->pb, path.c_str(), AVIO_FLAG_WRITE)) < 0) {
        error = "cannot write " + path + ": " + avError(rc);
        return false;
    }
    if ((rc = avformat_write_header(s.format, nullptr)) < 0) {
        error = path + ": cannot write the header: " + avError(rc);
        return false;
    }
    s.headerWritten = true;
    return true;
}

bool VideoWriter::add(const PngImage& image, std::string& error)
{
    State& s = *mState;
    if (!s.headerWritten && !start(image.width, image.height, error)) return false;
    if (image.width != s.width || image.height != s.height) {
        error = s.path + ": a frame of " + std::to_string(image.width) + "x" +
                std::to_string(image.height) + " in a video of " + std::to_string(s.width) +
                "x" + std::to_string(s.height);
        return false;
    }
    int rc = av_frame_make_writable(s.frame);
    if (rc < 0) {
        error = s.path + ": " + avError(rc);
        return false;
    }
    const size_t row = size_t(s.rgba->width) * 4;
    for (int y = 0; y < s.rgba->height; ++y) {
        std::copy_n(image.rgba.data() + size_t(y) * image.width * 4, row,
                    s.rgba->data[0] + size_t(y) * s.rgba->linesize[0]);
    }
    sws_scale(s.convert, s.rgba->data, s.rgba->linesize, 0, s.frame->height, s.frame->data,
              s.frame->linesize);
    s.frame->pts = int64_t(mFrames);
    if ((rc = avcodec_send_frame(s.codec, s.frame)) < 0) {
        error = s.path + ": cannot encode frame " + std::to_string(mFrames + 1) + ": " +
                avError(rc);
        return false;
    }
    ++mFrames;
    return encode(false, error);
}

bool VideoWriter::encode(bool flush, std::string& error)
{
    State& s = *mState;
    for (;;) {
        int rc = avcodec_receive_packet(s.codec, s.packet);
        if (rc == AVERROR(EAGAIN) && !flush) return true;
        if (rc == AVERROR_EOF) return true;
        if (rc < 0) {
            error = s.path + ": encoding failed: " + avError(rc);
            return false;
        }
        // Each frame lasts one tick: without it a container guesses the last frame's length
        // (and the rate) from the others.
        if (s.packet->duration == 0) s.packet->duration = 1;
        av_packet_rescale_ts(s.packet, s.codec->time_base, s.stream->time_base);
        s.packet->stream_index = s.stream->index;
        rc = av_interleaved_write_frame(s.format, s.packet);
        if (rc < 0) {
            error = "cannot write " + s.path + ": " + avError(rc);
            return false;
        }
    }
}

bool VideoWriter::finish(std::string& error)
{
    if (!mState || !mState->headerWritten || mState->finished) return true;
    State& s = *mState;
    s.finished = true;
    int rc = avcodec_send_frame(s.codec, nullptr);
    if (rc < 0 && rc != AVERROR_EOF) {
        error = s.path + ": " + avError(rc);
        return false;
    }
    if (!encode(true, error)) return false;
    if ((rc = av_write_trailer(s.format)) < 0) {
        error = "cannot write " + s.path + ": " + avError(rc);
        return false;
    }
    if ((rc = avio_closep(&s.format->pb)) < 0) {
        error = "cannot write " + s.path + ": " + avError(rc);
        return false;
    }
    return true;
}

} // namespace nprgl
