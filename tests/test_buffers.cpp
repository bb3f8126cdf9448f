// End to end: buffer offsets are never read as client pointers. probe_arb_vbo draws from ARB
// vertex and element buffers fetched by their ARB names (as SDL games do), textured from an
// ARB pixel-unpack buffer, and, with --vao, from a vertex array object nprgl does not follow
// while its cache holds a pointer to unmapped memory. Natively, under --style none, in the
// default style and recorded then replayed, it runs to the end, and its objects stay.

#include "common/PngImage.h"
#include "tests/support/ImageCompare.h"
#include "tests/support/Process.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>

using namespace nprgl;
using namespace nprgl::test;
namespace fs = std::filesystem;

namespace {

constexpr int kFrames = 3; // the probe's
constexpr uint8_t kClear[3] = {26, 51, 77};


std::vector<std::string> probe(const std::string& mode, std::vector<std::string> extra = {})
{
    std::vector<std::string> argv = {binDir() + "/probe_arb_vbo"};
    if (!mode.empty()) argv.push_back(mode);
    argv.insert(argv.end(), extra.begin(), extra.end());
    return argv;
}

class ArbBuffers : public ::testing::TestWithParam<std::string> {};

std::string caseName(const ::testing::TestParamInfo<std::string>& info)
{
    if (info.param.empty()) return "ArbNames";
    if (info.param == "--map") return "MappedRanges";
    if (info.param == "--program") return "ArbFragmentProgram";
    return info.param == "--vao" ? "VertexArrayObject" : "PrimitiveRestart";
}

} // namespace

TEST_P(ArbBuffers, StyleNonePrintsTheNativeChecksum)
{
    ProcessResult native = runProcess(probe(GetParam()));
    ASSERT_EQ(native.exitCode, 0) << native.err;
    ASSERT_GT(coveredCount(native.out), 1000) << native.out;
    ProcessResult none = runProcess(under({nprglCommand(), "--style", "none"}, probe(GetParam())));
    ASSERT_EQ(none.exitCode, 0) << none.err;
    EXPECT_EQ(none.out, native.out);
}

TEST_P(ArbBuffers, TheDefaultStyleRunsAndKeepsTheObjects)
{
    ProcessResult native = runProcess(probe(GetParam()));
    ASSERT_EQ(native.exitCode, 0) << native.err;
    const std::string dir = freshDir("styled");
    ProcessResult full =
        runProcess(under({nprglCommand()}, probe(GetParam(), {"--save", dir + "/full.rgba"})));
    ASSERT_EQ(full.exitCode, 0) << full.err; // 139: a buffer offset was read as a pointer
    ProcessResult empty = runProcess(
        under({nprglCommand()}, probe(GetParam(), {"--empty", "--save", dir + "/empty.rgba"})));
    ASSERT_EQ(empty.exitCode, 0) << empty.err;
    EXPECT_EQ(full.err.find("nprgl: error"), std::string::npos) << full.err;
    // The styled picture with the objects differs from the styled background alone over
    // most of where the objects are natively: they are drawn, styled or as they are.
    const int changed =
        differingRgbPixels(readRgba(dir + "/full.rgba"), readRgba(dir + "/empty.rgba"));
    EXPECT_GT(changed, coveredCount(native.out) * 3 / 4) << full.err;
    if (GetParam() == "--vao" || GetParam() == "--restart") {
        // The vertex array object's (or restart-cut) draw is passed through, and said once.
        EXPECT_NE(full.err.find("nprgl: warning"), std::string::npos) << full.err;
        EXPECT_NE(full.err.find("does not follow"), std::string::npos) << full.err;
    }
}

TEST_P(ArbBuffers, RecordedAndReplayedToTheEnd)
{
    const std::string dir = freshDir("recorded"), file = dir + "/probe.nprgl";
    ProcessResult native = runProcess(probe(GetParam(), {"--save", dir + "/native.rgba"}));
    ASSERT_EQ(native.exitCode, 0) << native.err;
    ProcessResult rec =
        runProcess(under({nprglCommand(), "record", "-o", file}, probe(GetParam())));
    ASSERT_EQ(rec.exitCode, 0) << rec.err;
    ASSERT_TRUE(fs::exists(file));
    std::string replayLog;
    for (const char* style : {"none", "toon+paper+edges"}) {
        const std::string out = dir + "/" + style;
        ProcessResult p = runProcess({nprglCommand(), "replay", "--style", style, file, "-o", out});
        ASSERT_EQ(p.exitCode, 0) << style << ": " << p.err;
        ASSERT_TRUE(fs::exists(framePng(out, kFrames))) << style << ": " << p.err;
        replayLog += p.err;
    }
    // Unstyled, the replayed last frame has what the program drew from its ARB buffers. (A
    // draw through a vertex array object, or with primitive restart, is not recorded: that
    // picture lacks the ring, and the capture says so.)
    PngImage image;
    std::string error;
    ASSERT_TRUE(PngImage::read(framePng(dir + "/none", kFrames), image, error)) << error;
    int drawn = 0;
    for (size_t i = 0; i + 3 < image.rgba.size(); i += 4) {
        drawn += image.rgba[i] != kClear[0] || image.rgba[i + 1] != kClear[1] ||
                 image.rgba[i + 2] != kClear[2];
    }
    const int expected = coveredCount(native.out);
    const bool complete = GetParam() != "--vao" && GetParam() != "--restart";
    if (complete) {
        // Everything was captured: the replay is the program's own picture (rows flipped:
        // the probe saves OSMesa's buffer bottom row first).
        image.flipRows();
        EXPECT_EQ(differingRgbPixels(image.rgba, readRgba(dir + "/native.rgba")), 0);
        EXPECT_GT(drawn, expected * 9 / 10);
        EXPECT_EQ(replayLog.find("not captured"), std::string::npos) << replayLog;
    } else {
        EXPECT_GT(drawn, expected / 5); // the cube
        ProcessResult info = runProcess({nprglCommand(), "info", file});
        ASSERT_EQ(info.exitCode, 0) << info.err;
        EXPECT_EQ(info.out.find("(none)"), std::string::npos) << info.out;
        // The draw left out, and every frame it is missing from, named by info and replay.
        const std::string frames = "1-" + std::to_string(kFrames);
        EXPECT_NE(info.out.find("glDrawElements  (frames " + frames + ")"), std::string::npos)
            << info.out;
        EXPECT_NE(replayLog.find("calls to glDrawElements (not captured), in frames " + frames),
                  std::string::npos)
            << replayLog;
    }
}

INSTANTIATE_TEST_SUITE_P(Probe, ArbBuffers,
                         ::testing::Values("", "--vao", "--restart", "--map", "--program"),
                         caseName);
