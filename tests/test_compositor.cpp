// End to end: the frame compositor. Golden replays of the committed captures in each style,
// overlays kept on top, core profiles passed through, presets and bad styles refused before
// the program starts.

#include "common/PngImage.h"
#include "tests/support/ImageCompare.h"
#include "tests/support/Process.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

using namespace nprgl;
using namespace nprgl::test;
namespace fs = std::filesystem;

namespace {

std::string source(const std::string& path) { return std::string(NPRGL_TEST_SOURCE_DIR) + path; }
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
    std::replace(name.begin(), name.end(), ':', '_');
    return name;
}

constexpr const char* kLive = "live:";

// Renders the case's frame: a replay of a capture, or a demo app run live under nprgl.
// Returns the PNG's path, or "" with the failure reported.
std::string renderGoldenCase(const GoldenCase& c, const std::string& dir)
{
    const std::string frame = std::to_string(c.frame);
    if (c.fixture.rfind(kLive, 0) == 0) {
        const std::string app = c.fixture.substr(std::string(kLive).size());
        ProcessResult r = runProcess({nprglCommand(), "--style", c.style, "--", demo(app),
                                      "--offscreen", "--size", "256x192", "--frames", frame,
                                      "--save-frames", frame, "--save-dir", dir});
        EXPECT_EQ(r.exitCode, 0) << r.err;
        return r.exitCode == 0 ? dir + "/" + app + "_" + frame + ".png" : "";
    }
    ProcessResult r = runProcess({nprglCommand(), "replay",
                                  source("/fixtures/" + c.fixture + ".nprgl"), "-o", dir,
                                  "--style", c.style, "--frames", frame});
    EXPECT_EQ(r.exitCode, 0) << r.err;
    return r.exitCode == 0 ? framePng(dir, c.frame) : "";
}

// A demo app's third frame at 320x240, run under nprgl with `options` (a style or preset) and
// the demo's `extra` options, written to a fresh directory named `name`; the run's log in
// `log` when asked. Returns the PNG's path.
std::string demoFrame(const std::string& app, const std::string& name,
                      const std::vector<std::string>& options,
                      const std::vector<std::string>& extra, std::string* log = nullptr)
{
    const std::string dir = freshDir(name);
    std::vector<std::string> command = {demo(app),       "--offscreen",  "--size", "320x240",
                                        "--frames",      "3",            "--save-frames", "3",
                                        "--save-dir",    dir};
    command.insert(command.end(), extra.begin(), extra.end());
    std::vector<std::string> wrapper = {nprglCommand()};
    wrapper.insert(wrapper.end(), options.begin(), options.end());
    ProcessResult r = runProcess(under(wrapper, command));
    EXPECT_EQ(r.exitCode, 0) << r.err;
    if (log) *log = r.err;
    return dir + "/" + app + "_3.png";
}

// The RGBA bytes of pixel (x, y) of `image`, rows from the top.
const uint8_t* pixel(const PngImage& image, int x, int y)
{
    return &image.rgba[(size_t(y) * image.width + x) * 4];
}

// The PNG at `path` (empty, with the failure reported, when it cannot be read).
PngImage readPng(const std::string& path)
{
    PngImage image;
    std::string error;
    EXPECT_TRUE(PngImage::read(path, image, error)) << error;
    return image;
}

} // namespace

class Golden : public ::testing::TestWithParam<GoldenCase> {};

// The tolerance absorbs llvmpipe's rounding differences between machines (a few levels on
// antialiased edges), not a changed look: at most 0.5% of pixels may differ by more than 24.
TEST_P(Golden, FrameMatchesTheGoldenImage)
{
    const GoldenCase& c = GetParam();
    const std::string dir = freshDir("golden_" + goldenName(c));
    const std::string rendered = renderGoldenCase(c, dir);
    ASSERT_FALSE(rendered.empty());
    const std::string golden = source("/golden/" + goldenName(c) + ".png");
    ASSERT_TRUE(fs::exists(golden)) << golden << " is missing: run scripts/rebase-goldens.sh";
    ImageDiff diff = compareImages(golden, rendered, 24);
    ASSERT_TRUE(diff.comparable) << diff.error;
    PngImage image;
    std::string error;
    ASSERT_TRUE(PngImage::read(golden, image, error)) << error;
    EXPECT_LE(diff.differingPixels, size_t(image.width) * image.height / 200)
        << c.fixture << " in " << c.style << " differs from " << golden << " (see " << rendered
        << ")";
}

INSTANTIATE_TEST_SUITE_P(Styles, Golden, ::testing::ValuesIn(goldenCases()),
                         [](const auto& p) {
                             std::string name = goldenName(p.param);
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
        // Its settings reach branches the styles' defaults do not (Cli.EveryStyleReads...).
        EXPECT_EQ(r.err.find("which no style declares"), std::string::npos) << name << r.err;
        ++count;
    }
    EXPECT_GE(count, 3);
}

// The comic preset promises ink between the bands: its frame differs from the same preset
// without band lines, and where it differs it is darker.
TEST(Compositor, ComicPresetDrawsInkBetweenTheBands)
{
    const std::string ink = freshDir("comic_ink"), plain = freshDir("comic_plain");
    const std::vector<std::string> app = {demo("displaylist"), "--offscreen", "--frames", "2",
                                          "--size", "256x192", "--save-frames", "2",
                                          "--save-dir"};
    std::vector<std::string> a = {nprglCommand(), "--preset", "comic", "--"};
    a.insert(a.end(), app.begin(), app.end());
    a.push_back(ink);
    std::vector<std::string> b = {nprglCommand(), "--preset", "comic", "--set",
                                  "toon.band_lines=off", "--"};
    b.insert(b.end(), app.begin(), app.end());
    b.push_back(plain);
    ProcessResult ra = runProcess(a), rb = runProcess(b);
    ASSERT_EQ(ra.exitCode, 0) << ra.err;
    ASSERT_EQ(rb.exitCode, 0) << rb.err;
    PngImage withInk, without;
    std::string error;
    ASSERT_TRUE(PngImage::read(ink + "/displaylist_2.png", withInk, error)) << error;
    ASSERT_TRUE(PngImage::read(plain + "/displaylist_2.png", without, error)) << error;
    ASSERT_EQ(withInk.rgba.size(), without.rgba.size());
    size_t differing = 0, darker = 0;
    for (size_t i = 0; i < withInk.rgba.size(); i += 4) {
        const int lumInk = withInk.rgba[i] + withInk.rgba[i + 1] + withInk.rgba[i + 2];
        const int lumPlain = without.rgba[i] + without.rgba[i + 1] + without.rgba[i + 2];
        if (std::abs(lumInk - lumPlain) <= 24) continue;
        ++differing;
        darker += lumInk < lumPlain;
    }
    EXPECT_GT(differing, 256u * 192u / 500) << "no ink between the bands";
    EXPECT_GE(darker * 10, differing * 9) << "the band lines are not ink";
}

// A backdrop the program draws in its clear colour without depth (an arena's dark floor) is
// a surface of the scene: the page goes under it, not over it. The page was laid after the
// scene, where a pixel was still the clear colour at the far depth, which the floor was.
TEST(Compositor, ABackdropInTheClearColourStaysOnThePage)
{
    const std::string dir = freshDir("backdrop_floor");
    ProcessResult r =
        runProcess(under({nprglCommand(), "--style", "toon+paper", "--set", "paper.tone=light"},
                         {demo("textured"), "--backdrop-floor", "--offscreen", "--size", "320x240",
                          "--frames", "2", "--save-frames", "2", "--save-dir", dir}));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    PngImage image;
    std::string error;
    ASSERT_TRUE(PngImage::read(dir + "/textured_2.png", image, error)) << error;
    // The clear colour (0.15, 0.15, 0.18): the floor's, in the floor's middle near the bottom;
    // the page above the scene.
    int floor = 0, all = 0;
    for (int y = 200; y < 236; ++y) {
        for (int x = 140; x < 180; ++x) {
            const uint8_t* p = pixel(image, x, y);
            floor += std::abs(p[0] - 38) <= 6 && std::abs(p[2] - 46) <= 6;
            ++all;
        }
    }
    EXPECT_GT(floor, all * 9 / 10) << floor << " of " << all << " floor pixels kept";
    EXPECT_GT(pixel(image, 160, 10)[0], 200) << "no page above the scene";
}

// The page goes where nothing of the frame is. A panel the program draws with glDrawPixels
// before its scene (frame 1) is the frame's and stays. Later frames clear only depth: in a
// window's back buffer, whose contents a swap leaves undefined, the panel's pixels are left
// over from a shown frame, so they are background and become page. On OSMesa, which has no
// swap, they are still the program's and stay.
TEST(Compositor, PixelsLeftFromAShownFrameBecomePageAndTheFramesOwnStay)
{
    // Frames 1 and 3 of one run; returns the directory they are in.
    auto run = [](bool window) {
        const std::string dir = freshDir(window ? "stale_panel_glx" : "stale_panel_osmesa");
        std::vector<std::string> command = {
            demo("textured"), "--stale-panel", "--size",     "320x240", "--frames", "3",
            "--save-frames",  "1,3",           "--save-dir", dir};
        if (!window) command.push_back("--offscreen");
        ProcessResult r = runProcess(
            under({nprglCommand(), "--style", "toon+paper", "--set", "paper.tone=light"}, command));
        EXPECT_EQ(r.exitCode, 0) << r.err;
        return dir;
    };
    auto panelAt = [](const std::string& dir, int frame) {
        const PngImage image = readPng(dir + "/textured_" + std::to_string(frame) + ".png");
        if (image.rgba.empty()) return std::array<int, 3>{-1, -1, -1};
        // Window (8, 10): the panel's corner, left of the floor.
        const uint8_t* p = pixel(image, 8, 229);
        return std::array<int, 3>{p[0], p[1], p[2]};
    };
    const std::array<int, 3> red{255, 0, 0};
    const std::string window = run(true);
    EXPECT_EQ(panelAt(window, 1), red) << "the frame's own panel became page";
    const std::array<int, 3> shown = panelAt(window, 3);
    EXPECT_GT(shown[1], 200) << "the last frame's panel is still there, not page";
    EXPECT_GT(shown[2], 190) << "the last frame's panel is still there, not page";
    EXPECT_EQ(panelAt(run(false), 3), red) << "without a swap the panel is the program's";
}

