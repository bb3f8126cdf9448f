// End to end: demo_state must see exactly the GL state it set, natively and under nprgl, and
// demo_shapes' ray-cast truth silhouettes must lie on the outlines of its GL frame.

#include "common/PngImage.h"
#include "tests/support/ImageCompare.h"
#include "tests/support/Process.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

using namespace nprgl;
using namespace nprgl::test;

namespace {

// Every style, alone and in the chains users reach for: the program must not notice any.
const std::vector<std::string> kStyles = {"none",           "toon",           "textured",
                                          "halftone",       "wireframe",      "perpixel",
                                          "edges",          "strokes",        "toon+edges",
                                          "halftone+wireframe", "textured+strokes",
                                          "toon+perpixel",  "halftone+strokes",
                                          "textured+edges", "toon+paper+edges",
                                          "paper",          "coverage",       "pencil",
                                          "gooch+blueprint", "depthcue"};


std::vector<std::string> stateArgs(bool offscreen)
{
    std::vector<std::string> args = {demo("state"), "--frames", "5", "--size", "200x150",
                                     "--report"};
    if (offscreen) args.push_back("--offscreen");
    return args;
}

// The item count from "state checks: N items x F frames, all equal", or -1.
int reportedItems(const std::string& out, int frames)
{
    std::smatch match;
    std::regex line("state checks: ([0-9]+) items x ([0-9]+) frames, all equal");
    if (!std::regex_search(out, match, line) || std::stoi(match[2]) != frames) return -1;
    return std::stoi(match[1]);
}

// demo_state's "glsl: ..." report line (its GLSL program as GL described it), or "".
std::string glslLine(const std::string& out)
{
    std::smatch match;
    return std::regex_search(out, match, std::regex("glsl: [^\n]*")) ? match.str() : "";
}

class StateUnderNprgl : public ::testing::TestWithParam<std::tuple<std::string, bool>> {};

std::string stateCaseName(const ::testing::TestParamInfo<std::tuple<std::string, bool>>& info)
{
    std::string name = std::get<0>(info.param);
    std::replace(name.begin(), name.end(), '+', '_');
    return name + (std::get<1>(info.param) ? "_offscreen" : "_glx");
}

} // namespace

TEST(StateNative, EveryQueryAnswersWhatWasSet)
{
    for (bool offscreen : {true, false}) {
        if (!offscreen && !haveDisplay()) {
            ADD_FAILURE() << "no DISPLAY: run the tests through scripts/test.sh (Xvfb)";
            continue;
        }
        ProcessResult r = runProcess(stateArgs(offscreen));
        ASSERT_EQ(r.exitCode, 0) << (offscreen ? "offscreen: " : "glx: ") << r.err;
        EXPECT_EQ(r.err, "");
        EXPECT_GE(reportedItems(r.out, 5), 100) << r.out;
        // README tells users how many pieces of state are checked: it must be this run's.
        std::ifstream readme(std::string(NPRGL_TEST_SOURCE_DIR) + "/../README.md");
        const std::string text{std::istreambuf_iterator<char>(readme), {}};
        std::regex claim("([0-9]+) pieces of GL state");
        int claims = 0;
        for (auto it = std::sregex_iterator(text.begin(), text.end(), claim);
             it != std::sregex_iterator(); ++it, ++claims) {
            EXPECT_EQ(std::stoi((*it)[1]), reportedItems(r.out, 5)) << "README: " << it->str();
        }
        EXPECT_GE(claims, 1) << "README no longer says how many pieces of state are checked";
    }
}

