// End to end: the frame compositor. Golden replays of the committed captures in each style,
// overlays kept on top, core profiles passed through, presets and bad styles refused before
// the program starts.

#include "common/PngImage.h"
#include "tests/support/ImageCompare.h"
#include "tests/support/Process.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace nprgl;
using namespace nprgl::test;
namespace fs = std::filesystem;

namespace {

std::string nprglCommand() { return binDir() + "/nprgl"; }
std::string demo(const std::string& name) { return binDir() + "/demo_" + name; }
std::string source(const std::string& path) { return std::string(NPRGL_TEST_SOURCE_DIR) + path; }
std::string framePng(const std::string& dir, int frame)
{
    char name[32];
    std::snprintf(name, sizeof name, "/frame_%010d.png", frame);
    return dir + name;
}

struct GoldenCase {
    std::string fixture, style;
    int frame = 0;
};

void PrintTo(const GoldenCase& c, std::ostream* os)
{
    *os << c.fixture << " " << c.style << " frame " << c.frame;
}

std::vector<GoldenCase> goldenCases()
{
    std::vector<GoldenCase> cases;
    std::ifstream in(source("/golden/cases.txt"));
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream fields(line);
        GoldenCase c;
        if (fields >> c.fixture >> c.style >> c.frame) cases.push_back(c);
    }
    return cases;
}

std::string goldenName(const GoldenCase& c)
{
    std::string name = c.fixture + "_" + c.style;
    std::replace(name.begin(), name.end(), '+', '-');
    return name;
}

} // namespace

class Golden : public ::testing::TestWithParam<GoldenCase> {};

// The tolerance absorbs llvmpipe's rounding differences between machines (a few levels on
// antialiased edges), not a changed look: at most 0.5% of pixels may differ by more than 24.
TEST_P(Golden, ReplayMatchesTheGoldenImage)
{
    const GoldenCase& c = GetParam();
    const std::string dir = freshDir("golden_" + goldenName(c));
    ProcessResult r =
        runProcess({nprglCommand(), "replay", source("/fixtures/" + c.fixture + ".nprgl"), "-o",
                    dir, "--style", c.style, "--frames", std::to_string(c.frame)});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const std::string golden = source("/golden/" + goldenName(c) + ".png");
    ASSERT_TRUE(fs::exists(golden)) << golden << " is missing: run scripts/rebase-goldens.sh";
    ImageDiff diff = compareImages(golden, framePng(dir, c.frame), 24);
    ASSERT_TRUE(diff.comparable) << diff.error;
    PngImage image;
    std::string error;
    ASSERT_TRUE(PngImage::read(golden, image, error)) << error;
    EXPECT_LE(diff.differingPixels, size_t(image.width) * image.height / 200)
        << c.fixture << " in " << c.style << " differs from " << golden << " (see "
        << framePng(dir, c.frame) << ")";
}

INSTANTIATE_TEST_SUITE_P(Styles, Golden, ::testing::ValuesIn(goldenCases()),
                         [](const auto& info) {
                             std::string name = goldenName(info.param);
                             std::replace(name.begin(), name.end(), '-', '_');
                             return name;
                         });