// Colour-coded picking (dreamchess picks its squares so): the program draws ids as flat
// colours into a framebuffer object and reads them back. Styled, they came back as paper,
// ink and shaded bands. From the first read on the program gets the ids native gets (the
// flush that read forces is drawn unstyled; later draws there are left), while the frame it
// shows is still styled.
TEST(Compositor, ColourCodedPickingReadsWhatTheProgramDrew)
{
    auto picks = [](const std::string& style, const std::string& dir) {
        ProcessResult r =
            runProcess(under({nprglCommand(), "--style", style, "--set", "paper.tone=light"},
                             {demo("textured"), "--pick", "--offscreen", "--size", "320x240",
                              "--frames", "3", "--save-frames", "3", "--save-dir", dir}));
        EXPECT_EQ(r.exitCode, 0) << r.err;
        return r.out;
    };
    const std::string native = picks("none", freshDir("pick_none"));
    EXPECT_NE(native.find("pick frame 3: 0 0 1 2 2 1 3 1 0 0"), std::string::npos)
        << "the demo picks something else: no test\n"
        << native;
    // The last: a chain without a shading style, where the program draws its objects.
    for (const std::string style : {"toon+paper+edges", "coverage", "paper+edges"}) {
        const std::string dir = freshDir("pick_styled");
        EXPECT_EQ(picks(style, dir), native) << style;
        const PngImage image = readPng(dir + "/textured_3.png");
        ASSERT_FALSE(image.rgba.empty());
        // Above the scene: the page (or the coverage style's untouched background).
        const uint8_t* p = pixel(image, 160, 10);
        if (style != "coverage") {
            EXPECT_GT(p[0], 200) << "the shown frame is not styled";
        }
    }
}

// The coverage style tints what is styled, with the program's alpha test: a cut-out's holes
// stay holes (a model's invisible cut-out quads covered scorched3d's window in grey).
TEST(Compositor, TheCoverageStyleKeepsCutOutsHoles)
{
    const ImageDiff diff =
        compareImages(demoFrame("textured", "coverage_solid", {"--style", "coverage"}, {}),
                      demoFrame("textured", "coverage_cutout", {"--style", "coverage"},
                                {"--cutout"}));
    ASSERT_TRUE(diff.comparable) << diff.error;
    // Eight holes on the cube's three visible faces: hundreds of pixels.
    EXPECT_GT(diff.differingPixels, 300u) << "the cube's holes are tinted over";
}

// A layer blended by its texture's alpha over the very quad of the floor (a pool of water laid
// over the ground, as cultivation draws its) is a picture of its own: drawn over the styled
// floor, not merged into it as a light or detail stage (it was, and the pool vanished), with
// the floor depth-tested (GL_LEQUAL) or drawn as a backdrop without the test.
TEST(Compositor, ALayerBlendedByItsAlphaOverItsSurfaceIsDrawn)
{
    auto poolPixels = [](const std::string& style, bool backdrop) {
        std::vector<std::string> extra = {"--floor-layer"};
        if (backdrop) extra.push_back("--backdrop-floor");
        const PngImage image =
            readPng(demoFrame("textured", "floor_layer", {"--style", style}, extra));
        int pool = 0; // the layer's blue (0.1, 0.35, 1), unlit
        for (size_t i = 0; i + 3 < image.rgba.size(); i += 4) {
            const uint8_t* p = &image.rgba[i];
            pool += p[0] < 50 && p[1] > 70 && p[1] < 110 && p[2] > 235;
        }
        return pool;
    };
    for (bool backdrop : {false, true}) {
        const int native = poolPixels("none", backdrop);
        const int styled = poolPixels("toon+paper+edges", backdrop);
        EXPECT_GT(native, 3000) << "no pool: no test";
        EXPECT_GT(styled, native * 9 / 10)
            << (backdrop ? "backdrop floor: " : "depth-tested floor: ") << styled << " of "
            << native << " pool pixels";
    }
}

// Surfaces drawn at the same depth under GL_LEQUAL: the later one covers the earlier, as in
// GL. The shading pass tested every held surface with GL_LESS, so the first kept its pixels:
// dreamchess's health bars (a white frame, then a blue gradient in it, flat in 2D with the
// depth test) came out white.
TEST(Compositor, ALaterSurfaceAtEqualDepthCoversUnderLequal)
{
    auto bluePixels = [](const std::string& style) {
        const PngImage image =
            readPng(demoFrame("textured", "hud_bar", {"--style", style}, {"--hud-bar"}));
        int blue = 0, seen = 0;
        // Along the bar's middle row (the demo's bar: x 22-218, rows 22-38 from the top).
        for (int x = 30; x <= 210 && !image.rgba.empty(); x += 10, ++seen) {
            const uint8_t* p = pixel(image, x, 30);
            blue += p[2] > p[0] + 40;
        }
        EXPECT_EQ(seen, 19);
        return blue;
    };
    EXPECT_EQ(bluePixels("none"), 19) << "no gradient natively: no test";
    for (const char* style : {"toon+paper+edges", "toon"}) {
        EXPECT_GE(bluePixels(style), 17) << style << ": the white frame covered its gradient";
    }
}

// The page is laid once per framebuffer until that framebuffer's colour is cleared again:
// a clear of another one (the picking target between the scene and the weapon) is no new
// background here. It was taken for one, and the weapon's flush laid the page again over the
// backdrop floor drawn in the clear colour (dreamchess: over the black of its sky).
TEST(Compositor, AnotherFramebuffersClearMakesNoNewBackground)
{
    const PngImage image = readPng(demoFrame("textured", "other_clear",
                                             {"--style", "toon+paper", "--set", "paper.tone=light"},
                                             {"--backdrop-floor", "--pick", "--weapon"}));
    ASSERT_FALSE(image.rgba.empty());
    // The floor near the bottom, in the clear colour (0.15, 0.15, 0.18); the page above.
    EXPECT_NEAR(pixel(image, 160, 220)[0], 38, 6) << "the page was laid over the floor";
    EXPECT_NEAR(pixel(image, 160, 220)[2], 46, 6) << "the page was laid over the floor";
    EXPECT_GT(pixel(image, 160, 10)[0], 200) << "no page above the scene";
}

// A translucent layer drawn without the depth test over an opaque backdrop drawn the same way
// (a sky's clouds over its ground: bzflag) stays translucent: the two were one object, opaque
// as the first, and the haze came out white over the floor (and bzflag's whole sky).
TEST(Compositor, ATranslucentBackdropOverAnOpaqueOneStaysTranslucent)
{
    auto hazeAt = [](const std::string& style) {
        const std::string dir = freshDir("backdrop_haze");
        ProcessResult r = runProcess(
            under({nprglCommand(), "--style", style},
                  {demo("textured"), "--backdrop-floor", "--backdrop-haze", "--offscreen",
                   "--size", "320x240", "--frames", "2", "--save-frames", "2", "--save-dir",
                   dir}));
        EXPECT_EQ(r.exitCode, 0) << r.err;
        PngImage image;
        std::string error;
        EXPECT_TRUE(PngImage::read(dir + "/textured_2.png", image, error)) << error;
        // The haze over the floor's far half, left of the cube.
        return int(image.rgba.empty() ? 0 : pixel(image, 160, 150)[0]);
    };
    const int native = hazeAt("none"), styled = hazeAt("toon+paper");
    EXPECT_GT(native, 60) << "no haze: no test";
    EXPECT_LT(native, 160) << "no haze: no test";
    EXPECT_NEAR(styled, native, 20) << "the haze is not translucent";
}

// Most programs end by exit() without destroying their GL context: the run's counts are
// still logged, once; a program that destroys its context logs them once too.
TEST(Compositor, TheRunsCountsAreLoggedAtExitWithTheContextAlive)
{
    for (bool undestroyed : {true, false}) {
        std::vector<std::string> args = {demo("immediate"), "--offscreen", "--frames", "3",
                                         "--size", "128x128"};
        if (undestroyed) args.push_back("--exit-undestroyed");
        ProcessResult r = runProcess(under({nprglCommand()}, args));
        ASSERT_EQ(r.exitCode, 0) << r.err;
        const size_t first = r.err.find("3D polygon draws: ");
        ASSERT_NE(first, std::string::npos) << (undestroyed ? "exit, context alive: " : "")
                                            << r.err;
        EXPECT_EQ(r.err.find("3D polygon draws: ", first + 1), std::string::npos)
            << "logged twice: " << r.err;
    }
}

// A context that never swaps (a single-buffered window ending its frames by glFlush, a
// toolkit's view drawn off screen and shown by another context) held every call it made for
// the whole run. Past kUnswappedFrameBytes its glFlush ends a frame: the memory is bounded,
// the frames counted, screenshots written, and the log says so.
TEST(Frames, AContextThatNeverSwapsStillEndsItsFrames)
{
    const std::string dir = freshDir("never_swaps");
    ProcessResult r = runProcess(under({nprglCommand(), "--screenshot", "frames=1;dir=" + dir},
                                       {demo("immediate"), "--flush-frames", "--frames", "700",
                                        "--size", "128x128"}));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("bytes of calls without a swap"), std::string::npos) << r.err;
    bool shot = false;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        shot = shot || entry.path().extension() == ".png";
    }
    EXPECT_TRUE(shot) << "no frame ever ended: " << r.err.substr(0, 2000);
}

// Lists called together and left (the plate added to the scene, GL_ONE, GL_ONE, by the one
// glCallLists of demo_displaylist) are counted with their reason and painted red by the
// coverage style, as a glCallList is: they were neither (a 3D draw nobody was told of).
TEST(Compositor, ListsCalledTogetherAndLeftAreCountedAndTinted)
{
    const std::string dir = freshDir("lists_left");
    ProcessResult r = runProcess(under({nprglCommand(), "--style", "coverage"},
                                       {demo("displaylist"), "--glowing-plate", "--offscreen",
                                        "--frames", "3", "--size", "256x192", "--save-frames",
                                        "3", "--save-dir", dir}));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("3D polygon draws: 9 styled, 3 left as the program drew them "
                         "(blending other than"),
              std::string::npos)
        << r.err;
    PngImage image;
    std::string error;
    ASSERT_TRUE(PngImage::read(dir + "/displaylist_3.png", image, error)) << error;
    size_t red = 0;
    for (size_t i = 0; i < image.rgba.size(); i += 4) {
        red += image.rgba[i] >= 250 && image.rgba[i + 1] < 40 && image.rgba[i + 2] < 40;
    }
    EXPECT_GT(red, 256u * 192u / 10) << "the plate is not red";
}

// A list that sets a blend the styles leave inside it (a pool game's ball shadows: white
// with alpha, GL_ZERO, GL_ONE_MINUS_SRC_ALPHA, called while blending by alpha is on) is left
// as the program draws it, said and counted: held for the state at the call, its shadow was
// styled as a white surface.
TEST(Compositor, AListBlendingInsideAsTheStylesLeaveIsLeft)
{
    auto whitePixels = [](bool shadow, std::string* err) {
        const std::string dir = freshDir(shadow ? "shadow_list" : "no_shadow_list");
        std::vector<std::string> app = {demo("displaylist"), "--offscreen", "--frames", "3",
                                        "--size", "256x192", "--save-frames", "3",
                                        "--save-dir", dir};
        if (shadow) app.push_back("--shadow-list");
        ProcessResult r = runProcess(under({nprglCommand(), "--style", "toon"}, app));
        EXPECT_EQ(r.exitCode, 0) << r.err;
        if (err) *err = r.err;
        PngImage image;
        std::string error;
        EXPECT_TRUE(PngImage::read(dir + "/displaylist_3.png", image, error)) << error;
        size_t white = 0;
        for (size_t i = 0; i < image.rgba.size(); i += 4) {
            white += std::min({image.rgba[i], image.rgba[i + 1], image.rgba[i + 2]}) > 200;
        }
        return white;
    };
    std::string err;
    const size_t plain = whitePixels(false, nullptr), shadowed = whitePixels(true, &err);
    EXPECT_LE(shadowed, plain + 20) << "the shadow is white";
    EXPECT_NE(err.find("display lists that blend inside other than by GL_SRC_ALPHA"),
              std::string::npos)
        << err;
}

