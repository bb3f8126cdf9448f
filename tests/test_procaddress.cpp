// End to end: a program that reaches GL's extensions only through ARB/EXT names fetched with
// GetProcAddress (probe_getproc: ARB vertex buffers, ARB multitexture with a lightmap, EXT
// framebuffer render-to-texture, EXT compiled vertex arrays, ARB shader objects), on OSMesa,
// GLX (glXCreateContextAttribsARB, compatibility profile, glXMakeContextCurrent) and an EGL
// pbuffer. Under --style none and recorded then replayed it is the native picture, pixel for
// pixel; under every shading style each of its five objects is still in the frame.

#include "common/PngImage.h"
#include "tests/support/ImageCompare.h"
#include "tests/support/Process.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdlib>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

using namespace nprgl;
using namespace nprgl::test;
namespace fs = std::filesystem;

namespace {

constexpr int kWidth = 240, kHeight = 160, kFrames = 3; // the probe's
constexpr int kObjects = 5; // in cells 0-4 of its 3x2 grid

std::vector<std::string> probe(const std::string& mode, std::vector<std::string> extra = {})
{
    std::vector<std::string> argv = {binDir() + "/probe_getproc_" + mode};
    argv.insert(argv.end(), extra.begin(), extra.end());
    return argv;
}

// The probe's "cells a b c d e f": pixels not of the clear colour per cell of its grid.
std::array<int, 6> cells(const std::string& out)
{
    std::array<int, 6> c{-1, -1, -1, -1, -1, -1};
    const size_t at = out.find("cells ");
    if (at == std::string::npos) return c;
    std::istringstream in(out.substr(at + 6));
    for (int& v : c) in >> v;
    return c;
}

// Pixels whose RGB differ by more than `tolerance` between two frames of the probe's size
// (bottom row first), per cell.
std::array<int, 6> differingPerCell(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b,
                                    int tolerance = 0)
{
    auto apart = [tolerance](uint8_t x, uint8_t y) {
        return std::abs(int(x) - int(y)) > tolerance;
    };
    std::array<int, 6> n{};
    if (a.size() != b.size() || a.size() != size_t(kWidth) * kHeight * 4) return {-1};
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            const size_t i = (size_t(y) * kWidth + x) * 4;
            const bool differs =
                apart(a[i], b[i]) || apart(a[i + 1], b[i + 1]) || apart(a[i + 2], b[i + 2]);
            n[(y < kHeight / 2 ? 3 : 0) + x * 3 / kWidth] += differs;
        }
    }
    return n;
}

class ProcAddress : public ::testing::TestWithParam<std::string> {};

} // namespace

TEST_P(ProcAddress, NativeDrawsEveryObject)
{
    ProcessResult native = runProcess(probe(GetParam()));
    ASSERT_EQ(native.exitCode, 0) << native.err;
    const std::array<int, 6> c = cells(native.out);
    for (int i = 0; i < kObjects; ++i) EXPECT_GT(c[size_t(i)], 800) << "cell " << i;
    EXPECT_NE(native.out.find("error 0x0"), std::string::npos) << native.out;
}

TEST_P(ProcAddress, StyleNoneIsTheNativePicture)
{
    ProcessResult native = runProcess(probe(GetParam()));
    ASSERT_EQ(native.exitCode, 0) << native.err;
    ProcessResult none = runProcess(under({nprglCommand(), "--style", "none"}, probe(GetParam())));
    ASSERT_EQ(none.exitCode, 0) << none.err;
    EXPECT_EQ(none.out, native.out); // checksum, cells and GL error
}

TEST_P(ProcAddress, RecordedAndReplayedIsTheNativePicture)
{
    const std::string dir = freshDir("procaddress"), file = dir + "/probe.nprgl";
    ProcessResult native = runProcess(probe(GetParam(), {"--save", dir + "/native.rgba"}));
    ASSERT_EQ(native.exitCode, 0) << native.err;
    ProcessResult rec = runProcess(
        under({nprglCommand(), "record", "--style", "none", "-o", file}, probe(GetParam())));
    ASSERT_EQ(rec.exitCode, 0) << rec.err;
    EXPECT_NE(rec.err.find("not captured: nothing"), std::string::npos) << rec.err;
    ProcessResult info = runProcess({nprglCommand(), "info", file});
    ASSERT_EQ(info.exitCode, 0) << info.err;
    // The capture knows its size (an EGL pbuffer's too) and lacks nothing.
    EXPECT_NE(info.out.find("size:        " + std::to_string(kWidth) + "x" +
                            std::to_string(kHeight)),
              std::string::npos)
        << info.out;
    EXPECT_NE(info.out.find("not captured:\n  (none)"), std::string::npos) << info.out;

    const std::string out = dir + "/replay";
    ProcessResult replay =
        runProcess({nprglCommand(), "replay", "--style", "none", file, "-o", out});
    ASSERT_EQ(replay.exitCode, 0) << replay.err;
    PngImage image;
    std::string error;
    ASSERT_TRUE(PngImage::read(framePng(out, kFrames), image, error)) << error;
    image.flipRows(); // the probe saves its frame bottom row first
    // The replay renders on OSMesa. Mesa's EGL pbuffer rounds some lit and blended colours
    // one step apart from OSMesa's buffer (native EGL and native OSMesa frames differ by at
    // most 1 in a channel, in about 2,800 channel values); GLX and OSMesa round alike.
    const int tolerance = GetParam() == "egl" ? 1 : 0;
    const std::array<int, 6> differing =
        differingPerCell(image.rgba, readRgba(dir + "/native.rgba"), tolerance);
    EXPECT_EQ(differing, (std::array<int, 6>{})) << "pixels differing per cell";
}

