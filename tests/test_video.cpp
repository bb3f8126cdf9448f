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

namespace {

// The codec's loss on the toon cube's black outlines, mean levels in 255 (see below).
constexpr double kLiveLoss = 3.0;

// probe_hotkeys (a cube turning a step each frame) under `nprgl run --video` with the
// screenshots of every frame beside it; `keys`: its --press options.
ProcessResult runLive(const std::string& dir, const std::string& video, int frames,
                      const std::vector<std::string>& keys, const std::vector<std::string>& extra)
{
    std::vector<std::string> command = {nprglCommand(), "run", "--style", "toon+edges",
                                        "--video", video};
    command.insert(command.end(), extra.begin(), extra.end());
    command.insert(command.end(), {"--", binDir() + "/probe_hotkeys", "--frames",
                                   std::to_string(frames)});
    command.insert(command.end(), keys.begin(), keys.end());
    return runProcess(command,
                      {{"NPRGL_SCREENSHOT", "frames=1-" + std::to_string(frames) + ";dir=" + dir},
                       {"NPRGL_CONFIG_FILE", ""},
                       {"XDG_CONFIG_HOME", dir + "/home"}},
                      300);
}

std::vector<PngImage> liveFrames(const std::string& dir, int frames)
{
    std::vector<PngImage> shots(static_cast<size_t>(frames));
    std::string error;
    for (int i = 0; i < frames; ++i) {
        EXPECT_TRUE(PngImage::read(dir + "/probe_hotkeys_" + std::to_string(i + 1) + ".png",
                                   shots[size_t(i)], error))
            << error;
    }
    return shots;
}

// The program frame (from 1) each video frame is nearest to, and how near.
std::vector<std::pair<int, double>> nearest(const Decoded& decoded,
                                            const std::vector<PngImage>& shots)
{
    std::vector<std::pair<int, double>> found;
    for (const PngImage& frame : decoded.frames) {
        std::pair<int, double> best{0, 1e9};
        for (size_t j = 0; j < shots.size(); ++j) {
            const double d = meanDifference(frame, shots[j]);
            if (d < best.second) best = {int(j) + 1, d};
        }
        found.push_back(best);
    }
    return found;
}

} // namespace

// A live run's video holds the frames the program showed, in order: each video frame is,
// within the codec's loss, one of the program's frames (its screenshot), and never an
// earlier one than the video frame before it. The loss is about 2 levels in 255 on the
// cube's outlines (kLiveLoss); the frame one step away is 3.2 off, ten steps away 19.
TEST(LiveVideo, HoldsTheProgramsFramesInOrder)
{
    const std::string dir = freshDir("video_live");
    const std::string video = dir + "/live.mp4";
    const ProcessResult r = runLive(dir, video, 30, {}, {});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.out, "ok\n");
    EXPECT_NE(r.err.find("video " + video + ": "), std::string::npos) << r.err;
    Decoded decoded;
    std::string error;
    ASSERT_TRUE(decode(video, decoded, error)) << error;
    EXPECT_EQ(decoded.codec, "h264");
    ASSERT_GE(decoded.frames.size(), 1u);
    const std::vector<PngImage> shots = liveFrames(dir, 30);
    int previous = 0;
    for (const auto& [frame, difference] : nearest(decoded, shots)) {
        EXPECT_LT(difference, kLiveLoss) << "nearest program frame " << frame;
        EXPECT_GE(frame, previous);
        previous = frame;
    }
    EXPECT_EQ(nearest(decoded, shots).front().first, 1);
}

// The video key (Shift_R+F6) pressed at frame 10 stops the recording, pressed at 20 starts
// the next one into live-2.mp4: the first file holds frames before 10, the second frames
// from 20 on.
TEST(LiveVideo, TheVideoKeyStopsItAndStartsTheNextFile)
{
    const std::string dir = freshDir("video_live_key");
    const std::string video = dir + "/live.mp4";
    const ProcessResult r = runLive(
        dir, video, 30, {"--press", "10", "Shift_R+F6", "--press", "20", "Shift_R+F6"}, {});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("recording 1 stopped"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("recording 2 started"), std::string::npos) << r.err;
    const std::vector<PngImage> shots = liveFrames(dir, 30);
    Decoded first, second;
    std::string error;
    ASSERT_TRUE(decode(video, first, error)) << error;
    ASSERT_TRUE(decode(dir + "/live-2.mp4", second, error)) << error;
    ASSERT_GE(first.frames.size(), 1u);
    ASSERT_GE(second.frames.size(), 1u);
    for (const auto& [frame, difference] : nearest(first, shots)) {
        EXPECT_LT(frame, 10);
        EXPECT_LT(difference, kLiveLoss);
    }
    for (const auto& [frame, difference] : nearest(second, shots)) {
        EXPECT_GE(frame, 20);
        EXPECT_LT(difference, kLiveLoss);
    }
    EXPECT_FALSE(fs::exists(dir + "/live-3.mp4"));
}