// demo_displaylist draws its state and its plate with one glCallLists. The compositor and
// the tracker must agree on holding it: when the tracker held the plate while the compositor
// let the call through, the plate was drawn twice, the program's own grey fighting in depth
// with the style's (stripes). Under gooch (whose tones never equal the program's lit grey),
// no pixel of the program's plate colour may remain.
TEST(Compositor, ListsCalledTogetherAreDrawnOnce)
{
    const std::string native = freshDir("lists_native"), gooch = freshDir("lists_gooch");
    const std::vector<std::string> app = {demo("displaylist"), "--offscreen", "--frames", "3",
                                          "--size", "256x192", "--save-frames", "3",
                                          "--save-dir"};
    std::vector<std::string> a = {nprglCommand(), "--style", "none", "--"};
    a.insert(a.end(), app.begin(), app.end());
    a.push_back(native);
    std::vector<std::string> b = {nprglCommand(), "--style", "gooch", "--"};
    b.insert(b.end(), app.begin(), app.end());
    b.push_back(gooch);
    ProcessResult ra = runProcess(a), rb = runProcess(b);
    ASSERT_EQ(ra.exitCode, 0) << ra.err;
    ASSERT_EQ(rb.exitCode, 0) << rb.err;
    PngImage plain, styled;
    std::string error;
    ASSERT_TRUE(PngImage::read(native + "/displaylist_3.png", plain, error)) << error;
    ASSERT_TRUE(PngImage::read(gooch + "/displaylist_3.png", styled, error)) << error;
    ASSERT_EQ(plain.rgba.size(), styled.rgba.size());
    // The plate's colour natively: the most common colour that is not the black background.
    std::map<uint32_t, size_t> counts;
    for (size_t i = 0; i < plain.rgba.size(); i += 4) {
        const uint32_t c = uint32_t(plain.rgba[i]) << 16 | uint32_t(plain.rgba[i + 1]) << 8 |
                           plain.rgba[i + 2];
        if (c != 0) ++counts[c];
    }
    ASSERT_FALSE(counts.empty());
    const auto plate = std::max_element(counts.begin(), counts.end(), [](auto& x, auto& y) {
        return x.second < y.second;
    });
    ASSERT_GT(plate->second, 256u * 192u / 10) << "the plate is not where it was";
    size_t left = 0;
    for (size_t i = 0; i < styled.rgba.size(); i += 4) {
        const uint32_t c = uint32_t(styled.rgba[i]) << 16 | uint32_t(styled.rgba[i + 1]) << 8 |
                           styled.rgba[i + 2];
        left += c == plate->first;
    }
    EXPECT_EQ(left, 0u) << "pixels of the program's own plate under gooch";
}

// A program may turn glFrontFace between the batches of one object, each culled by its own
// front face: xscreensaver's involute gears (moebiusgears) wind each ring and face their own
// way. The styles culled the whole object by its first batch's winding and lost the other
// batches' front faces (gears with missing faces). demo_displaylist --clockwise-fronts draws
// its gears' front faces clockwise under glFrontFace(GL_CW), the same picture as without:
// styled, it must stay the same picture too.
TEST(Compositor, BatchesCulledByTheirOwnFrontFaceKeepTheirFaces)
{
    for (const char* style : {"none", "toon"}) {
        const std::string name = std::string("clockwise_fronts_") + style;
        const std::string plain = demoFrame("displaylist", name, {"--style", style}, {});
        const std::string turned =
            demoFrame("displaylist", name + "_turned", {"--style", style}, {"--clockwise-fronts"});
        ImageDiff diff = compareImages(plain, turned, 24);
        ASSERT_TRUE(diff.comparable) << diff.error;
        EXPECT_LT(diff.differingPixels, 320u * 240u / 200) << style << ": faces were lost";
    }
}

// GL leaves to the implementation which diagonal cuts a quad into two triangles, and Mesa cuts
// glBegin/glEnd quads along v0-v2 but indexed ones and display lists' along v1-v3. The replica
// cuts each as the driver does: three quads with a colour per corner (red, green, white,
// blue) show red and white meeting at the centre of the first, green and blue at the centre of
// the other two, natively and in replica (the replica cut all three along v0-v2: pulsar's
// listed quads came out with the wrong colours across their middles).
TEST(Compositor, TheReplicaCutsQuadsAlongTheDiagonalTheDriverDoes)
{
    const PngImage native =
        readPng(demoFrame("displaylist", "quad_cut_none", {"--style", "none"}, {"--corner-quads"}));
    const PngImage replica = readPng(
        demoFrame("displaylist", "quad_cut_replica", {"--style", "replica"}, {"--corner-quads"}));
    ASSERT_FALSE(native.rgba.empty() || replica.rgba.empty());
    const bool redCentre[3] = {true, false, false};
    for (int q = 0; q < 3; ++q) {
        const int x = 58 + 102 * q, y = 120; // the quads' centres at 320 x 240
        const uint8_t* n = pixel(native, x, y);
        const uint8_t* r = pixel(replica, x, y);
        // Red there is 255 where red (v0) and white (v2) meet, 0 where green and blue do.
        EXPECT_EQ(n[0] > 128, redCentre[q]) << "quad " << q << ": the driver cuts otherwise";
        EXPECT_NEAR(r[0], n[0], 24) << "quad " << q;
        EXPECT_NEAR(r[1], n[1], 24) << "quad " << q;
        EXPECT_NEAR(r[2], n[2], 24) << "quad " << q;
    }
}

// glxgears turns its gears by the time between frames, and its first frame has had none:
// frame 1 shows the gears at angle 0 in every run, so style none and toon can be compared.
TEST(Compositor, GlxgearsInToonKeepsItsRedGreenAndBlueGears)
{
    if (!std::getenv("DISPLAY") || !*std::getenv("DISPLAY")) GTEST_SKIP() << "no DISPLAY";
    const std::string plain = freshDir("glxgears_none"), toon = freshDir("glxgears_toon");
    ProcessResult n = runUntilFile({nprglCommand(), "--style", "none", "--screenshot",
                                    "frames=1;dir=" + plain, "--", "glxgears"},
                                   {}, plain + "/glxgears_1.png");
    ASSERT_TRUE(n.stopped) << n.err;
    ProcessResult t = runUntilFile({nprglCommand(), "--style", "toon", "--screenshot",
                                    "frames=1,20;dir=" + toon, "--", "glxgears"},
                                   {}, toon + "/glxgears_20.png");
    ASSERT_TRUE(t.stopped) << t.err;
    EXPECT_EQ(t.err.find("nprgl: error"), std::string::npos) << t.err;
    expectGlxgearsPicture(toon + "/glxgears_1.png");
    expectGlxgearsPicture(toon + "/glxgears_20.png");
    // The same gears, shaded in bands instead of by the program's lighting. The bands follow
    // GL's own light (toon.bands=program), so they differ from it only where GL grades the
    // light (the teeth's sides, the green gear's top: about 5% of the window); a frame left
    // as the program drew it differs nowhere.
    ImageDiff diff = compareImages(plain + "/glxgears_1.png", toon + "/glxgears_1.png", 24);
    ASSERT_TRUE(diff.comparable) << diff.error;
    EXPECT_GT(diff.differingPixels, 300u * 300u / 50) << "toon left glxgears as it was";
}

struct DemoCase {
    std::string app;
    std::vector<std::string> args;
};

void PrintTo(const DemoCase& c, std::ostream* os) { *os << c.app; }

class DefaultStyle : public ::testing::TestWithParam<DemoCase> {};

namespace {

int channelDelta(const PngImage& a, const PngImage& b, size_t i)
{
    return std::abs(a.rgba[i] - b.rgba[i]) + std::abs(a.rgba[i + 1] - b.rgba[i + 1]) +
           std::abs(a.rgba[i + 2] - b.rgba[i + 2]);
}

// The program's drawing: pixels of the native frame away from its most common colour.
std::vector<bool> drawnMask(const PngImage& native)
{
    std::map<uint32_t, size_t> histogram;
    for (size_t i = 0; i < native.rgba.size(); i += 4) {
        ++histogram[uint32_t(native.rgba[i]) << 16 | uint32_t(native.rgba[i + 1]) << 8 |
                    native.rgba[i + 2]];
    }
    const uint32_t bg =
        std::max_element(histogram.begin(), histogram.end(), [](const auto& a, const auto& b) {
            return a.second < b.second;
        })->first;
    std::vector<bool> mask(native.rgba.size() / 4);
    for (size_t i = 0; i < native.rgba.size(); i += 4) {
        const int delta = std::abs(native.rgba[i] - int(bg >> 16)) +
                          std::abs(native.rgba[i + 1] - int(bg >> 8 & 255)) +
                          std::abs(native.rgba[i + 2] - int(bg & 255));
        mask[i / 4] = delta > 24;
    }
    return mask;
}

} // namespace

