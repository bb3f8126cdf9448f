// End to end: small programs on freeglut, SDL2 and GLFW (probe_toolkit.cpp) run under nprgl in
// the default style as they run natively: they exit on their own with status 0, and their
// cube is styled (the frame differs from native) and still there.

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

std::vector<std::string> under(std::vector<std::string> nprgl, const std::vector<std::string>& p)
{
    nprgl.push_back("--");
    nprgl.insert(nprgl.end(), p.begin(), p.end());
    return nprgl;
}

int covered(const std::string& out)
{
    const size_t at = out.find("covered ");
    return at == std::string::npos ? -1 : std::atoi(out.c_str() + at + 8);
}

std::vector<uint8_t> readBytes(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

int differingPixels(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b)
{
    if (a.size() != b.size() || a.empty()) return -1;
    int n = 0;
    for (size_t i = 0; i + 3 < a.size(); i += 4) {
        n += a[i] != b[i] || a[i + 1] != b[i + 1] || a[i + 2] != b[i + 2];
    }
    return n;
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
    ASSERT_GT(covered(native.out), 2000) << native.out;

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
    const std::vector<uint8_t> frame = readBytes(dir + "/styled.rgba");
    EXPECT_GT(differingPixels(frame, readBytes(dir + "/native.rgba")), covered(native.out) / 2);
    EXPECT_GT(differingPixels(frame, readBytes(dir + "/empty.rgba")),
              covered(native.out) * 3 / 4);
}

INSTANTIATE_TEST_SUITE_P(Probe, Toolkit, ::testing::Values("glut", "sdl2", "glfw"),
                         [](const auto& param) { return param.param; });
