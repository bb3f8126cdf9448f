// End to end: demo_character's three animation techniques on assimp-testmodels' files, under
// `nprgl --style none` and through record and replay, plus its error for a missing model.

#include "common/PngImage.h"
#include "tests/support/ImageCompare.h"
#include "tests/support/Process.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

using namespace nprgl;
using namespace nprgl::test;
namespace fs = std::filesystem;

namespace {

constexpr int kFrames = 4;

std::string demoCharacter() { return binDir() + "/demo_character"; }

std::string livePng(const std::string& dir, int frame)
{
    return dir + "/character_" + std::to_string(frame) + ".png";
}

std::string replayPng(const std::string& dir, int frame)
{
    char name[32];
    std::snprintf(name, sizeof name, "/frame_%010d.png", frame);
    return dir + name;
}

struct CharacterCase {
    std::string name;
    std::string model; // from Debian's assimp-testmodels
    std::vector<std::string> args;
};

void PrintTo(const CharacterCase& c, std::ostream* os) { *os << c.name; }

std::string caseName(const ::testing::TestParamInfo<CharacterCase>& info)
{
    return info.param.name;
}

class Character : public ::testing::TestWithParam<CharacterCase> {
protected:
    void SetUp() override
    {
        if (!fs::exists(GetParam().model)) {
            GTEST_SKIP() << GetParam().model << " is missing: install assimp-testmodels";
        }
    }

    std::vector<std::string> demoArgs(const std::string& saveDir) const
    {
        std::vector<std::string> args = {demoCharacter(), "--model", GetParam().model,
                                         "--offscreen", "--frames", std::to_string(kFrames),
                                         "--size", "160x120", "--save-dir", saveDir};
        args.insert(args.end(), GetParam().args.begin(), GetParam().args.end());
        return args;
    }
};

} // namespace

TEST_P(Character, StyleNoneIsPixelIdenticalToNative)
{
    std::string nativeDir = freshDir("native"), shimDir = freshDir("shim");
    ProcessResult a = runProcess(demoArgs(nativeDir));
    ASSERT_EQ(a.exitCode, 0) << a.err;
    std::vector<std::string> shimmed = {nprglCommand(), "--style", "none", "--"};
    std::vector<std::string> args = demoArgs(shimDir);
    shimmed.insert(shimmed.end(), args.begin(), args.end());
    ProcessResult b = runProcess(shimmed);
    ASSERT_EQ(b.exitCode, 0) << b.err;
    EXPECT_EQ(b.err.find("nprgl: error"), std::string::npos) << b.err;

    for (int frame = 1; frame <= kFrames; ++frame) {
        ImageDiff diff = compareImages(livePng(nativeDir, frame), livePng(shimDir, frame));
        ASSERT_TRUE(diff.comparable) << diff.error;
        EXPECT_EQ(diff.differingPixels, 0u) << "frame " << frame;
        PngImage image;
        std::string error;
        ASSERT_TRUE(PngImage::read(livePng(nativeDir, frame), image, error)) << error;
        EXPECT_GT(coveredFraction(image), 0.02) << "frame " << frame << " is nearly empty";
    }
    // The character moves: the last frame is not the first.
    ImageDiff motion = compareImages(livePng(nativeDir, 1), livePng(nativeDir, kFrames));
    ASSERT_TRUE(motion.comparable) << motion.error;
    EXPECT_GT(motion.differingPixels, 0u);
}

TEST_P(Character, ReplayIsPixelIdenticalToTheLiveFrames)
{
    std::string dir = freshDir("rec"), live = dir + "/live", replay = dir + "/replay";
    std::string file = dir + "/capture.nprgl";
    std::vector<std::string> cmd = {nprglCommand(), "record", "--style", "none", "-o", file, "--"};
    std::vector<std::string> args = demoArgs(live);
    cmd.insert(cmd.end(), args.begin(), args.end());
    ProcessResult r = runProcess(cmd);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    ProcessResult p = runProcess({nprglCommand(), "replay", "--style", "none", file, "-o", replay});
    ASSERT_EQ(p.exitCode, 0) << p.err;
    for (int frame = 1; frame <= kFrames; ++frame) {
        ImageDiff diff = compareImages(livePng(live, frame), replayPng(replay, frame));
        ASSERT_TRUE(diff.comparable) << diff.error;
        EXPECT_EQ(diff.differingPixels, 0u) << "frame " << frame;
    }
    EXPECT_FALSE(fs::exists(replayPng(replay, kFrames + 1)));
}