// With no configuration at all: every demo app (lit or not, with or without normals,
// textured, overlays, the character) runs under the default chain, prints what it prints
// natively, and its picture is the chain's: the toon shading covers what the program drew
// (not the paper), and the edges add ink to toon+paper.
TEST_P(DefaultStyle, EveryDemoAppRunsAndIsStylised)
{
    const DemoCase& c = GetParam();
    if (c.app == "character" && !fs::exists("/usr/share/assimp/models/X/Testwuson.X")) {
        GTEST_SKIP() << "assimp-testmodels is not installed";
    }
    std::vector<std::string> args = {demo(c.app), "--offscreen", "--frames", "3", "--size",
                                     "160x120", "--save-frames", "3"};
    args.insert(args.end(), c.args.begin(), c.args.end());
    const std::string file = "/" + c.app + "_3.png";
    // chain "" is the default (no style set anywhere); "native" runs without nprgl.
    // `settings`: --set values for the run.
    auto run = [&](const std::string& chain, PngImage& image,
                   const std::vector<std::string>& settings = {}) {
        const std::string dir = freshDir("default_" + c.app);
        std::vector<std::string> argv;
        if (chain != "native") {
            argv = {nprglCommand()};
            if (!chain.empty()) argv.insert(argv.end(), {"--style", chain});
            for (const std::string& s : settings) argv.insert(argv.end(), {"--set", s});
            argv.push_back("--");
        }
        argv.insert(argv.end(), args.begin(), args.end());
        argv.insert(argv.end(), {"--save-dir", dir});
        ProcessResult r =
            runProcess(argv, {{"NPRGL_STYLE", ""}, {"NPRGL_CONFIG", ""}, {"NPRGL_PRESET", ""}});
        std::string error;
        EXPECT_TRUE(PngImage::read(dir + file, image, error)) << chain << ": " << error;
        return r;
    };
    PngImage native, styled, inked, inkless, paperOnly;
    ProcessResult a = run("native", native);
    ProcessResult b = run("", styled);
    ASSERT_EQ(a.exitCode, 0) << a.err;
    ASSERT_EQ(b.exitCode, 0) << b.err;
    EXPECT_EQ(b.out, a.out);
    EXPECT_EQ(b.err.find("nprgl: error"), std::string::npos) << b.err;
    EXPECT_EQ(b.err.find("nprgl: warning"), std::string::npos) << b.err;
    // The ink is what the default chain adds to toon+paper. Live, a texture's drawing is made
    // off the frame, so the frame that first shows it depends on speed (a slow ASan run drew
    // it in one of the two runs only): both draw the program's textures.
    const std::vector<std::string> programsTextures = {"toon.texture_detail=1"};
    ASSERT_EQ(run("", inked, programsTextures).exitCode, 0);
    ASSERT_EQ(run("toon+paper", inkless, programsTextures).exitCode, 0);
    ASSERT_EQ(run("paper", paperOnly).exitCode, 0);
    ASSERT_EQ(native.rgba.size(), styled.rgba.size());
    ASSERT_EQ(inked.rgba.size(), styled.rgba.size());
    ASSERT_EQ(inkless.rgba.size(), styled.rgba.size());
    ASSERT_EQ(paperOnly.rgba.size(), styled.rgba.size());

    // Toon redrew what the program drew: there, the frame is not paper alone's (the
    // program's own shading on paper) ...
    const std::vector<bool> drawn = drawnMask(native);
    size_t covered = 0, redrawn = 0, vivid = 0, vividKept = 0;
    auto chroma = [](const PngImage& image, size_t i) {
        const auto [lo, hi] = std::minmax({image.rgba[i], image.rgba[i + 1], image.rgba[i + 2]});
        return int(hi) - int(lo);
    };
    auto dominant = [](const PngImage& image, size_t i) {
        return std::max_element(&image.rgba[i], &image.rgba[i] + 3) - &image.rgba[i];
    };
    for (size_t i = 0; i < styled.rgba.size(); i += 4) {
        if (!drawn[i / 4]) continue;
        ++covered;
        redrawn += channelDelta(styled, paperOnly, i) > 24;
        // ... and nothing was lost: where the program drew a vivid colour, the frame keeps
        // a vivid colour of the same hue (a missing object shows paper or what was behind).
        if (chroma(native, i) < 60) continue;
        ++vivid;
        vividKept += chroma(styled, i) >= 40 && dominant(styled, i) == dominant(native, i);
    }
    ASSERT_GT(covered, 160u * 120u / 50) << "the program drew almost nothing";
    // Measured with toon working: redrawn 11-98% of the drawing (overlay's 11.5% the least: a
    // few small shapes, which toon's half band draws close to GL's own shading), vivid
    // colours kept 58-96%; paper alone: 0% redrawn; toon drawing nothing: 0% kept on all but
    // the demos whose vivid pixels are mostly 2D (overlay, state).
    EXPECT_GT(redrawn * 100, covered * 5) << "the program's drawing is as it drew it: no toon";
    if (vivid * 20 >= covered) {
        EXPECT_GE(vividKept * 10, vivid * 4)
            << "the program's objects are missing: toon drew nothing";
    }
    // What the program drew changed (its background may not: a dark page is about the
    // colour of a program's own dark background).
    size_t changed = 0;
    for (size_t i = 0; i < styled.rgba.size(); i += 4) {
        changed += drawn[i / 4] && channelDelta(native, styled, i) > 24;
    }
    EXPECT_GT(changed * 10, covered) << "the default style changed too little";

    // The edges' share: ink that toon+paper alone does not have, against the page: dark ink
    // on a light page, light ink on the dark page of a program that clears to black.
    auto sum = [](const PngImage& image, size_t i) {
        return int(image.rgba[i]) + image.rgba[i + 1] + image.rgba[i + 2];
    };
    uint64_t pageSum = 0, pagePixels = 0;
    for (size_t i = 0; i < styled.rgba.size(); i += 4) {
        if (drawn[i / 4]) continue;
        pageSum += uint64_t(sum(styled, i));
        ++pagePixels;
    }
    ASSERT_GT(pagePixels, 0u) << "the program drew everywhere: no page to judge the ink by";
    const bool darkPage = pageSum < pagePixels * 3 * 128;
    size_t inkPixels = 0, contrasting = 0;
    for (size_t i = 0; i < inked.rgba.size(); i += 4) {
        if (channelDelta(inked, inkless, i) <= 24) continue;
        ++inkPixels;
        contrasting +=
            darkPage ? sum(inked, i) > sum(inkless, i) : sum(inked, i) < sum(inkless, i);
    }
    EXPECT_GT(inkPixels, 160u * 120u / 200) << "the edges drew no ink";
    EXPECT_GE(contrasting * 10, inkPixels * 8)
        << "what the edges added is not ink of the page's contrast ("
        << (darkPage ? "dark" : "light") << " page)";
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
    [](const auto& p) { return p.param.app + std::to_string(p.index); });

// A surface on generated texture coordinates (glTexGen on unit 0) is styled like any other:
// no draw is left, and the draws after it (texgen off again) keep their own textures. Stripes
// projected on GL_OBJECT_LINEAR or GL_EYE_LINEAR planes are the sphere's own texture, on
// coordinates the style generates as GL does: where the program has them. Stripes reflected
// by GL_SPHERE_MAP are dropped (the surface's colour tinted by the texture's mean, no
// stripes) unless toon.reflections asks for them: then they are back, where the program has
// them.
class GeneratedCoordinates : public ::testing::TestWithParam<std::vector<std::string>> {};

TEST_P(GeneratedCoordinates, AreStyledWithoutTheirTextureUnlessAsked)
{
    const std::string name = "texgen" + std::to_string(GetParam().size()) + GetParam().back();
    const std::string native = freshDir(name + "_native"), toon = freshDir(name + "_toon");
    const std::string shown = freshDir(name + "_reflections");
    std::vector<std::string> app = {demo("textured")};
    app.insert(app.end(), GetParam().begin(), GetParam().end());
    for (const char* a : {"--offscreen", "--size", "320x240", "--frames", "3", "--save-frames",
                          "3", "--save-dir"}) {
        app.push_back(a);
    }
    auto with = [](std::vector<std::string> v, const std::string& dir) {
        v.push_back(dir);
        return v;
    };
    ProcessResult n = runProcess(under({nprglCommand(), "--style", "none"}, with(app, native)));
    ASSERT_EQ(n.exitCode, 0) << n.err;
    // The thesis's bands (by L.n alone): bands by GL's light follow the normal as a sphere
    // map's stripes do, and would read as stripes where there are none.
    ProcessResult t = runProcess(under(
        {nprglCommand(), "--style", "toon", "--set", "toon.bands=thesis"}, with(app, toon)));
    ASSERT_EQ(t.exitCode, 0) << t.err;
    EXPECT_NE(t.err.find("styled, 0 left as the program drew them"), std::string::npos) << t.err;
    ProcessResult r = runProcess(under(
        {nprglCommand(), "--style", "toon", "--set", "toon.reflections=1"}, with(app, shown)));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    PngImage a, b, c;
    std::string error;
    ASSERT_TRUE(PngImage::read(native + "/textured_3.png", a, error)) << error;
    ASSERT_TRUE(PngImage::read(toon + "/textured_3.png", b, error)) << error;
    ASSERT_TRUE(PngImage::read(shown + "/textured_3.png", c, error)) << error;
    // The sphere's middle (right half of the frame, above the floor's far edge): orange
    // stripes natively, the white material's tones styled.
    int orangeNative = 0, orangeStyled = 0, orangeShown = 0, orangeBoth = 0;
    // The styled picture's blue where the program's stripes are orange, and where not: alike
    // when the styled sphere has no stripes.
    double blueOnStripes = 0.0, blueOff = 0.0;
    double warmth = 0.0; // red over blue, styled
    for (int y = 100; y < 150; ++y) {
        for (int x = 190; x < 230; ++x) {
            const size_t i = (size_t(y) * a.width + x) * 4;
            auto orange = [&](const PngImage& im) {
                return im.rgba[i] > 150 && im.rgba[i] - im.rgba[i + 2] > 90;
            };
            orangeNative += orange(a);
            orangeStyled += orange(b);
            orangeShown += orange(c);
            orangeBoth += orange(a) && orange(c);
            (orange(a) ? blueOnStripes : blueOff) += b.rgba[i + 2];
            warmth += int(b.rgba[i]) - int(b.rgba[i + 2]);
        }
    }
    EXPECT_GT(orangeNative, 300) << "the demo's sphere is not where the test looks";
    if (GetParam().front() == "--sphere-map") {
        const int off = 50 * 40 - orangeNative;
        ASSERT_GT(off, 100);
        EXPECT_NEAR(blueOnStripes / orangeNative, blueOff / off, 12.0)
            << "the reflection's stripes were taken for the sphere's own texture";
        // Its average tint stays: the white sphere is as warm as its orange and white stripes.
        EXPECT_GT(warmth / (50 * 40), 30.0) << "the reflection's mean tint was dropped";
    } else {
        EXPECT_GT(orangeStyled, 300) << "the projected texture was dropped";
    }
    EXPECT_GT(orangeShown, 300) << "toon.reflections did not show the generated texture";
    // On the program's coordinates: the stripes lie where the program's lie.
    EXPECT_GT(orangeBoth * 10, orangeNative * 7) << "the stripes are elsewhere";
    EXPECT_GT(orangeBoth * 10, orangeShown * 7) << "the stripes are elsewhere";
    // The cube's red checks, drawn after texgen went off, are still red.
    int red = 0;
    for (int y = 100; y < 170; ++y) {
        for (int x = 80; x < 140; ++x) {
            const size_t i = (size_t(y) * b.width + x) * 4;
            red += b.rgba[i] > 150 && b.rgba[i + 1] < 90 && b.rgba[i + 2] < 90;
        }
    }
    EXPECT_GT(red, 200) << "the cube lost its texture";
}

