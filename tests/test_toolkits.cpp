// End to end: small programs on freeglut, SDL2 and GLFW (probe_toolkit.cpp) run under nprgl in
// the default style as they run natively: they exit on their own with status 0, and their
// cube is styled (the frame differs from native) and still there.

#include "tests/support/ImageCompare.h"
#include "tests/support/Process.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>

using namespace nprgl::test;
namespace fs = std::filesystem;

namespace {

std::vector<std::string> probe(const std::string& kit, std::vector<std::string> extra = {})
{
    std::vector<std::string> argv = {binDir() + "/probe_" + kit};
    argv.insert(argv.end(), extra.begin(), extra.end());
    return argv;
}

class Toolkit : public ::testing::TestWithParam<std::string> {};

} // namespace

TEST_P(Toolkit, RunsStyledToItsOwnEnd)
{
    if (!fs::exists(probe(GetParam())[0])) {
        GTEST_SKIP() << "probe_" << GetParam() << " was not built (toolkit not installed)";
    }
    const std::string dir = freshDir("toolkit-" + GetParam());
    ProcessResult native = runProcess(probe(GetParam(), {"--save", dir + "/native.rgba"}));
    ASSERT_EQ(native.exitCode, 0) << native.err;
    ASSERT_GT(coveredCount(native.out), 2000) << native.out;

    // Passthrough first: the same picture.
    ProcessResult none = runProcess(under({nprglCommand(), "--style", "none"}, probe(GetParam())));
    ASSERT_EQ(none.exitCode, 0) << none.err;
    EXPECT_EQ(none.out, native.out);

    ProcessResult styled = runProcess(
        under({nprglCommand()}, probe(GetParam(), {"--save", dir + "/styled.rgba"})));
    ASSERT_EQ(styled.exitCode, 0) << styled.err;
    ProcessResult empty = runProcess(
        under({nprglCommand()}, probe(GetParam(), {"--empty", "--save", dir + "/empty.rgba"})));
    ASSERT_EQ(empty.exitCode, 0) << empty.err;
    EXPECT_EQ(styled.err.find("nprgl: error"), std::string::npos) << styled.err;
    EXPECT_NE(styled.err.find("style toon+paper+edges"), std::string::npos) << styled.err;
    // Styled: not the native picture; the cube there: the styled frame differs from the
    // styled background alone over most of where the cube is natively.
    const std::vector<uint8_t> frame = readRgba(dir + "/styled.rgba");
    EXPECT_GT(differingRgbPixels(frame, readRgba(dir + "/native.rgba")), coveredCount(native.out) / 2);
    EXPECT_GT(differingRgbPixels(frame, readRgba(dir + "/empty.rgba")),
              coveredCount(native.out) * 3 / 4);
}

// The overlay opens over a toolkit's window as over a bare GLX one (overlay=open from the
// start): the same run with and without it differs over most of the small window.
TEST_P(Toolkit, ShowsTheOverlay)
{
    if (!fs::exists(probe(GetParam())[0])) {
        GTEST_SKIP() << "probe_" << GetParam() << " was not built (toolkit not installed)";
    }
    std::string dirs[2];
    for (int open = 0; open < 2; ++open) {
        dirs[open] = freshDir("toolkit-overlay-" + GetParam());
        ProcessResult r = runProcess(
            under({nprglCommand(), "--screenshot", "frames=4;dir=" + dirs[open]},
                  probe(GetParam())),
            {{"NPRGL_OVERLAY", open ? "open" : "closed"},
             {"XDG_CONFIG_HOME", freshDir("toolkit-overlay-home")}, {"NPRGL_CONFIG_FILE", ""}});
        ASSERT_EQ(r.exitCode, 0) << r.err;
        EXPECT_EQ(r.err.find("nprgl: overlay open") != std::string::npos, open == 1) << r.err;
    }
    // SDL2 draws with its second context: the picture is named after it (..._ctx2_4.png).
    std::string shot;
    for (const auto& entry : fs::directory_iterator(dirs[0])) shot = entry.path().filename();
    ASSERT_FALSE(shot.empty()) << "no screenshot in " << dirs[0];
    ImageDiff diff = compareImages(dirs[0] + "/" + shot, dirs[1] + "/" + shot, 6);
    ASSERT_TRUE(diff.comparable) << diff.error;
    EXPECT_GT(diff.differingPixels, 200u * 150u / 3);
}

INSTANTIATE_TEST_SUITE_P(Probe, Toolkit, ::testing::Values("glut", "sdl2", "glfw"),
                         [](const auto& param) { return param.param; });