TEST_P(ProcAddress, EveryShadingStyleKeepsEveryObject)
{
    const std::string dir = freshDir("procaddress-styles");
    ProcessResult native = runProcess(probe(GetParam()));
    ASSERT_EQ(native.exitCode, 0) << native.err;
    const std::array<int, 6> nativeCells = cells(native.out);
    for (const char* style : {"toon", "textured", "halftone", "toon+paper+edges"}) {
        const std::string full = dir + "/" + style + ".rgba";
        const std::string empty = dir + "/" + style + "-0.rgba";
        ProcessResult a = runProcess(
            under({nprglCommand(), "--style", style}, probe(GetParam(), {"--save", full})));
        ASSERT_EQ(a.exitCode, 0) << style << ": " << a.err;
        ProcessResult b = runProcess(under({nprglCommand(), "--style", style},
                                           probe(GetParam(), {"--empty", "--save", empty})));
        ASSERT_EQ(b.exitCode, 0) << style << ": " << b.err;
        EXPECT_EQ(a.err.find("nprgl: error"), std::string::npos) << style << ": " << a.err;
        // Against the same style's empty frame (its background), each object's cell changed
        // over most of where the object is natively: drawn, styled or as it was.
        const std::array<int, 6> changed = differingPerCell(readRgba(full), readRgba(empty));
        for (int i = 0; i < kObjects; ++i) {
            EXPECT_GT(changed[size_t(i)], nativeCells[size_t(i)] * 3 / 4)
                << style << ", cell " << i;
        }
    }
}

// Cell 4's cube is coloured by its own shader program (a uniform tint): a style cannot know
// what that program draws, so the draw is left as it is, not shaded in the current glColor.
TEST_P(ProcAddress, DrawsWithTheProgramsOwnShadersAreLeftAsTheyAre)
{
    const std::string dir = freshDir("procaddress-shaders");
    ProcessResult native = runProcess(probe(GetParam(), {"--save", dir + "/native.rgba"}));
    ASSERT_EQ(native.exitCode, 0) << native.err;
    ProcessResult toon = runProcess(under({nprglCommand(), "--style", "toon"},
                                          probe(GetParam(), {"--save", dir + "/toon.rgba"})));
    ASSERT_EQ(toon.exitCode, 0) << toon.err;
    EXPECT_NE(toon.err.find("drawn with the program's own shaders are left"), std::string::npos)
        << toon.err;
    // And counted at exit: one such draw per frame, the only one left. The lightmapped quad
    // of cell 1 is styled with its detail texture, lit by its lightmap.
    EXPECT_NE(toon.err.find("left as the program drew them (the program's own shaders " +
                            std::to_string(kFrames) + ")"),
              std::string::npos)
        << toon.err;
    EXPECT_NE(toon.err.find("lightmaps on unit 1 give the shading styles their light"),
              std::string::npos)
        << toon.err;
    const std::array<int, 6> differing =
        differingPerCell(readRgba(dir + "/toon.rgba"), readRgba(dir + "/native.rgba"));
    EXPECT_EQ(differing[4], 0);
    EXPECT_GT(differing[0], 100); // while the cube of cell 0 is styled
    EXPECT_GT(differing[1], 100); // and the lightmapped quad of cell 1

    // The coverage style shows it left: red alone where the cube was (the fixed pipeline's
    // fog that tints the other left draws red is no part of a shader's picture).
    ProcessResult coverage =
        runProcess(under({nprglCommand(), "--style", "coverage"},
                         probe(GetParam(), {"--save", dir + "/coverage.rgba"})));
    ASSERT_EQ(coverage.exitCode, 0) << coverage.err;
    const std::vector<uint8_t> tinted = readRgba(dir + "/coverage.rgba");
    const std::vector<uint8_t> nativeImage = readRgba(dir + "/native.rgba");
    const std::array<int, 6> nativeCells = cells(native.out);
    ASSERT_EQ(tinted.size(), size_t(kWidth) * kHeight * 4);
    int red = 0;
    for (int y = 0; y < kHeight / 2; ++y) { // cell 4 (rows bottom first)
        for (int x = kWidth / 3; x < 2 * kWidth / 3; ++x) {
            const size_t i = (size_t(y) * kWidth + x) * 4;
            const bool object = nativeImage[i] != tinted[i] || nativeImage[i + 1] != tinted[i + 1];
            red += object && tinted[i] > 20 && tinted[i + 1] == 0 && tinted[i + 2] == 0;
        }
    }
    EXPECT_GT(red, nativeCells[4] * 3 / 4) << "of " << nativeCells[4];
}

INSTANTIATE_TEST_SUITE_P(Context, ProcAddress, ::testing::Values("osmesa", "glx", "egl"),
                         [](const auto& param) { return param.param; });
