// nprgl replay --video: the video decoded back with FFmpeg's libraries holds the replay's
// frames, in order, at the asked rate, within a lossy codec's tolerance of the PNGs.
#include "common/PngImage.h"
#include "tests/support/Process.h"

#include <gtest/gtest.h>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libswscale/swscale.h>
}

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

using namespace nprgl;
using namespace nprgl::test;
namespace fs = std::filesystem;

namespace {

struct Decoded {
    std::string codec;
    std::vector<double> seconds;  // each frame's time
    std::vector<PngImage> frames; // RGBA, top row first
};

// Every frame of the file's video stream, converted to RGBA.
bool decode(const std::string& path, Decoded& out, std::string& error)
{
    AVFormatContext* format = nullptr;
    if (avformat_open_input(&format, path.c_str(), nullptr, nullptr) < 0) {
        error = "cannot open " + path;
        return false;
    }
    avformat_find_stream_info(format, nullptr);
    const AVCodec* decoder = nullptr;
    const int index = av_find_best_stream(format, AVMEDIA_TYPE_VIDEO, -1, -1, &decoder, 0);
    if (index < 0 || !decoder) {
        avformat_close_input(&format);
        error = path + ": no video stream";
        return false;
    }
    const AVStream* stream = format->streams[index];
    out.codec = decoder->name;
    AVCodecContext* codec = avcodec_alloc_context3(decoder);
    avcodec_parameters_to_context(codec, stream->codecpar);
    avcodec_open2(codec, decoder, nullptr);
    AVPacket* packet = av_packet_alloc();
    AVFrame* frame = av_frame_alloc();
    SwsContext* convert = nullptr;
    // swscale writes whole SIMD blocks past a row's end: into a padded frame, then copied.
    AVFrame* rgba = av_frame_alloc();
    auto drain = [&]() {
        while (avcodec_receive_frame(codec, frame) == 0) {
            if (rgba->width != frame->width || rgba->height != frame->height) {
                av_frame_unref(rgba);
                rgba->format = AV_PIX_FMT_RGBA;
                rgba->width = frame->width;
                rgba->height = frame->height;
                av_frame_get_buffer(rgba, 0);
            }
            convert = sws_getCachedContext(convert, frame->width, frame->height,
                                           AVPixelFormat(frame->format), frame->width,
                                           frame->height, AV_PIX_FMT_RGBA, SWS_BICUBIC, nullptr,
                                           nullptr, nullptr);
            sws_scale(convert, frame->data, frame->linesize, 0, frame->height, rgba->data,
                      rgba->linesize);
            PngImage image;
            image.width = frame->width;
            image.height = frame->height;
            const size_t row = size_t(frame->width) * 4;
            image.rgba.resize(row * frame->height);
            for (int y = 0; y < frame->height; ++y) {
                std::copy_n(rgba->data[0] + size_t(y) * rgba->linesize[0], row,
                            image.rgba.data() + row * y);
            }
            out.frames.push_back(std::move(image));
            out.seconds.push_back(double(frame->best_effort_timestamp) *
                                  av_q2d(stream->time_base));
        }
    };
    while (av_read_frame(format, packet) >= 0) {
        if (packet->stream_index == index) avcodec_send_packet(codec, packet);
        av_packet_unref(packet);
        drain();
    }
    avcodec_send_packet(codec, nullptr);
    drain();
    sws_freeContext(convert);
    av_frame_free(&rgba);
    av_frame_free(&frame);
    av_packet_free(&packet);
    avcodec_free_context(&codec);
    avformat_close_input(&format);
    return true;
}

// Mean absolute difference of the RGB channels over the video's (even) size, 0..255.
double meanDifference(const PngImage& video, const PngImage& png)
{
    double sum = 0;
    for (int y = 0; y < video.height; ++y) {
        for (int x = 0; x < video.width; ++x) {
            const uint8_t* a = &video.rgba[(size_t(y) * video.width + x) * 4];
            const uint8_t* b = &png.rgba[(size_t(y) * png.width + x) * 4];
            for (int c = 0; c < 3; ++c) sum += std::abs(int(a[c]) - int(b[c]));
        }
    }
    return sum / (double(video.width) * video.height * 3);
}

struct VideoCase {
    const char* name;
    const char* file;
    const char* codec;
};

class Video : public testing::TestWithParam<VideoCase> {};

} // namespace