INSTANTIATE_TEST_SUITE_P(Modes, GeneratedCoordinates,
                         ::testing::Values(std::vector<std::string>{"--sphere-map"},
                                           std::vector<std::string>{"--linear-map", "object"},
                                           std::vector<std::string>{"--linear-map", "eye"},
                                           std::vector<std::string>{"--linear-map", "object",
                                                                    "--texgen-matrix"}),
                         [](const auto& p) {
                             return p.param.size() == 1   ? std::string("SphereMap")
                                    : p.param.size() == 3 ? std::string("ByTheTextureMatrix")
                                    : p.param[1] == "object" ? std::string("ObjectLinear")
                                                             : std::string("EyeLinear");
                         });

// A cube whose faces have their own textures (six glBegin/glEnd between glBindTexture calls,
// one object): each face keeps its texture when styled, not the first face's on all six.
TEST(Compositor, EachFaceOfAnObjectKeepsItsOwnTexture)
{
    const std::string native = freshDir("faces_native"), toon = freshDir("faces_toon");
    auto app = [](const std::string& dir) {
        return std::vector<std::string>{demo("textured"), "--face-textures", "--offscreen",
                                        "--size", "320x240", "--frames", "20",
                                        "--save-frames", "20", "--save-dir", dir};
    };
    ProcessResult n = runProcess(under({nprglCommand(), "--style", "none"}, app(native)));
    ASSERT_EQ(n.exitCode, 0) << n.err;
    ProcessResult t = runProcess(under({nprglCommand(), "--style", "toon"}, app(toon)));
    ASSERT_EQ(t.exitCode, 0) << t.err;
    PngImage a, b;
    std::string error;
    ASSERT_TRUE(PngImage::read(native + "/textured_20.png", a, error)) << error;
    ASSERT_TRUE(PngImage::read(toon + "/textured_20.png", b, error)) << error;
    // Pixels of the cube (left of the frame's middle) by the hue of the face textures' checks
    // that face the camera in frame 20: blue, green, magenta.
    auto count = [](const PngImage& im) {
        std::array<int, 3> hues{};
        for (int y = 80; y < 190; ++y) {
            for (int x = 55; x < 165; ++x) {
                const uint8_t* p = pixel(im, x, y);
                const int r = p[0], g = p[1], bl = p[2];
                hues[0] += bl > r + 60 && bl > g + 40;  // blue
                hues[1] += g > 2 * r + 20 && g > 2 * bl + 20; // green, also in a shadow band
                hues[2] += r > 2 * g + 20 && bl > 2 * g + 20 && std::abs(r - bl) < 20; // magenta
            }
        }
        return hues;
    };
    const std::array<int, 3> want = count(a), got = count(b);
    for (int i = 0; i < 3; ++i) {
        EXPECT_GT(want[i], 150) << "colour " << i << ": the cube is not where the test looks";
        EXPECT_GT(got[i], want[i] / 2) << "colour " << i << " lost when styled";
    }
}

// Display lists compiled from vertex arrays (glDrawElements/glDrawArrays inside glNewList,
// replayed with glCallList) are styled with the arrays' own colours and normals, as the list
// holds them, not with the current colour at the call (which painted them flat grey). The
// demo enables its client arrays inside the list (GL_COMPILE), as xscreensaver's glknots
// does: GL runs client state at once, so the draws compile from them (the tracker used to
// keep those calls for later and saw no arrays: nothing styled, nothing counted).
TEST(Compositor, ListsCompiledFromArraysKeepTheArraysColoursAndNormals)
{
    const std::string native = freshDir("arraylist_native"), toon = freshDir("arraylist_toon");
    auto app = [](const std::string& dir) {
        return std::vector<std::string>{demo("arrays"), "--list", "--offscreen", "--size",
                                        "320x240", "--frames", "4", "--save-frames", "4",
                                        "--save-dir", dir};
    };
    ProcessResult n = runProcess(under({nprglCommand(), "--style", "none"}, app(native)));
    ASSERT_EQ(n.exitCode, 0) << n.err;
    ProcessResult t = runProcess(under({nprglCommand(), "--style", "toon"}, app(toon)));
    ASSERT_EQ(t.exitCode, 0) << t.err;
    EXPECT_NE(t.err.find(" styled, 0 left as the program drew them"), std::string::npos) << t.err;
    PngImage a, b;
    std::string error;
    ASSERT_TRUE(PngImage::read(native + "/arrays_4.png", a, error)) << error;
    ASSERT_TRUE(PngImage::read(toon + "/arrays_4.png", b, error)) << error;
    auto blue = [](const PngImage& im) {
        int count = 0;
        for (size_t i = 0; i < im.rgba.size(); i += 4) {
            count += im.rgba[i + 2] > im.rgba[i] + 60 && im.rgba[i + 2] > 120;
        }
        return count;
    };
    EXPECT_GT(blue(a), 5000) << "the demo's surface is not blue";
    EXPECT_GT(blue(b), blue(a) / 2) << "the surface lost its colours in the list";
    const ImageDiff diff = compareImages(native + "/arrays_4.png", toon + "/arrays_4.png", 24);
    ASSERT_TRUE(diff.comparable) << diff.error;
    EXPECT_GT(diff.differingPixels, 1000u) << "the list was not styled";
}

// The coverage style: styled objects in colours of their own, never red; a 3D draw left as
// the program draws it (here a sphere added to the scene, GL_ONE, GL_ONE) all red, also over
// the light tint of a styled object, and counted with its reason.
TEST(Compositor, TheCoverageStylePaintsWhatIsLeftRed)
{
    const std::string dir = freshDir("coverage");
    ProcessResult r = runProcess(under({nprglCommand(), "--style", "coverage"},
                                       {demo("textured"), "--additive", "--offscreen",
                                        "--size", "320x240", "--frames", "3", "--save-frames",
                                        "3", "--save-dir", dir}));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("left as the program drew them (blending other than"), std::string::npos)
        << r.err;
    PngImage image;
    std::string error;
    ASSERT_TRUE(PngImage::read(dir + "/textured_3.png", image, error)) << error;
    auto redIn = [&](int x0, int y0, int x1, int y1) {
        int red = 0, all = 0;
        for (int y = y0; y < y1; ++y) {
            for (int x = x0; x < x1; ++x) {
                const uint8_t* p = pixel(image, x, y);
                // Laid over what is behind by its alpha (added, it read pink over the floor's
                // light tint); no colour of the styled objects reaches 250 in red.
                red += p[0] >= 250 && p[1] < 60 && p[2] < 60;
                ++all;
            }
        }
        return float(red) / float(all);
    };
    EXPECT_GT(redIn(190, 110, 225, 145), 0.95f) << "the glowing sphere is not red";
    EXPECT_GT(redIn(195, 130, 220, 155), 0.95f) << "the glow is not red over the floor";
    EXPECT_LT(redIn(85, 110, 135, 160), 0.01f) << "the styled cube is red";
    EXPECT_LT(redIn(20, 200, 300, 235), 0.01f) << "the styled floor is red";
}

// An additive glow (the demo's sphere, GL_ONE, GL_ONE) on a paper page is drawn as ink of its
// colour: not washed out to the page's white, as it is added natively and over a chain
// without a page; still counted as left (its geometry is the program's drawing). On a dark
// page (paper.tone=dark, or auto over the demo's black) it adds light as natively. Also with
// the program's alpha test on (gibson's glowing towers of text): the ink's fragments carry
// the program's alpha, which the test passes (they carried none, and every one was dropped).
class AdditiveGlows : public ::testing::TestWithParam<bool> {};

TEST_P(AdditiveGlows, ReadOverPaper)
{
    // The share of the sphere's square washed out to white, and how many of its pixels show
    // its orange stripes (added natively; in ink of their colour on the page).
    auto whiteInSphere = [](const std::string& style, const char* tone, int* orange = nullptr) {
        const std::string dir = freshDir("glow");
        std::vector<std::string> app = {demo("textured"), "--additive", "--offscreen",
                                        "--size", "320x240", "--frames", "3", "--save-frames",
                                        "3", "--save-dir", dir};
        if (GetParam()) app.push_back("--glow-alpha-test");
        ProcessResult r = runProcess(
            under({nprglCommand(), "--style", style, "--set", std::string("paper.tone=") + tone},
                  app));
        EXPECT_EQ(r.exitCode, 0) << r.err;
        EXPECT_NE(r.err.find("left as the program drew them (blending other than"),
                  std::string::npos)
            << r.err;
        EXPECT_EQ(r.err.find("drawn as ink") != std::string::npos,
                  style.find("paper") != std::string::npos && std::string(tone) == "light")
            << r.err;
        PngImage image;
        std::string error;
        EXPECT_TRUE(PngImage::read(dir + "/textured_3.png", image, error)) << error;
        int white = 0, all = 0, stripes = 0;
        for (int y = 110; y < 145; ++y) {
            for (int x = 190; x < 225; ++x) {
                const uint8_t* p = pixel(image, x, y);
                white += std::min({p[0], p[1], p[2]}) >= 225;
                stripes += p[0] > 150 && p[0] - p[2] > 60;
                ++all;
            }
        }
        if (orange) *orange = stripes;
        return float(white) / float(all);
    };
    EXPECT_GT(whiteInSphere("toon", "light"), 0.3f) << "the glow does not wash out here: no test";
    int orange = 0;
    EXPECT_LT(whiteInSphere("toon+paper", "light", &orange), 0.05f)
        << "the glow washed out on the page";
    EXPECT_GT(orange, 300) << "the glow is not on the page";
    EXPECT_GT(whiteInSphere("toon+paper", "dark"), 0.3f) << "the glow was inked on a dark page";
}

INSTANTIATE_TEST_SUITE_P(Compositor, AdditiveGlows, ::testing::Bool(),
                         [](const auto& p) {
                             return std::string(p.param ? "AlphaTested" : "Plain");
                         });

// A glow drawn from a display list that turns texturing off inside it (gibson's towers: their
// faces plain, their glyphs textured, each in lists of their own) is inked in its own plain
// colour. The ink's texturing is set once a call, from the state before the list, and sampled
// the texture still bound there: the blue sphere came out in the orange and white stripes of
// that texture, and on a dark floor as black. And nothing of nprgl's own is compiled into a
// list the program compiles (the ink's set-up was, with every strip of the sphere).
TEST(Compositor, AGlowListTurningItsTextureOffIsInkedPlain)
{
    const std::string dir = freshDir("glowlist");
    ProcessResult r = runProcess(
        under({nprglCommand(), "--style", "toon+paper", "--set", "paper.tone=light"},
              {demo("textured"), "--additive", "--glow-list-plain", "--offscreen", "--size",
               "320x240", "--frames", "3", "--save-frames", "3", "--save-dir", dir}));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    ASSERT_NE(r.err.find("drawn as ink"), std::string::npos) << r.err;
    // Compiled in frame 1 under the glow's state: nprgl's ink set-up was compiled into the
    // program's list with its 24 strips (each counted as a draw left, though GL_COMPILE draws
    // nothing). Now one call a frame, the strips inside it as the list's.
    EXPECT_NE(r.err.find("3D polygon draws: 6 styled, 3 left"), std::string::npos) << r.err;
    PngImage image;
    std::string error;
    ASSERT_TRUE(PngImage::read(dir + "/textured_3.png", image, error)) << error;
    int blue = 0, all = 0;
    for (int y = 115; y < 140; ++y) {
        for (int x = 195; x < 220; ++x) {
            const uint8_t* p = pixel(image, x, y);
            blue += p[2] > p[0] + 60 && p[2] > p[1] + 40;
            ++all;
        }
    }
    EXPECT_GT(blue, all * 9 / 10) << blue << " of " << all << " pixels in the glow's blue";
}

