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

INSTANTIATE_TEST_SUITE_P(Probe, Toolkit, ::testing::Values("glut", "sdl2", "glfw"),
                         [](const auto& param) { return param.param; });