TEST(Compositor, StylesChangeTheSceneAndKeepTheOverlayOnTop)
{
    const std::string native = freshDir("overlay_native"), styled = freshDir("overlay_toon");
    ProcessResult n = runProcess({demo("overlay"), "--offscreen", "--frames", "2",
                                  "--save-dir", native, "--save-frames", "2"});
    ASSERT_EQ(n.exitCode, 0) << n.err;
    ProcessResult s = runProcess({nprglCommand(), "--style", "toon", "--", demo("overlay"),
                                  "--offscreen", "--frames", "2", "--save-dir", styled,
                                  "--save-frames", "2"});
    ASSERT_EQ(s.exitCode, 0) << s.err;
    EXPECT_EQ(s.out, n.out);
    PngImage a, b;
    std::string error;
    ASSERT_TRUE(PngImage::read(native + "/overlay_2.png", a, error)) << error;
    ASSERT_TRUE(PngImage::read(styled + "/overlay_2.png", b, error)) << error;
    ASSERT_EQ(a.rgba.size(), b.rgba.size());
    // The title text (top left, drawn with glBitmap after the scene) is the program's own;
    // the scene below it is not.
    size_t titleDiffers = 0, sceneDiffers = 0;
    for (int y = 0; y < a.height; ++y) {
        for (int x = 0; x < a.width; ++x) {
            const size_t i = (size_t(y) * a.width + x) * 4;
            const bool differs = std::abs(a.rgba[i] - b.rgba[i]) +
                                     std::abs(a.rgba[i + 1] - b.rgba[i + 1]) +
                                     std::abs(a.rgba[i + 2] - b.rgba[i + 2]) >
                                 6;
            if (y < 32 && x < 170) titleDiffers += differs;
            if (y > 150 && y < 420) sceneDiffers += differs;
        }
    }
    EXPECT_EQ(titleDiffers, 0u);
    EXPECT_GT(sceneDiffers, size_t(a.width) * 270 / 50) << "toon changed less than 2% of the scene";
}

TEST(Compositor, CoreProfileProgramsArePassedThroughWithOneWarning)
{
    ProcessResult n = runProcess({binDir() + "/probe_core"});
    ASSERT_EQ(n.exitCode, 0) << n.err;
    ProcessResult s =
        runProcess({nprglCommand(), "--style", "toon", "--", binDir() + "/probe_core"});
    ASSERT_EQ(s.exitCode, 0) << s.err;
    EXPECT_EQ(s.out, n.out);
    size_t warnings = 0;
    for (size_t at = s.err.find("passthrough"); at != std::string::npos;
         at = s.err.find("passthrough", at + 1)) {
        ++warnings;
    }
    EXPECT_EQ(warnings, 1u) << s.err;
    EXPECT_NE(s.err.find("core profile"), std::string::npos) << s.err;
}

TEST(Compositor, BadStylesParametersAndPresetsAreRefusedBeforeTheProgramStarts)
{
    const std::string dir = freshDir("presets");
    const std::string bad = dir + "/bad.conf";
    std::ofstream(bad) << "# a preset\nstyle=toon\ntoon.nonesuch=1\n";
    const std::vector<std::vector<std::string>> cases = {
        {"--style", "sparkles"},
        {"--style", "toon", "--set", "toon.diffuse_threshold=7"},
        {"--style", "toon", "--set", "toon.tones=many"},
        {"--style", "toon+toon"},
        {"--preset", "nonesuch"},
        {"--preset", bad},
        {"--preset", dir + "/missing.conf"},
    };
    for (const auto& options : cases) {
        std::vector<std::string> cmd = {nprglCommand()};
        cmd.insert(cmd.end(), options.begin(), options.end());
        cmd.insert(cmd.end(), {"--", "sh", "-c", "echo started"});
        ProcessResult r = runProcess(cmd);
        EXPECT_NE(r.exitCode, 0) << options.back();
        EXPECT_EQ(r.out, "") << options.back();
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_EQ(r.err.rfind("nprgl: ", 0), 0u) << r.err;
    }
    // The bad presets' messages name the file and the line.
    ProcessResult r = runProcess({nprglCommand(), "--preset", bad, "--", "true"});
    EXPECT_NE(r.err.find(bad + ":3:"), std::string::npos) << r.err;
    const std::string range = dir + "/range.conf";
    std::ofstream(range) << "style=toon\ntoon.tones=9\n";
    r = runProcess({nprglCommand(), "--preset", range, "--", "true"});
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.err.find(range + ":2: parameter toon.tones=9 is out of range"), std::string::npos)
        << r.err;
}