// A scene drawn again under a scissor after a scissored clear (a rear-view mirror, a 3D pane
// in a tool's window): the styled redraw stays inside the scissor box, so everything outside
// it is the picture without the inset, and the page is laid again where the program cleared
// (a clear counts even when the page was already laid this frame).
TEST(Compositor, AScissoredInsetStaysInItsBoxAndGetsItsOwnPage)
{
    auto run = [](bool inset) {
        const std::string dir = freshDir("inset");
        std::vector<std::string> args = {
            demo("textured"), "--offscreen", "--size",     "320x240", "--frames", "3",
            "--save-frames",  "3",           "--save-dir", dir};
        if (inset) args.push_back("--inset");
        ProcessResult r = runProcess(under(
            {nprglCommand(), "--style", "toon+paper+edges", "--set", "paper.tone=light"}, args));
        EXPECT_EQ(r.exitCode, 0) << r.err;
        PngImage image;
        std::string error;
        EXPECT_TRUE(PngImage::read(dir + "/textured_3.png", image, error)) << error;
        return image;
    };
    const PngImage plain = run(false);
    const PngImage inset = run(true);
    ASSERT_EQ(plain.width, 320);
    ASSERT_EQ(inset.width, 320);
    // Rows top first: the inset is x >= 160, y < 120.
    int outsideDiffer = 0, insideDiffer = 0;
    for (int y = 0; y < 240; ++y) {
        for (int x = 0; x < 320; ++x) {
            const size_t i = (size_t(y) * 320 + x) * 4;
            const bool differs = std::memcmp(&plain.rgba[i], &inset.rgba[i], 3) != 0;
            (x >= 160 && y < 120 ? insideDiffer : outsideDiffer) += differs;
        }
    }
    EXPECT_EQ(outsideDiffer, 0) << "the inset's styled scene spilled out of its scissor box";
    EXPECT_GT(insideDiffer, 1000) << "the inset was not drawn";
    // Its top right corner is background: paper (f4efe1), not the clear colour (26, 26, 31).
    const uint8_t* corner = &inset.rgba[(size_t(2) * 320 + 317) * 4];
    EXPECT_NEAR(corner[0], 0xf4, 8);
    EXPECT_NEAR(corner[1], 0xef, 8);
    EXPECT_NEAR(corner[2], 0xe1, 8);
}

// A translucent surface (GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, depth writes off) is styled and
// drawn over the styled scene with the program's blending: what is behind it shows through.
TEST(Compositor, TranslucentSurfacesAreStyledAndBlendedOverTheScene)
{
    auto run = [](const std::string& name, const std::string& style, bool translucent) {
        const std::string dir = freshDir(name);
        std::vector<std::string> app = {demo("textured"), "--offscreen", "--size", "320x240",
                                        "--frames", "3", "--save-frames", "3", "--save-dir", dir};
        if (translucent) app.push_back("--translucent");
        ProcessResult r = runProcess(under({nprglCommand(), "--style", style}, app));
        EXPECT_EQ(r.exitCode, 0) << r.err;
        if (style != "none") {
            EXPECT_NE(r.err.find(" styled, 0 left as the program drew them"), std::string::npos)
                << r.err;
        }
        return dir + "/textured_3.png";
    };
    const std::string glass = run("glass_toon", "toon", true);
    const std::string solid = run("solid_toon", "toon", false);
    const std::string native = run("glass_native", "none", true);
    PngImage a, b, c;
    std::string error;
    ASSERT_TRUE(PngImage::read(glass, a, error)) << error;
    ASSERT_TRUE(PngImage::read(solid, b, error)) << error;
    ASSERT_TRUE(PngImage::read(native, c, error)) << error;
    // The sphere's middle, right of the frame's centre.
    auto share = [](const PngImage& x, const PngImage& y) {
        int n = 0, all = 0;
        for (int row = 110; row < 145; ++row) {
            for (int col = 190; col < 225; ++col) {
                const size_t i = (size_t(row) * x.width + col) * 4;
                int d = 0;
                for (int k = 0; k < 3; ++k) d += std::abs(int(x.rgba[i + k]) - int(y.rgba[i + k]));
                n += d > 24;
                ++all;
            }
        }
        return float(n) / float(all);
    };
    EXPECT_GT(share(a, b), 0.5f) << "the styled sphere is not translucent";
    EXPECT_GT(share(a, c), 0.3f) << "the translucent sphere is not styled";
}

// Cut-outs: a cube whose texture has round holes (alpha 0) drawn with the alpha test keeps its
// holes when styled: the floor shows through them as it does natively, and not when the same
// cube has no holes.
TEST(Compositor, AlphaTestedCutOutsKeepTheirHoles)
{
    auto run = [](const std::string& name, const std::string& style, bool cutout) {
        const std::string dir = freshDir(name);
        std::vector<std::string> app = {demo("textured"), "--offscreen", "--size", "320x240",
                                        "--frames", "3", "--save-frames", "3", "--save-dir", dir};
        if (cutout) app.push_back("--cutout");
        ProcessResult r = runProcess(under({nprglCommand(), "--style", style}, app));
        EXPECT_EQ(r.exitCode, 0) << r.err;
        if (style != "none") {
            EXPECT_NE(r.err.find(" styled, 0 left as the program drew them"), std::string::npos)
                << r.err;
        }
        PngImage image;
        std::string error;
        EXPECT_TRUE(PngImage::read(dir + "/textured_3.png", image, error)) << error;
        // Floor blue around and through the cube (left of the frame's middle).
        int blue = 0;
        for (int y = 90; y < 180 && !image.rgba.empty(); ++y) {
            for (int x = 75; x < 150; ++x) {
                const uint8_t* p = pixel(image, x, y);
                blue += p[2] > p[0] + 60 && p[2] > p[1] + 30;
            }
        }
        return blue;
    };
    const int native = run("cutout_native", "none", true);
    const int styled = run("cutout_toon", "toon", true);
    const int solid = run("solid_cube_toon", "toon", false);
    EXPECT_GT(native, solid + 150) << "the demo's holes do not show the floor";
    EXPECT_GT(styled, solid + 150) << "the styled cube lost its holes";
    EXPECT_NEAR(styled, native, native / 5);
}

// The pencil preset draws no fills of its own colour, only hatching on paper over the
// surfaces and strokes along them: a cut-out is hatched where the program's texture and alpha
// test keep it, and its holes show the floor's drawing behind, not the faces' hatching (it
// hatched whole quads, as if solid, and stroked their edges).
TEST(Compositor, PencilHatchesCutOutsInTheirShape)
{
    auto run = [](const std::string& name, bool cutout) {
        return demoFrame("textured", name, {"--preset", "pencil"},
                         cutout ? std::vector<std::string>{"--cutout"} : std::vector<std::string>{});
    };
    const ImageDiff diff = compareImages(run("pencil_solid", false), run("pencil_cutout", true), 24);
    ASSERT_TRUE(diff.comparable) << diff.error;
    EXPECT_GT(diff.differingPixels, 1000u) << "the cut-out cube is drawn as a solid one";
}

// A first-person weapon (demo_textured --weapon): a cube far behind the scene, drawn in a
// depth range of its own (glDepthRange 0 to 0.1) so that it is in front of everything, as
// ioquake3 draws its gun. The styles draw it in that range too: in the shading chain it
// changes the styled picture about as much as the native one (drawn with the full range, the
// scene's cube and sphere hid most of it); the pencil, which hatches over the program's own
// depth, hatches it (missing that depth, it left the program's red checks).
TEST(Compositor, AWeaponInADepthRangeOfItsOwnStaysInFront)
{
    auto run = [](const std::string& style, bool weapon) {
        return demoFrame("textured", "weapon_" + style + (weapon ? "_on" : "_off"),
                         {"--style", style},
                         weapon ? std::vector<std::string>{"--weapon"} : std::vector<std::string>{});
    };
    auto changed = [&](const std::string& style) {
        const ImageDiff diff = compareImages(run(style, false), run(style, true), 24);
        EXPECT_TRUE(diff.comparable) << diff.error;
        return diff.differingPixels;
    };
    const size_t native = changed("none");
    EXPECT_GT(native, 3000u) << "the weapon is not in the picture";
    EXPECT_GT(changed("toon+edges"), native * 8 / 10);
    auto redPixels = [](const std::string& path) {
        PngImage image;
        std::string error;
        EXPECT_TRUE(PngImage::read(path, image, error)) << error;
        int red = 0;
        for (size_t i = 0; i < image.rgba.size(); i += 4) {
            red += image.rgba[i] > 150 && image.rgba[i + 1] < 90 && image.rgba[i + 2] < 90;
        }
        return red;
    };
    EXPECT_GT(redPixels(run("none", true)), 1000) << "the weapon's checks are not red";
    EXPECT_LT(redPixels(run("pencil+paper", true)), 50) << "the pencil left the weapon as drawn";
}

// Every enabled GL light shades the styled scene, as GL sums their diffuse light: demo_immediate
// --light1 adds a white light as bright as its first, from the lower right. In toon the far
// sides of the shapes come out of the shadow band (with the brightest light alone, they would
// not: the two white lights leave the colours' hue as it was). A spot aimed away from the
// shapes lights none of them, as in GL; aimed at them, it does.
TEST(Compositor, EveryEnabledLightShadesTheStyledScene)
{
    auto run = [](const std::string& style, const std::string& light1) {
        std::vector<std::string> extra;
        if (!light1.empty()) extra = {"--light1", light1};
        return demoFrame("immediate", "light1_" + style + "_" + (light1.empty() ? "off" : light1),
                         {"--style", style}, extra);
    };
    const ImageDiff native = compareImages(run("none", ""), run("none", "directional"), 24);
    ASSERT_TRUE(native.comparable) << native.error;
    EXPECT_GT(native.differingPixels, 2000u) << "the second light lights nothing natively";

    // Styled, a light changes the picture where it moves a band boundary (toon's bands follow
    // GL's own light), a little less than natively: about 2,000 pixels here; none if lost.
    const std::string alone = run("toon", "");
    const ImageDiff second = compareImages(alone, run("toon", "directional"), 24);
    ASSERT_TRUE(second.comparable) << second.error;
    EXPECT_GT(second.differingPixels, 1500u) << "the second light is not in the styled shading";

    const ImageDiff away = compareImages(alone, run("toon", "spot-away"), 24);
    ASSERT_TRUE(away.comparable) << away.error;
    EXPECT_EQ(away.differingPixels, 0u) << "a spot aimed away from the shapes lit them";
    const ImageDiff at = compareImages(alone, run("toon", "spot"), 24);
    ASSERT_TRUE(at.comparable) << at.error;
    EXPECT_GT(at.differingPixels, 1500u) << "a spot aimed at the shapes lit nothing";
}