// --video-on-key: nothing is recorded until the key; without a press, no file and a line
// that says why.
TEST(LiveVideo, OnKeyWaitsForTheKey)
{
    const std::string dir = freshDir("video_live_wait");
    const std::string video = dir + "/live.mp4";
    const ProcessResult idle = runLive(dir, video, 6, {}, {"--video-on-key"});
    ASSERT_EQ(idle.exitCode, 0) << idle.err;
    EXPECT_FALSE(fs::exists(video));
    EXPECT_NE(idle.err.find("no frame was recorded"), std::string::npos) << idle.err;
    const ProcessResult keyed =
        runLive(dir, video, 12, {"--press", "6", "Shift_R+F6"}, {"--video-on-key"});
    ASSERT_EQ(keyed.exitCode, 0) << keyed.err;
    Decoded decoded;
    std::string error;
    ASSERT_TRUE(decode(video, decoded, error)) << error;
    ASSERT_GE(decoded.frames.size(), 1u);
    for (const auto& [frame, difference] : nearest(decoded, liveFrames(dir, 12))) {
        EXPECT_GE(frame, 6);
        EXPECT_LT(difference, kLiveLoss);
    }
}

// Frames are placed on the video's clock by the time they carry: frames 40 ms apart at 50
// fps fill two video frames each (the last one once), each video frame the grey of the
// program frame shown at its time.
TEST(LiveVideo, FramesArePlacedOnTheClockTheyCarry)
{
    const std::string dir = freshDir("video_live_clock");
    const std::string video = dir + "/clock.mkv";
    const ProcessResult r =
        runProcess({nprglCommand(), "run", "--video", video, "--fps", "50", "--",
                    binDir() + "/probe_video_feed", "--good", "4"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    Decoded decoded;
    std::string error;
    ASSERT_TRUE(decode(video, decoded, error)) << error;
    ASSERT_EQ(decoded.frames.size(), 7u) << r.err;
    const int expected[] = {40, 40, 80, 80, 120, 120, 160};
    for (size_t i = 0; i < decoded.frames.size(); ++i) {
        const PngImage& frame = decoded.frames[i];
        EXPECT_NEAR(frame.rgba[(size_t(16) * frame.width + 16) * 4], expected[i], 3) << i;
    }
    EXPECT_NE(r.err.find("(7 frames) from 4 frames of process"), std::string::npos) << r.err;
}

// What comes over the socket is checked: a stranger's hello, a header that is not one, a
// frame larger than any video and one cut short are each said (with where) and end that
// feed; the run itself is the program's, exit status 0, and no file claims frames it lacks.
TEST(LiveVideo, ADamagedFeedIsSaidAndEndsThatFeed)
{
    const std::string dir = freshDir("video_live_damaged");
    struct Case {
        const char* mode;
        const char* said;
        bool file;
    };
    const Case cases[] = {
        {"--not-nprgl", "a connection that is not nprgl's library", false},
        {"--bad-magic", "a damaged frame message from process", true},
        {"--huge", "a damaged frame message from process", false},
        {"--truncated", "ended in the middle of frame 1", false},
    };
    for (const Case& c : cases) {
        const std::string video = dir + "/" + std::string(c.mode + 2) + ".mp4";
        const ProcessResult r = runProcess({nprglCommand(), "run", "--video", video, "--",
                                            binDir() + "/probe_video_feed", c.mode});
        EXPECT_EQ(r.exitCode, 0) << c.mode << "\n" << r.err;
        EXPECT_NE(r.err.find(c.said), std::string::npos) << c.mode << "\n" << r.err;
        EXPECT_EQ(fs::exists(video), c.file) << c.mode << "\n" << r.err;
    }
}

// A name no container takes, a bad rate, and --fps or --video-on-key without --video are
// usage errors before the program starts.
TEST(LiveVideo, BadOptionsAreUsageErrorsBeforeTheProgram)
{
    const std::string dir = freshDir("video_live_options");
    const std::string marker = dir + "/ran";
    const std::vector<std::string> program = {"--", "touch", marker};
    const std::vector<std::vector<std::string>> bad = {
        {"--video", dir + "/v.nosuchformat"},
        {"--video", dir + "/v.mp4", "--fps", "0"},
        {"--fps", "25"},
        {"--video-on-key"},
    };
    for (std::vector<std::string> options : bad) {
        options.insert(options.begin(), {nprglCommand(), "run"});
        options.insert(options.end(), program.begin(), program.end());
        const ProcessResult r = runProcess(options);
        EXPECT_EQ(r.exitCode, 2) << options[2] << "\n" << r.err;
        EXPECT_FALSE(fs::exists(marker)) << options[2];
    }
}