TEST_P(StateUnderNprgl, EveryQueryAnswersWhatWasSet)
{
    const auto& [style, offscreen] = GetParam();
    if (!offscreen) {
        ASSERT_TRUE(haveDisplay()) << "no DISPLAY: run the tests through scripts/test.sh";
    }
    std::string nativeDir = freshDir("native"), shimDir = freshDir("shim");
    std::vector<std::string> nativeArgs = stateArgs(offscreen);
    nativeArgs.insert(nativeArgs.end(), {"--save-dir", nativeDir});
    ProcessResult native = runProcess(nativeArgs);
    ASSERT_EQ(native.exitCode, 0) << native.err;

    std::vector<std::string> args = {binDir() + "/nprgl", "--style", style, "--"};
    std::vector<std::string> app = stateArgs(offscreen);
    args.insert(args.end(), app.begin(), app.end());
    args.insert(args.end(), {"--save-dir", shimDir});
    ProcessResult r = runProcess(args);
    // demo_state's stderr line names the first state that differs and both values.
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.err.find("nprgl: error"), std::string::npos) << r.err;
    int items = reportedItems(r.out, 5);
    EXPECT_GE(items, 100) << r.out;
    EXPECT_EQ(items, reportedItems(native.out, 5)) << r.out;
    // What GL said of the program's own GLSL program (compile and link results, logs,
    // locations, active uniforms and attributes) is what it says natively.
    EXPECT_EQ(glslLine(r.out), glslLine(native.out));
    EXPECT_NE(glslLine(native.out), "");
    if (style != "none") {
        // The style did draw (a transparent nothing would pass the checks above too).
        std::string file = "/state_5.png";
        ImageDiff diff = compareImages(nativeDir + file, shimDir + file, 16);
        ASSERT_TRUE(diff.comparable) << diff.error;
        // Thin outlines: perpixel inks only the sphere's and torus's rims (about 200 pixels;
        // its cube's flat faces never turn away), where nothing drawn differs in none.
        EXPECT_GT(diff.differingPixels, 100u) << style;
    }
    if (style == "none") {
        // Passthrough draws the same pictures, state juggling and all.
        for (int frame = 1; frame <= 5; ++frame) {
            std::string file = "/state_" + std::to_string(frame) + ".png";
            ImageDiff diff = compareImages(nativeDir + file, shimDir + file);
            ASSERT_TRUE(diff.comparable) << diff.error;
            EXPECT_EQ(diff.differingPixels, 0u) << "frame " << frame;
        }
    }
}

// The overlay draws just before the swap, after the program's last query of the frame and
// before its first of the next: every piece of state and every GL error must survive it.
TEST(StateUnderNprglOverlay, EveryQueryAnswersWhatWasSetWithTheOverlayOpen)
{
    ASSERT_TRUE(haveDisplay()) << "no DISPLAY: run the tests through scripts/test.sh";
    ProcessResult native = runProcess(stateArgs(false));
    ASSERT_EQ(native.exitCode, 0) << native.err;
    std::vector<std::string> args = {binDir() + "/nprgl", "--style", "toon+edges", "--"};
    std::vector<std::string> app = stateArgs(false);
    args.insert(args.end(), app.begin(), app.end());
    ProcessResult r = runProcess(args, {{"NPRGL_OVERLAY", "open"},
                                        {"XDG_CONFIG_HOME", freshDir("overlay_state_home")},
                                        {"NPRGL_CONFIG_FILE", ""}});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("nprgl: overlay open"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("nprgl: error"), std::string::npos) << r.err;
    EXPECT_EQ(reportedItems(r.out, 5), reportedItems(native.out, 5)) << r.out;
}

// The screenshot key's pair: the frame after the press is written styled, then drawn again
// from its calls as the program draws it, in the program's context, between the swap and the
// program's next query. demo_state pops the state it pushed at the end of the previous frame
// (so its calls run from the state they left) and changes state all over: every piece of it
// must survive, and the unstyled picture must be the program's own frame 4.
TEST(StateUnderNprglScreenshot, EveryQueryAnswersWhatWasSetAcrossAScreenshotPair)
{
    ASSERT_TRUE(haveDisplay()) << "no DISPLAY: run the tests through scripts/test.sh";
    const std::string nativeDir = freshDir("pair_state_native");
    std::vector<std::string> native = stateArgs(false);
    native.insert(native.end(), {"--save-dir", nativeDir, "--save-frames", "4"});
    ProcessResult n = runProcess(native);
    ASSERT_EQ(n.exitCode, 0) << n.err;
    const std::string home = freshDir("pair_state_home"), pictures = home + "/pictures";
    {
        std::ofstream(home + "/keys.conf") << "screenshot_dir=" << pictures << "\n";
    }
    std::vector<std::string> args = {binDir() + "/nprgl", "--style", "toon+edges", "--"};
    std::vector<std::string> app = stateArgs(false);
    args.insert(args.end(), app.begin(), app.end());
    args.insert(args.end(), {"--press", "3", "Shift_R+F11"});
    ProcessResult r = runProcess(args, {{"XDG_CONFIG_HOME", home},
                                        {"NPRGL_CONFIG_FILE", home + "/keys.conf"}});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(reportedItems(r.out, 5), reportedItems(n.out, 5)) << r.out << r.err;
    EXPECT_EQ(r.err.find("cannot be drawn again"), std::string::npos) << r.err;
    std::vector<std::string> unstyled;
    for (const auto& entry : std::filesystem::directory_iterator(pictures)) {
        const std::string name = entry.path().string();
        if (name.size() > 13 && name.substr(name.size() - 13) == "_unstyled.png") {
            unstyled.push_back(name);
        }
    }
    ASSERT_EQ(unstyled.size(), 1u) << r.err;
    ImageDiff diff = compareImages(unstyled[0], nativeDir + "/state_4.png");
    ASSERT_TRUE(diff.comparable) << diff.error;
    EXPECT_EQ(diff.differingPixels, 0u);
}