TEST(Compositor, EveryShippedPresetRuns)
{
    ProcessResult list = runProcess({nprglCommand(), "styles"});
    ASSERT_EQ(list.exitCode, 0);
    const size_t presets = list.out.find("Presets");
    ASSERT_NE(presets, std::string::npos) << list.out;
    std::istringstream lines(list.out.substr(presets));
    std::string line;
    std::getline(lines, line);
    int count = 0;
    while (std::getline(lines, line)) {
        std::istringstream words(line);
        std::string name;
        if (!(words >> name) || line.rfind("    ", 0) != 0) continue;
        const std::string dir = freshDir("preset_" + name);
        ProcessResult r = runProcess({nprglCommand(), "--preset", name, "--", demo("displaylist"),
                                      "--offscreen", "--frames", "2", "--save-dir", dir,
                                      "--save-frames", "2"});
        EXPECT_EQ(r.exitCode, 0) << name << ": " << r.err;
        EXPECT_TRUE(fs::exists(dir + "/displaylist_2.png")) << name;
        ++count;
    }
    EXPECT_GE(count, 3);
}

TEST(Compositor, GlxgearsInToonKeepsItsRedGreenAndBlueGears)
{
    if (!std::getenv("DISPLAY") || !*std::getenv("DISPLAY")) GTEST_SKIP() << "no DISPLAY";
    const std::string dir = freshDir("glxgears_toon");
    ProcessResult r = runProcess({nprglCommand(), "--style", "toon", "--screenshot",
                                  "frames=20;dir=" + dir, "--", "glxgears"},
                                 {}, 3);
    ASSERT_TRUE(fs::exists(dir + "/glxgears_20.png")) << r.err;
    expectGlxgearsPicture(dir + "/glxgears_20.png");
}

struct DemoCase {
    std::string app;
    std::vector<std::string> args;
};

void PrintTo(const DemoCase& c, std::ostream* os) { *os << c.app; }

class DefaultStyle : public ::testing::TestWithParam<DemoCase> {};

// With no configuration at all: every demo app (lit or not, with or without normals,
// textured, overlays, the character) runs under the default chain, prints what it prints
// natively, and its picture is the chain's, not the program's.
TEST_P(DefaultStyle, EveryDemoAppRunsAndIsStylised)
{
    const DemoCase& c = GetParam();
    if (c.app == "character" && !fs::exists("/usr/share/assimp/models/X/Testwuson.X")) {
        GTEST_SKIP() << "assimp-testmodels is not installed";
    }
    const std::string native = freshDir("default_native_" + c.app);
    const std::string styled = freshDir("default_styled_" + c.app);
    std::vector<std::string> args = {demo(c.app), "--offscreen", "--frames", "3", "--size",
                                     "160x120", "--save-frames", "3"};
    args.insert(args.end(), c.args.begin(), c.args.end());
    std::vector<std::string> n = args, s = {nprglCommand(), "--"};
    n.insert(n.end(), {"--save-dir", native});
    s.insert(s.end(), args.begin(), args.end());
    s.insert(s.end(), {"--save-dir", styled});
    ProcessResult a = runProcess(n), b = runProcess(s, {{"NPRGL_STYLE", ""}, {"NPRGL_CONFIG", ""}});
    ASSERT_EQ(a.exitCode, 0) << a.err;
    ASSERT_EQ(b.exitCode, 0) << b.err;
    EXPECT_EQ(b.out, a.out);
    EXPECT_EQ(b.err.find("nprgl: error"), std::string::npos) << b.err;
    EXPECT_EQ(b.err.find("nprgl: warning"), std::string::npos) << b.err;
    const std::string file = "/" + c.app + "_3.png";
    ImageDiff diff = compareImages(native + file, styled + file, 24);
    ASSERT_TRUE(diff.comparable) << diff.error;
    EXPECT_GT(diff.differingPixels, 160u * 120u / 20) << "the default style changed too little";
}

INSTANTIATE_TEST_SUITE_P(
    Demos, DefaultStyle,
    ::testing::Values(DemoCase{"immediate", {}}, DemoCase{"arrays", {}},
                      DemoCase{"arrays", {"--vbo"}}, DemoCase{"displaylist", {}},
                      DemoCase{"textured", {}}, DemoCase{"overlay", {}},
                      DemoCase{"state", {}},
                      DemoCase{"character",
                               {"--model", "/usr/share/assimp/models/X/Testwuson.X"}},
                      DemoCase{"character",
                               {"--model", "/usr/share/assimp/models/MD2/sydney.md2"}}),
    [](const auto& info) {
        std::string name = info.param.app + std::to_string(info.index);
        return name;
    });