TEST_P(Video, DecodesToTheReplayedFramesInOrder)
{
    const VideoCase& c = GetParam();
    const std::string dir = freshDir(std::string("video_") + c.name);
    const std::string video = dir + "/" + c.file;
    // The morphing character: its three frames differ by more than the codec's loss (style
    // none: no paper grain, whose fine noise is what a lossy codec smooths first).
    const std::string fixture =
        std::string(NPRGL_TEST_SOURCE_DIR) + "/fixtures/character_morph.nprgl";
    ProcessResult r = runProcess({nprglCommand(), "replay", fixture, "-o", dir + "/png",
                                  "--video", video, "--fps", "12", "--style", "none"},
                                 {}, 300);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("wrote 3 frames to " + video + " at 12 fps"), std::string::npos)
        << r.err;

    Decoded decoded;
    std::string error;
    ASSERT_TRUE(decode(video, decoded, error)) << error;
    EXPECT_EQ(decoded.codec, c.codec);
    ASSERT_EQ(decoded.frames.size(), 3u);
    for (size_t i = 1; i < decoded.seconds.size(); ++i) {
        EXPECT_NEAR(decoded.seconds[i] - decoded.seconds[i - 1], 1.0 / 12, 1e-3) << i;
    }
    std::vector<PngImage> pngs(3);
    for (int i = 0; i < 3; ++i) {
        ASSERT_TRUE(PngImage::read(framePng(dir + "/png", i + 1), pngs[i], error)) << error;
    }
    for (size_t i = 0; i < decoded.frames.size(); ++i) {
        const PngImage& frame = decoded.frames[i];
        ASSERT_EQ(frame.width, pngs[i].width & ~1);
        ASSERT_EQ(frame.height, pngs[i].height & ~1);
        // A lossy codec at near-transparent quality: about one level in 255 on average here
        // (4:2:0 chroma at coloured edges), where the other frames are 2.7 or more off.
        const double same = meanDifference(frame, pngs[i]);
        EXPECT_LT(same, 2.0) << "video frame " << i + 1;
        for (size_t j = 0; j < pngs.size(); ++j) {
            if (j == i) continue;
            EXPECT_LT(same, meanDifference(frame, pngs[j]))
                << "video frame " << i + 1 << " is closer to replayed frame " << j + 1;
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Codecs, Video,
                         testing::Values(VideoCase{"h264", "gears.mp4", "h264"},
                                         VideoCase{"vp9", "gears.webm", "vp9"}),
                         [](const auto& param) { return std::string(param.param.name); });

TEST(VideoOptions, ABadNameOrRateIsAUsageErrorBeforeAnyFrame)
{
    const std::string dir = freshDir("video_bad");
    const std::string fixture = std::string(NPRGL_TEST_SOURCE_DIR) + "/fixtures/glxgears.nprgl";
    ProcessResult name =
        runProcess({nprglCommand(), "replay", fixture, "--video", dir + "/gears.nosuchformat"});
    EXPECT_EQ(name.exitCode, 2) << name.err;
    EXPECT_NE(name.err.find("no video container"), std::string::npos) << name.err;
    ProcessResult rate =
        runProcess({nprglCommand(), "replay", fixture, "--video", dir + "/g.mp4", "--fps", "0"});
    EXPECT_EQ(rate.exitCode, 2) << rate.err;
    EXPECT_FALSE(fs::exists(dir + "/g.mp4"));
}