INSTANTIATE_TEST_SUITE_P(Styles, StateUnderNprgl,
                         ::testing::Combine(::testing::ValuesIn(kStyles), ::testing::Bool()),
                         stateCaseName);

TEST(ShapesTruth, SilhouettesLieOnTheGlFramesOutlines)
{
    std::string dir = freshDir("shapes");
    const int frame = 7;
    ProcessResult r = runProcess({demo("shapes"), "--offscreen", "--frames", "7", "--step",
                                  "3", "--save-dir", dir, "--save-frames", "7", "--truth", dir});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    std::string base = dir + "/shapes_" + std::to_string(frame);
    PngImage picture, truth;
    std::string error;
    ASSERT_TRUE(PngImage::read(base + ".png", picture, error)) << error;
    ASSERT_TRUE(PngImage::read(base + "_truth.png", truth, error)) << error;
    ASSERT_EQ(picture.width, truth.width);
    ASSERT_EQ(picture.height, truth.height);
    int w = picture.width;
    int h = picture.height;

    // Colour boundaries of the GL frame: a 4-neighbour differs clearly. Shading changes
    // smoothly between neighbours; object/background and object/object edges do not.
    auto at = [&](const PngImage& image, int x, int y, int c) {
        return static_cast<int>(image.rgba[(static_cast<size_t>(y) * w + x) * 4 + c]);
    };
    std::vector<uint8_t> boundary(static_cast<size_t>(w) * h, 0);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            for (auto [dx, dy] : {std::pair{1, 0}, std::pair{0, 1}}) {
                if (x + dx >= w || y + dy >= h) continue;
                int difference = 0;
                for (int c = 0; c < 3; ++c) {
                    difference += std::abs(at(picture, x, y, c) - at(picture, x + dx, y + dy, c));
                }
                if (difference > 30) {
                    boundary[static_cast<size_t>(y) * w + x] = 1;
                    boundary[static_cast<size_t>(y + dy) * w + x + dx] = 1;
                }
            }
        }
    }

    // Every truth silhouette pixel within 1.5 px (the 8 neighbours) of a boundary.
    size_t silhouettePixels = 0, nearBoundary = 0;
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            if (at(truth, x, y, 0) < 128) continue;
            ++silhouettePixels;
            bool found = false;
            for (int dy = -1; dy <= 1 && !found; ++dy) {
                for (int dx = -1; dx <= 1 && !found; ++dx) {
                    int nx = x + dx, ny = y + dy;
                    found = nx >= 0 && ny >= 0 && nx < w && ny < h
                            && boundary[static_cast<size_t>(ny) * w + nx];
                }
            }
            nearBoundary += found;
        }
    }
    // Six shapes of 50-200 px across at 512x512 have thousands of silhouette pixels.
    EXPECT_GT(silhouettePixels, 1500u);
    std::printf("truth silhouette: %zu pixels, %.4f of them on a GL colour boundary\n",
                silhouettePixels, static_cast<double>(nearBoundary) / silhouettePixels);
    EXPECT_GE(static_cast<double>(nearBoundary) / silhouettePixels, 0.95)
        << nearBoundary << " of " << silhouettePixels << " silhouette pixels on a boundary";

    // The ids picture is written alongside and shows all six shapes.
    PngImage ids;
    ASSERT_TRUE(PngImage::read(base + "_ids.png", ids, error)) << error;
    std::vector<uint32_t> colours;
    for (size_t i = 0; i < ids.rgba.size(); i += 4) {
        uint32_t colour = ids.rgba[i] << 16 | ids.rgba[i + 1] << 8 | ids.rgba[i + 2];
        if (std::find(colours.begin(), colours.end(), colour) == colours.end()) {
            colours.push_back(colour);
        }
    }
    EXPECT_EQ(colours.size(), 7u) << "background and six shapes";
}

TEST(ShapesTruth, RunsAreDeterministic)
{
    std::string a = freshDir("shapes_a"), b = freshDir("shapes_b");
    for (const std::string& dir : {a, b}) {
        ProcessResult r = runProcess({demo("shapes"), "--offscreen", "--frames", "2", "--size",
                                      "128x128", "--save-dir", dir, "--truth", dir});
        ASSERT_EQ(r.exitCode, 0) << r.err;
    }
    for (const char* file : {"/shapes_2.png", "/shapes_2_truth.png"}) {
        PngImage x, y;
        std::string error;
        ASSERT_TRUE(PngImage::read(a + file, x, error)) << error;
        ASSERT_TRUE(PngImage::read(b + file, y, error)) << error;
        EXPECT_EQ(x.rgba, y.rgba) << file;
    }
}