// Pixels the program copies into a texture are that texture's content, not the window's
// page: foobillardplus draws each ball's surroundings into a corner of the window, copies them
// into a cube map, clears, and adds the map over the ball (GL_ONE_MINUS_DST_COLOR, GL_ONE).
// Paper laid in the corner went into the maps and washed every ball white. demo_textured
// --env-map copies its scene from a 64x64 corner and shows the texture at the top left: its
// corners, background when copied, keep the program's clear colour. With --env-map-line a
// line the styles leave is drawn over the corner before the copy: it flushes the scene before
// the copy does, and that flush laid the page (glblur's blurred copies of its scene were
// paper-coloured): a viewport the program copied into a texture before gets no page either.
TEST(Compositor, PixelsCopiedIntoATextureGetNoPage)
{
    auto corner = [](const std::string& style, bool line) {
        PngImage image;
        std::string error;
        std::vector<std::string> args = {"--env-map"};
        if (line) args.push_back("--env-map-line");
        // A light page: it differs from the dark clear colour (a dark page would not).
        EXPECT_TRUE(PngImage::read(demoFrame("textured",
                                             std::string("env_map_") + (line ? "line_" : "") +
                                                 style,
                                             {"--style", style, "--set", "paper.tone=light"},
                                             args),
                                   image, error))
            << error;
        std::vector<int> out;
        for (auto [x, y] : {std::pair{2, 2}, std::pair{61, 2}, std::pair{2, 61}}) {
            if (image.rgba.empty()) break;
            const uint8_t* p = &image.rgba[(size_t(y) * image.width + x) * 4];
            out.insert(out.end(), {p[0], p[1], p[2]});
        }
        return out;
    };
    for (bool line : {false, true}) {
        const std::vector<int> native = corner("none", line);
        ASSERT_EQ(native.size(), 9u);
        EXPECT_LT(native[0], 100) << "the copied corner is not the dark clear colour: no test";
        const std::vector<int> styled = corner("toon+paper+edges", line);
        ASSERT_EQ(styled.size(), 9u);
        for (size_t i = 0; i < 9; ++i) {
            EXPECT_NEAR(styled[i], native[i], 12)
                << (line ? "with the line: " : "") << "channel " << i % 3 << " of corner "
                << i / 3;
        }
    }
}

// A backdrop drawn at the far plane with the depth test on (xscreensaver's atlantis draws its
// water so: identity matrices, z = 1, GL_LEQUAL) keeps the cleared depth, and the page, laid
// after the opaque scene where that depth remains, covered it: the program's backdrop became
// paper. Such a flush lays its page first, and the backdrop is drawn over it.
TEST(Compositor, ABackdropAtTheFarPlaneIsNotPaper)
{
    // The three corners' colours, one int a channel.
    auto corners = [](const std::string& style) {
        PngImage image;
        std::string error;
        EXPECT_TRUE(PngImage::read(demoFrame("textured", "far_backdrop_" + style,
                                             {"--style", style}, {"--far-backdrop"}),
                                   image, error))
            << error;
        std::vector<int> out;
        for (auto [x, y] : {std::pair{4, 4}, std::pair{315, 4}, std::pair{4, 235}}) {
            if (image.rgba.empty()) break;
            const uint8_t* p = pixel(image, x, y);
            out.insert(out.end(), {p[0], p[1], p[2]});
        }
        return out;
    };
    const std::vector<int> native = corners("none");
    ASSERT_EQ(native.size(), 9u);
    EXPECT_GT(native[2], 120) << "no blue backdrop natively: no test";
    for (const char* style : {"toon+paper+edges", "paper"}) {
        const std::vector<int> styled = corners(style);
        ASSERT_EQ(styled.size(), 9u);
        for (size_t i = 0; i < 9; ++i) {
            EXPECT_NEAR(styled[i], native[i], 24) << style << ": corner " << i / 3 << " is paper";
        }
    }
}

// A texture drawn with GL_REPLACE shows its own colours, not the lit or current colour's
// (timetunnel's tunnel under a yellow glColor came out yellow-green): demo_textured --replace
// draws its white and red cube under a blue material. The white checks stay white (or grey in
// the shadow band) in the shading styles (without paper, which is near white itself);
// modulated by the material they were blue.
TEST(Compositor, AReplacingTextureShowsItsOwnColours)
{
    auto whiteChecks = [](const std::string& style) {
        PngImage image;
        std::string error;
        EXPECT_TRUE(PngImage::read(demoFrame("textured", "replace_" + style, {"--style", style},
                                             {"--replace"}),
                                   image, error))
            << error;
        int white = 0;
        for (int y = 80; y < 190 && !image.rgba.empty(); ++y) {
            for (int x = 40; x < 160; ++x) {
                const uint8_t* p = pixel(image, x, y);
                white += p[0] > 90 && std::abs(p[0] - p[2]) < 30 && std::abs(p[1] - p[2]) < 30;
            }
        }
        return white;
    };
    const int native = whiteChecks("none");
    EXPECT_GT(native, 1500) << "the cube's white checks are not there natively: no test";
    for (const char* style : {"toon", "textured"}) {
        EXPECT_GT(whiteChecks(style), native / 2) << style << ": the material tints the texture";
    }
}

// The program's fog (linear, 6 to 11 units, pale) is applied to the styled colours: the far
// floor fades into the fog colour as it does natively, and does not without fog.
TEST(Compositor, TheProgramsFogFadesTheStyledScene)
{
    auto distance = [](const std::string& style, bool fog, int x0, int y0, int x1, int y1) {
        const std::string dir = freshDir("fog_" + style);
        std::vector<std::string> app = {demo("textured"), "--offscreen", "--size", "320x240",
                                        "--frames", "3", "--save-frames", "3", "--save-dir", dir};
        if (fog) app.push_back("--fog");
        ProcessResult r = runProcess(under({nprglCommand(), "--style", style}, app));
        EXPECT_EQ(r.exitCode, 0) << r.err;
        PngImage image;
        std::string error;
        EXPECT_TRUE(PngImage::read(dir + "/textured_3.png", image, error)) << error;
        if (image.rgba.empty()) return 0.0;
        // Mean distance (sum over channels) from the demo's fog colour 0.7, 0.72, 0.78.
        const int fogColour[3] = {178, 184, 199};
        double sum = 0.0;
        int n = 0;
        for (int y = y0; y < y1; ++y) {
            for (int x = x0; x < x1; ++x) {
                const uint8_t* p = pixel(image, x, y);
                for (int c = 0; c < 3; ++c) sum += std::abs(p[c] - fogColour[c]);
                ++n;
            }
        }
        return sum / n;
    };
    // The floor's far edge between the cube and the sphere, and a nearer patch.
    EXPECT_LT(distance("none", true, 145, 119, 170, 123), 20.0) << "the demo has no fog there";
    EXPECT_LT(distance("toon", true, 145, 119, 170, 123), 60.0) << "the styled floor is unfogged";
    EXPECT_GT(distance("toon", false, 145, 119, 170, 123), 120.0);
    EXPECT_NEAR(distance("toon", true, 60, 160, 75, 170), distance("none", true, 60, 160, 75, 170),
                40.0);
}

// A depth pre-pass (the scene with the colour mask off, then its colours at GL_LEQUAL) is
// styled as the scene alone: the pre-pass supplies depth only, nothing is drawn twice and the
// styled surfaces do not fight the pre-pass's depth (which striped them).
TEST(Compositor, DepthOnlyPassesSupplyDepthAndNothingElse)
{
    auto run = [](const std::string& name, bool prepass) {
        std::string log;
        const std::string frame = demoFrame(
            "textured", name, {"--style", "toon+edges"},
            prepass ? std::vector<std::string>{"--depth-prepass"} : std::vector<std::string>{},
            &log);
        EXPECT_NE(log.find(" styled, 0 left as the program drew them"), std::string::npos) << log;
        return frame;
    };
    const ImageDiff diff = compareImages(run("prepass_off", false), run("prepass_on", true), 24);
    ASSERT_TRUE(diff.comparable) << diff.error;
    EXPECT_LT(diff.differingPixels, 320u * 240u / 200u) << "the pre-pass changed the picture";
}

// A square drawn into depth alone before the scene (an occluder: razzledazzle draws its ship so
// and its sky and sea around it) hides the scene behind it, as natively: the hole shows the
// clear colour. The styles drew depth-only objects after the scene, and the hole was filled.
TEST(Compositor, ADepthOnlyOccluderHidesWhatIsDrawnBehindIt)
{
    auto centre = [](const std::string& style) {
        const PngImage image = readPng(demoFrame("textured", "occluder_" + style,
                                                 {"--style", style}, {"--depth-occluder"}));
        if (image.rgba.empty()) return std::vector<int>{};
        const uint8_t* p = pixel(image, 160, 120);
        return std::vector<int>{p[0], p[1], p[2]};
    };
    const PngImage plain = readPng(demoFrame("textured", "occluder_off", {"--style", "none"}, {}));
    ASSERT_FALSE(plain.rgba.empty());
    const uint8_t* scene = pixel(plain, 160, 120);
    const std::vector<int> native = centre("none");
    ASSERT_EQ(native.size(), 3u);
    ASSERT_GT(std::abs(native[0] - scene[0]) + std::abs(native[1] - scene[1]) +
                  std::abs(native[2] - scene[2]),
              60)
        << "the scene does not differ from the hole natively: no test";
    const std::vector<int> styled = centre("toon");
    ASSERT_EQ(styled.size(), 3u);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(styled[size_t(c)], native[size_t(c)], 8) << c;
}

// A depth-only pass drawn after the surfaces it covers (squirtorus masks its ground so) changes
// nothing natively; drawn before the scene it tied with them in depth and hid them (black
// rings on squirtorus's sand): it stays after the opaque scene.
TEST(Compositor, ADepthOnlyPassAfterItsSurfacesChangesNothing)
{
    auto run = [](const std::string& name, bool after) {
        return demoFrame("textured", name, {"--style", "toon"},
                         after ? std::vector<std::string>{"--depth-after"}
                               : std::vector<std::string>{});
    };
    const ImageDiff natively =
        compareImages(demoFrame("textured", "after_none", {"--style", "none"}, {}),
                      demoFrame("textured", "after_none_on", {"--style", "none"}, {"--depth-after"}),
                      8);
    ASSERT_TRUE(natively.comparable) << natively.error;
    ASSERT_EQ(natively.differingPixels, 0u) << "the pass changes the picture natively: no test";
    const ImageDiff diff = compareImages(run("after_off", false), run("after_on", true), 24);
    ASSERT_TRUE(diff.comparable) << diff.error;
    EXPECT_LT(diff.differingPixels, 320u * 240u / 200u) << "the depth-only pass hid the floor";
}

