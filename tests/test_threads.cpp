// End to end: a program whose two threads draw into two GLX windows at the same time, each
// with its own context, styled (nprgl's default style) and recorded. scripts/test.sh runs
// these tests again with a ThreadSanitizer build of the library preloaded.

#include "common/PngImage.h"
#include "tests/support/ImageCompare.h"
#include "tests/support/Process.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <map>

using namespace nprgl;
using namespace nprgl::test;
namespace fs = std::filesystem;

namespace {

constexpr int kFrames = 4;

std::string probe() { return binDir() + "/probe_glx_threads"; }

void requireDisplay()
{
    const char* d = std::getenv("DISPLAY");
    ASSERT_TRUE(d && *d) << "run through scripts/test.sh (Xvfb)";
}

// Share of pixels unlike the top-left one (the background): the shape is drawn.
double drawnFraction(const PngImage& image)
{
    size_t drawn = 0;
    for (size_t i = 0; i < image.rgba.size(); i += 4) {
        for (int c = 0; c < 3; ++c) {
            if (std::abs(image.rgba[i + c] - image.rgba[c]) > 8) {
                ++drawn;
                break;
            }
        }
    }
    return image.rgba.empty() ? 0.0 : double(drawn) / double(image.rgba.size() / 4);
}

PngImage readPng(const std::string& path)
{
    PngImage image;
    std::string error;
    EXPECT_TRUE(PngImage::read(path, image, error)) << error;
    return image;
}

// Runs the probe natively: its two last frames, thread0.png and thread1.png.
std::string nativeFrames()
{
    std::string dir = freshDir("threads_native");
    ProcessResult r = runProcess({probe(), std::to_string(kFrames), dir});
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.out, "ok\n");
    return dir;
}

} // namespace

TEST(GlxThreads, BothThreadsAreStyledAtOnce)
{
    requireDisplay();
    std::string native = nativeFrames();
    std::string styled = freshDir("threads_styled");
    ProcessResult r = runProcess({nprglCommand(), "--", probe(), std::to_string(kFrames), styled});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.out, "ok\n");
    EXPECT_EQ(r.err.find("ThreadSanitizer"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("nprgl: error"), std::string::npos) << r.err;
    for (const char* name : {"/thread0.png", "/thread1.png"}) {
        PngImage plain = readPng(native + name), nice = readPng(styled + name);
        ASSERT_EQ(plain.width, 128);
        ASSERT_EQ(nice.width, 128);
        // The shape covers a good part of the window in both pictures.
        EXPECT_GT(drawnFraction(plain), 0.15) << name;
        EXPECT_GT(drawnFraction(nice), 0.15) << styled + name;
        ImageDiff diff = compareImages(native + name, styled + name, 16);
        ASSERT_TRUE(diff.comparable) << diff.error;
        // Paper and toon shading change nearly every pixel; a quarter is a safe floor.
        EXPECT_GT(diff.differingPixels, size_t(128 * 96 / 4)) << styled + name;
    }
}

TEST(GlxThreads, TheRecordingHasOneStreamPerContextAndBothReplay)
{
    requireDisplay();
    std::string native = nativeFrames();
    std::string dir = freshDir("threads_record"), file = dir + "/t.nprgl";
    ProcessResult r = runProcess(
        {nprglCommand(), "record", "-o", file, "--", probe(), std::to_string(kFrames), dir});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.err.find("ThreadSanitizer"), std::string::npos) << r.err;
    ProcessResult i = runProcess({nprglCommand(), "info", file});
    ASSERT_EQ(i.exitCode, 0) << i.err;
    EXPECT_NE(i.out.find("(context 1: 4)  (context 2: 4)"), std::string::npos) << i.out;
    EXPECT_EQ(i.out.find("recovered"), std::string::npos) << i.out;
    // Which thread made its context current first is up to the scheduler: each replayed
    // context must be one thread's native frame, pixel for pixel, and they must differ.
    int matched[2] = {0, 0};
    for (int ctx : {1, 2}) {
        std::string out = dir + "/ctx" + std::to_string(ctx);
        ProcessResult p = runProcess({nprglCommand(), "replay", "--style", "none", file,
                                      "--context", std::to_string(ctx), "-o", out});
        ASSERT_EQ(p.exitCode, 0) << p.err;
        ASSERT_TRUE(fs::exists(framePng(out, kFrames))) << p.err;
        EXPECT_FALSE(fs::exists(framePng(out, kFrames + 1)));
        for (int t : {0, 1}) {
            ImageDiff diff = compareImages(native + "/thread" + std::to_string(t) + ".png",
                                           framePng(out, kFrames));
            ASSERT_TRUE(diff.comparable) << diff.error;
            matched[t] += diff.differingPixels == 0;
        }
    }
    EXPECT_EQ(matched[0], 1);
    EXPECT_EQ(matched[1], 1);
}

// A program that exits while another thread has its context current (a render thread it never
// stopped, here in the middle of a frame) logs that context's counts as they stood at its last
// frame end, said so, and not the counts that thread may be changing; the context no thread
// holds any more logs its counts as they stand. Each once, and the program's exit is its own.
TEST(GlxThreads, AtExitAContextCurrentOnAnotherThreadLogsItsLastFrameEndsCounts)
{
    requireDisplay();
    const std::string dir = freshDir("threads_exit_mid_frame");
    ProcessResult r = runProcess(
        {nprglCommand(), "--", probe(), std::to_string(kFrames), dir, "exit-mid-frame"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.out, "ok\n");
    std::vector<std::string> lines;
    for (size_t at = r.err.find("3D polygon draws: "); at != std::string::npos;
         at = r.err.find("3D polygon draws: ", at + 1)) {
        lines.push_back(r.err.substr(at, r.err.find('\n', at) - at));
    }
    ASSERT_EQ(lines.size(), 2u) << r.err;
    const std::string kElsewhere = "(to its last frame end: it is current on another thread)";
    const size_t elsewhere = std::count_if(lines.begin(), lines.end(), [&](const auto& l) {
        return l.find(kElsewhere) != std::string::npos;
    });
    EXPECT_EQ(elsewhere, 1u) << r.err;
    // Its frames' draws, one a frame (the box), and not the frame it stopped in.
    EXPECT_NE(r.err.find("3D polygon draws: " + std::to_string(kFrames) + " styled"),
              std::string::npos)
        << r.err;
}