INSTANTIATE_TEST_SUITE_P(
    Techniques, Character,
    ::testing::Values(
        CharacterCase{"morph", "/usr/share/assimp/models/MD2/sydney.md2", {}},
        CharacterCase{"morph_immediate", "/usr/share/assimp/models/MD2/faerie.md2",
                      {"--immediate"}},
        CharacterCase{"skin", "/usr/share/assimp/models/X/Testwuson.X", {}},
        CharacterCase{"skin_vbo", "/usr/share/assimp/models/X/Testwuson.X", {"--vbo"}},
        CharacterCase{"rigid", "/usr/share/assimp/models/BVH/01_01.bvh", {}},
        CharacterCase{"rigid_vbo", "/usr/share/assimp/models/BVH/01_01.bvh",
                      {"--vbo", "--technique", "rigid"}}),
    caseName);

TEST(CharacterErrors, MissingModelExitsWithOneNamingThePath)
{
    std::string missing = freshDir("missing") + "/no_such_model.md2";
    ProcessResult r = runProcess({demoCharacter(), "--model", missing, "--offscreen",
                                  "--frames", "1", "--size", "64x48"});
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.err.find(missing), std::string::npos) << r.err;
}

TEST(CharacterErrors, UnknownTechniqueIsRefused)
{
    std::string model = "/usr/share/assimp/models/MD2/sydney.md2";
    if (!fs::exists(model)) GTEST_SKIP() << model << " is missing";
    ProcessResult r = runProcess({demoCharacter(), "--model", model, "--technique", "warp",
                                  "--offscreen", "--frames", "1", "--size", "64x48"});
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.err.find("warp"), std::string::npos) << r.err;
}

TEST(CharacterTexture, MD2SkinsAreLoadedAndABadOneIsNamed)
{
    const std::string md2 = "/usr/share/assimp/models/MD2/";
    if (!fs::exists(md2 + "sydney.md2")) GTEST_SKIP() << "assimp-testmodels is not installed";
    // sydney.bmp lies beside sydney.md2: the model is drawn textured.
    ProcessResult r = runProcess({demoCharacter(), "--model", md2 + "sydney.md2", "--offscreen",
                                  "--frames", "1", "--size", "64x64", "--report"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("textured"), std::string::npos) << r.out;
    ProcessResult bad = runProcess({demoCharacter(), "--model", md2 + "faerie.md2", "--texture",
                                    "/no/such/skin.bmp", "--offscreen", "--frames", "1"});
    EXPECT_EQ(bad.exitCode, 1);
    EXPECT_NE(bad.err.find("/no/such/skin.bmp"), std::string::npos) << bad.err;
}

TEST(CharacterWindow, AllThreeTechniquesRunUnderNprglInAGlxWindow)
{
    const char* display = std::getenv("DISPLAY");
    ASSERT_TRUE(display && *display) << "run through scripts/test.sh (Xvfb)";
    const std::string models = "/usr/share/assimp/models/";
    for (const char* model : {"MD2/sydney.md2", "X/Testwuson.X", "BVH/01_01.bvh"}) {
        if (!fs::exists(models + model)) GTEST_SKIP() << "assimp-testmodels is not installed";
        std::string nativeDir = freshDir("glxnative"), shimDir = freshDir("glxshim");
        std::vector<std::string> args = {demoCharacter(), "--model", models + model, "--frames",
                                         "3", "--size", "128x96", "--save-frames", "1-3"};
        std::vector<std::string> native = args, shimmed = {nprglCommand(), "--style", "none",
                                                           "--"};
        native.insert(native.end(), {"--save-dir", nativeDir});
        shimmed.insert(shimmed.end(), args.begin(), args.end());
        shimmed.insert(shimmed.end(), {"--save-dir", shimDir});
        ProcessResult a = runProcess(native);
        ASSERT_EQ(a.exitCode, 0) << model << ": " << a.err;
        ProcessResult b = runProcess(shimmed);
        ASSERT_EQ(b.exitCode, 0) << model << ": " << b.err;
        for (int frame = 1; frame <= 3; ++frame) {
            ImageDiff diff = compareImages(livePng(nativeDir, frame), livePng(shimDir, frame));
            ASSERT_TRUE(diff.comparable) << diff.error;
            EXPECT_EQ(diff.differingPixels, 0u) << model << " frame " << frame;
        }
    }
}