// A decal: a yellow square in the floor's plane, kept in front of it by glPolygonOffset. The
// styled decal is whole, as it is natively, not striped by the floor fighting it.
// A translucent decal (blended by its alpha, no depth writes, as neverball paints its goal
// and arrows) is drawn after the opaque scene with its offset too (it vanished into the floor).
TEST(Compositor, DecalsStayOnTheirSurface)
{
    auto yellowShare = [](const std::string& name, const std::string& style,
                          const std::string& decal = "--decal") {
        PngImage image;
        std::string error;
        EXPECT_TRUE(PngImage::read(demoFrame("textured", name, {"--style", style}, {decal}),
                                   image, error))
            << error;
        int yellow = 0, all = 0;
        for (int y = 198; y < 225 && !image.rgba.empty(); ++y) {
            for (int x = 142; x < 182; ++x) {
                const uint8_t* p = pixel(image, x, y);
                yellow += p[0] > 150 && p[1] > 110 && p[2] < 90;
                ++all;
            }
        }
        return float(yellow) / float(std::max(all, 1));
    };
    EXPECT_GT(yellowShare("decal_native", "none"), 0.95f) << "the decal is not where we look";
    EXPECT_GT(yellowShare("decal_toon", "toon+edges"), 0.95f) << "the floor fights the decal";
    EXPECT_GT(yellowShare("glass_decal_native", "none", "--translucent-decal"), 0.95f);
    EXPECT_GT(yellowShare("glass_decal_toon", "toon+edges", "--translucent-decal"), 0.95f)
        << "the translucent decal sank into the floor";
}

// A state rule (leave_state=translucent, from the program's configuration file, and given to
// a replay with --rules): the demo's translucent sphere is left as the program draws it (the
// coverage style paints it red, the log gives the rule as the reason); the opaque cube and
// floor stay styled. Without the rule the sphere is styled (never red).
TEST(Compositor, AStateRuleLeavesTheDrawsInThatState)
{
    const std::string rules = freshDir("state_rules") + "/rules.conf";
    std::ofstream(rules) << "leave_state=translucent\n";
    auto redShare = [](const std::string& path, int x0, int y0, int x1, int y1) {
        PngImage image;
        std::string error;
        EXPECT_TRUE(PngImage::read(path, image, error)) << error;
        int red = 0, all = 0;
        for (int y = y0; y < y1 && !image.rgba.empty(); ++y) {
            for (int x = x0; x < x1; ++x) {
                // A left translucent draw is fog-red blended by its alpha (0.6) over the page.
                const uint8_t* p = pixel(image, x, y);
                red += p[0] >= 200 && p[1] < 90 && p[2] < 90;
                ++all;
            }
        }
        return float(red) / float(std::max(all, 1));
    };
    const std::string dir = freshDir("state_rule_live");
    ProcessResult r = runProcess(under({nprglCommand(), "--style", "coverage"},
                                       {demo("textured"), "--translucent", "--offscreen",
                                        "--size", "320x240", "--frames", "3", "--save-frames",
                                        "3", "--save-dir", dir}),
                                 {{"NPRGL_CONFIG_FILE", rules}});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("(leave_texture, leave_state)"), std::string::npos) << r.err;
    const std::string plain = demoFrame("textured", "state_rule_none", {"--style", "coverage"},
                                        {"--translucent"});
    // The sphere (right of the middle), the cube (left) and the floor (bottom).
    EXPECT_GT(redShare(dir + "/textured_3.png", 190, 110, 225, 145), 0.95f);
    EXPECT_LT(redShare(plain, 190, 110, 225, 145), 0.01f) << "styled without the rule";
    EXPECT_LT(redShare(dir + "/textured_3.png", 85, 110, 135, 160), 0.01f) << "the cube";
    EXPECT_LT(redShare(dir + "/textured_3.png", 20, 200, 300, 235), 0.01f) << "the floor";

    // A replay of a recording, given the file.
    const std::string rec = freshDir("state_rule_rec");
    ProcessResult recorded = runProcess(
        under({nprglCommand(), "record", "--style", "none", "-o", rec + "/t.nprgl"},
              {demo("textured"), "--translucent", "--offscreen", "--size", "320x240",
               "--frames", "3"}));
    ASSERT_EQ(recorded.exitCode, 0) << recorded.err;
    ProcessResult replayed =
        runProcess({nprglCommand(), "replay", rec + "/t.nprgl", "-o", rec + "/out", "--frames",
                    "3", "--style", "coverage", "--rules", rules});
    ASSERT_EQ(replayed.exitCode, 0) << replayed.err;
    EXPECT_GT(redShare(framePng(rec + "/out", 3), 190, 110, 225, 145), 0.95f) << replayed.err;
}

// A multi-pass surface: --shine draws an object a second time over the same vertices,
// adding light (GL_ONE, GL_ONE), as ioquake3 draws a shader's stages: demo_arrays with an
// array draw, demo_immediate with glBegin/glEnd, demo_displaylist by calling the list again.
// The pass is merged into the styled object: the styled picture is the one without the pass
// (nothing drawn twice), the coverage style paints none of it red, and the counts say so.
// Natively the pass does add light (else the test would prove nothing).
class MultiPass : public ::testing::TestWithParam<std::string> {};

TEST_P(MultiPass, ABlendedSecondPassIsMergedIntoItsObject)
{
    const std::string app = GetParam();
    auto run = [&](const std::string& style, bool shine, std::string* log = nullptr) {
        return demoFrame(app, "shine_" + app + "_" + style + (shine ? "_on" : "_off"),
                         {"--style", style},
                         shine ? std::vector<std::string>{"--shine"} : std::vector<std::string>{},
                         log);
    };
    const ImageDiff native = compareImages(run("none", false), run("none", true), 24);
    ASSERT_TRUE(native.comparable) << native.error;
    EXPECT_GT(native.differingPixels, 1000u) << "the pass adds no light natively";

    std::string log;
    const ImageDiff styled =
        compareImages(run("toon+paper+edges", false), run("toon+paper+edges", true, &log), 24);
    ASSERT_TRUE(styled.comparable) << styled.error;
    EXPECT_EQ(styled.differingPixels, 0u) << "the pass was drawn over the styled object";
    EXPECT_NE(log.find("passes merged into their object), 0 left"), std::string::npos) << log;

    PngImage image;
    std::string error;
    ASSERT_TRUE(PngImage::read(run("coverage", true, &log), image, error)) << error;
    int red = 0;
    for (size_t i = 0; i < image.rgba.size(); i += 4) red += image.rgba[i] >= 250;
    EXPECT_EQ(red, 0) << "the pass was left as the program draws it";
}

INSTANTIATE_TEST_SUITE_P(Compositor, MultiPass,
                         ::testing::Values("arrays", "immediate", "displaylist"),
                         [](const auto& param) { return param.param; });

// A program that draws with alpha writes off (glColorMask(1, 1, 1, 0): briquolo, every
// frame) draws its whole picture: it is styled (it was all left as "a partial colour mask"),
// and the styles keep the destination alpha the program keeps (cleared to 0.25 here), which
// the demo reads back at five points after its scene.
TEST(Compositor, AProgramMaskingOnlyAlphaIsStyledAndKeepsItsAlpha)
{
    for (const char* style : {"toon+paper+edges", "halftone+paper+edges", "pencil"}) {
        ProcessResult r = runProcess(under({nprglCommand(), "--style", style},
                                           {demo("textured"), "--offscreen", "--alpha-mask",
                                            "--frames", "3", "--size", "320x240"}));
        ASSERT_EQ(r.exitCode, 0) << r.err;
        EXPECT_NE(r.err.find(" styled, 0 left as the program drew them"), std::string::npos)
            << style << ": " << r.err;
        EXPECT_NE(r.out.find("alpha frame 3: 64 64 64 64 64"), std::string::npos)
            << style << ": " << r.out;
    }
}

// A cut-out (demo_textured --cutout: round holes in the cube's faces by its texture's alpha
// and the alpha test) is outlined along its cut: the edge style draws its attributes where
// the program's test keeps its texture, so its silhouette and the rims of its holes get ink.
// It got none before (a cut-out's polygons are not its shape, so it was left out).
namespace {

// Ink (near-black pixels) in the box of demo_textured's cube in frame 3 at 320x240, run with
// `extra` under `style` (the cut-out's holes show the dark background, not black).
int cubeInk(const std::string& name, const std::string& style,
            const std::vector<std::string>& extra)
{
    // Black ink (a light page's): counted by its darkness.
    const PngImage image = readPng(
        demoFrame("textured", name, {"--style", style, "--set", "paper.tone=light"}, extra));
    int n = 0;
    for (int y = 85; y < 180 && !image.rgba.empty(); ++y) {
        for (int x = 75; x < 150; ++x) {
            const uint8_t* p = pixel(image, x, y);
            n += std::max({p[0], p[1], p[2]}) < 20;
        }
    }
    return n;
}

} // namespace

TEST(Compositor, CutOutsAreOutlinedAlongTheirCuts)
{
    auto ink = [](const std::string& name, const std::string& style,
                  const std::vector<std::string>& extra = {"--cutout"}) {
        return cubeInk(name, style, extra);
    };
    EXPECT_EQ(ink("cutout_toon", "toon"), 0) << "toon alone draws no ink";
    EXPECT_GT(ink("cutout_edges", "toon+edges"), 800) << "the cut-out cube has no outlines";
    // Blended as well, with depth writes (foliage with soft rims): the same shape.
    EXPECT_GT(ink("cutout_blend_edges", "toon+edges", {"--cutout", "--cutout-blend"}), 800)
        << "the blended cut-out cube has no outlines";
}

TEST(Compositor, AnObjectPushedBackByItsOffsetIsOutlined)
{
    // A positive polygon offset pushes the cube away (megaglest draws all its models so):
    // not a decal lifted over a surface, whose lines would fight it. Without the rule it got
    // no line at all.
    EXPECT_EQ(cubeInk("pushed_toon", "toon", {"--pushed-back"}), 0) << "toon alone draws no ink";
    EXPECT_GT(cubeInk("pushed_edges", "toon+edges", {"--pushed-back"}), 300)
        << "the cube pushed back by its offset has no outlines";
}

TEST(Compositor, AFineCutOutIsNotSwampedByInk)
{
    // A grille of bars and holes about two pixels across on screen: lines one pixel each side
    // of every bar would turn it into a mesh of ink (3,053 dark pixels in the cube's box when
    // it was outlined along its cut). Its cut gets no lines; the floor's far edge behind it
    // shows through the holes.
    EXPECT_LT(cubeInk("grille_edges", "toon+edges", {"--cutout-fine"}), 300)
        << "the fine grille is swamped by ink";
}
