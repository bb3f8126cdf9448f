// Real programs nobody here wrote: Debian's xscreensaver GL hacks (package xscreensaver-gl),
// each run under Xvfb for 40 frames in the coverage style (styled objects in their own
// colours, every 3D draw left as the program draws it in red). For each: no crash, and the
// share of the drawn pixels of frame 40 that nprgl styled; the hacks nprgl cannot style yet
// must say why in the log. Figures and what is left: docs/compat.md. Hacks that pick their
// look at random (jigglypuff: sometimes wireframe) are not in the list: a test must not
// depend on a coin toss.

#include "common/PngImage.h"
#include "tests/support/ImageCompare.h"
#include "tests/support/Process.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

using namespace nprgl;
using namespace nprgl::test;

namespace {

const std::string kHacks = "/usr/libexec/xscreensaver/";

struct CompatCase {
    std::string program;
    // Empty: at least 90% of the drawn pixels styled. Else the reason the log must give for
    // what is left (and the share is only recorded).
    std::string leftBecause;
    // Games: where the program is, its arguments into its 3D scene, the frame looked at and
    // the context that draws it (SDL programs draw with their second).
    std::string path = kHacks;
    std::vector<std::string> args = {"-window"};
    int frame = 40;
    std::string context;
    std::string executable; // its name in the screenshots, when a script runs it (empty: program)
    bool quits = false;     // ends by itself (its arguments say when): its exit status is 0

    CompatCase(std::string name, std::string left)
        : program(std::move(name)), leftBecause(std::move(left))
    {
    }
    CompatCase(std::string name, std::string left, std::string where, std::vector<std::string> with,
               int at, std::string drawnBy)
        : program(std::move(name)), leftBecause(std::move(left)), path(std::move(where)),
          args(std::move(with)), frame(at), context(std::move(drawnBy))
    {
    }
};

std::ostream& operator<<(std::ostream& os, const CompatCase& c) { return os << c.program; }

// Drawn pixels: those unlike the clear colour (the frame's top-left corner). Left: red the
// coverage style added (a left draw is all fog-red; over anything, red saturates).
double styledShare(const PngImage& image, int& drawn)
{
    const uint8_t* bg = image.rgba.data();
    int left = 0;
    drawn = 0;
    for (size_t i = 0; i + 3 < image.rgba.size(); i += 4) {
        const uint8_t* p = &image.rgba[i];
        if (std::abs(p[0] - bg[0]) + std::abs(p[1] - bg[1]) + std::abs(p[2] - bg[2]) <= 12) {
            continue;
        }
        ++drawn;
        left += p[0] >= 250 && p[1] < 200;
    }
    return drawn ? 1.0 - double(left) / drawn : 0.0;
}

// Reads a run's screenshot and measures the styled share of its drawn pixels (recorded as a
// test property and printed).
void measureStyledShare(const std::string& shot, const std::string& name, double& share)
{
    PngImage image;
    std::string error;
    ASSERT_TRUE(PngImage::read(shot, image, error)) << error;
    int drawn = 0;
    share = styledShare(image, drawn);
    ASSERT_GT(drawn, 500) << name << " drew (almost) nothing";
    ::testing::Test::RecordProperty("styled_share", std::to_string(share));
    std::printf("compat: %-14s %6d drawn pixels, %5.1f%% styled\n", name.c_str(), drawn,
                100.0 * share);
}

class Compat : public ::testing::TestWithParam<CompatCase> {};

} // namespace

TEST_P(Compat, RunsStyledAndSaysWhatIsLeft)
{
    const CompatCase& c = GetParam();
    const std::string program = c.path + c.program;
    if (!std::filesystem::exists(program)) {
        GTEST_SKIP() << program << " is not installed (scripts/install-deps.sh installs it)";
    }
    const std::string dir = freshDir("compat_" + c.program);
    const std::string frame = std::to_string(c.frame);
    const std::string shown = c.executable.empty() ? c.program : c.executable;
    const std::string shot = dir + "/" + shown + c.context + "_" + frame + ".png";
    std::vector<std::string> command = {program};
    command.insert(command.end(), c.args.begin(), c.args.end());
    // They run until told to stop (or quit where their arguments say); the run lasts its
    // frames however fast the machine is. A home of their own: no settings of an earlier run.
    const std::map<std::string, std::string> env = {
        {"NPRGL_SCREENSHOT", "frames=" + frame + ";dir=" + dir},
        {"HOME", freshDir("compat_home_" + c.program)}};
    const std::vector<std::string> argv = under({nprglCommand(), "--style", "coverage"}, command);
    ProcessResult r = c.quits ? runProcess(argv, env) : runUntilFile(argv, env, shot, SIGTERM);
    if (c.quits) {
        EXPECT_EQ(r.exitCode, 0) << r.err.substr(0, 2000);
        ASSERT_TRUE(std::filesystem::exists(shot)) << "no frame " << frame;
    } else {
        ASSERT_TRUE(r.stopped) << "no frame " << frame << ": " << r.err.substr(0, 2000);
        EXPECT_TRUE(r.exitCode == 0 || r.exitCode == 128 + SIGTERM) << "exit " << r.exitCode << "\n"
                                                                    << r.err.substr(0, 2000);
    }
    EXPECT_EQ(r.err.find("nprgl: error"), std::string::npos) << r.err.substr(0, 2000);
    double share = 0.0;
    ASSERT_NO_FATAL_FAILURE(measureStyledShare(shot, c.program, share));
    if (c.leftBecause.empty()) {
        EXPECT_GE(share, 0.9) << c.program << ": " << r.err.substr(0, 2000);
    } else {
        EXPECT_NE(r.err.find("drawn with " + c.leftBecause), std::string::npos)
            << c.program << " should say why it is left: " << r.err.substr(0, 2000);
    }
}

INSTANTIATE_TEST_SUITE_P(
    XscreensaverGl, Compat,
    ::testing::Values(
        CompatCase{"antinspect", ""}, CompatCase{"cubestorm", ""}, CompatCase{"engine", ""},
        CompatCase{"gears", ""}, CompatCase{"geodesic", ""}, CompatCase{"glknots", ""},
        CompatCase{"glsnake", ""}, CompatCase{"molecule", ""}, CompatCase{"morph3d", ""},
        CompatCase{"pipes", ""}, CompatCase{"polyhedra", ""}, CompatCase{"sierpinski3d", ""},
        CompatCase{"superquadrics", ""}, CompatCase{"topblock", ""},
        // Its own shaders ignore the coverage tint: its pixels cannot tell, the log does.
        CompatCase{"hypertorus", "the program's own shaders"},
        CompatCase{"blinkbox", "blending other than GL_SRC_ALPHA"},
        CompatCase{"stonerview", "blending other than GL_SRC_ALPHA"},
        CompatCase{"moebius", "glPolygonMode lines or points"}),
    [](const auto& param) { return param.param.program; });

CompatCase openArena()
{
    CompatCase c("openarena", "", "/usr/games/",
                 {"+set",    "r_mode",         "-1",      "+set", "r_customwidth", "640",
                  "+set",    "r_customheight", "480",     "+set", "r_fullscreen",  "0",
                  "+set",    "cl_renderer",    "opengl1", "+set", "s_initsound",   "0",
                  "+devmap", "oa_dm1",         "+wait",   "800",  "+quit"},
                 250, "_ctx2");
    c.executable = "ioquake3";
    c.quits = true; // "wait" counts the engine's frames: 800 of them draw more than 250
    return c;
}

// Games from Debian, brought into their 3D scene by their own arguments.
INSTANTIATE_TEST_SUITE_P(
    Games, Compat,
    ::testing::Values(
        // A level: its floor, coins, ball and backdrop styled (the rails, drawn through
        // texture combiners only, are left and said).
        CompatCase{"neverball", "", "/usr/games/", {"-l", "map-easy/coins.sol"}, 100, "_ctx2"},
        // A map (+devmap) in a window, with its first renderer (fixed function; the second is
        // GLSL); the world's lightmaps give the styles their light; the gun's shine layers
        // (additive passes over its own vertices) merge into it. Spawn points vary: the
        // view does too.
        openArena()),
    [](const auto& param) { return param.param.program; });

// extremetuxracer reaches its race through its menus: five Returns (the player, the main
// menu's practice, the course, the race settings, go), each sent once nprgl has written the
// frame before it, on a 640x480 display of its own (etr takes the whole screen). Its sound
// goes to OpenAL's null device: without a sound card etr floods stderr with OpenAL errors
// (gigabytes in a minute) and now and then crashes on its own, with or without nprgl.
TEST(GamesDriven, ExtremeTuxRacerRacesStyled)
{
    const std::string program = "/usr/games/etr";
    if (!std::filesystem::exists(program) || !std::filesystem::exists("/usr/bin/xdotool")) {
        GTEST_SKIP() << "needs extremetuxracer and xdotool (scripts/install-deps.sh)";
    }
    const std::string dir = freshDir("compat_etr");
    const std::string source = NPRGL_TEST_SOURCE_DIR;
    const std::map<std::string, std::string> env = {
        {"NPRGL_SCREENSHOT", "frames=50,100,150,200,250,600;dir=" + dir},
        {"HOME", freshDir("compat_home_etr")},
        {"ALSOFT_DRIVERS", "null"},
        {"WITH_DISPLAY_SIZE", "640x480"}};
    const std::vector<std::string> argv = {
        source + "/../scripts/with-display.sh", source + "/compat/drive-keys.sh", dir, "etr_ctx2",
        "600", "50:Return 100:Return 150:Return 200:Return 250:Return", "--", nprglCommand(),
        "--style", "coverage", "--", program};
    ProcessResult r = runProcess(argv, env);
    ASSERT_EQ(r.exitCode, 0) << r.err.substr(0, 3000);
    EXPECT_EQ(r.err.find("nprgl: error"), std::string::npos) << r.err.substr(0, 2000);
    double share = 0.0;
    ASSERT_NO_FATAL_FAILURE(measureStyledShare(dir + "/etr_ctx2_600.png", "etr", share));
    EXPECT_GE(share, 0.9) << r.err.substr(0, 2000);
    // In the race: its slope, trees and Tux (the menus are 2D and would be all background).
    EXPECT_NE(r.err.find("3D polygons drawn with"), std::string::npos) << r.err.substr(0, 2000);
}

// A game's apitrace trace replayed by glretrace under nprgl with style none draws what it
// draws natively: the same pixels at the same frames (a replay is deterministic, a live game
// is not). openarena into its map, traced once here (no trace file is kept in the repository).
TEST(Traces, StyleNoneReplaysAGameAsNative)
{
    const CompatCase game = openArena();
    const std::string program = game.path + game.program;
    if (!std::filesystem::exists(program) || !std::filesystem::exists("/usr/bin/apitrace") ||
        !std::filesystem::exists("/usr/bin/glretrace")) {
        GTEST_SKIP() << "needs openarena and apitrace (scripts/install-deps.sh installs both)";
    }
    const std::string dir = freshDir("trace_openarena");
    std::vector<std::string> trace = {"apitrace",          "trace", "--api", "gl", "-o",
                                      dir + "/game.trace", program};
    trace.insert(trace.end(), game.args.begin(), game.args.end());
    ProcessResult traced = runProcess(trace, {{"HOME", freshDir("trace_home")}});
    ASSERT_EQ(traced.exitCode, 0) << traced.err.substr(0, 2000);
    auto replay = [&](const std::string& name, bool underNprgl) {
        std::filesystem::create_directories(dir + "/" + name);
        // Every 100th frame, named by frame (--snapshot takes call numbers, which land in the
        // black frames of the loading screen).
        const std::vector<std::string> retrace = {
            "glretrace", "--snapshot-prefix=" + dir + "/" + name + "/", "--snapshot-interval=100",
            "--call-nos=false", dir + "/game.trace"};
        ProcessResult r =
            runProcess(underNprgl ? under({nprglCommand(), "--style", "none"}, retrace) : retrace);
        EXPECT_EQ(r.exitCode, 0) << name << ": " << r.err.substr(0, 2000);
    };
    replay("native", false);
    replay("none", true);
    for (const char* frame : {"0000000200.png", "0000000300.png"}) {
        const ImageDiff diff = compareImages(dir + "/native/" + frame, dir + "/none/" + frame);
        ASSERT_TRUE(diff.comparable) << diff.error;
        EXPECT_EQ(diff.differingPixels, 0u) << frame;
        // The map, not a black loading frame: most pixels lit.
        PngImage image;
        std::string error;
        ASSERT_TRUE(PngImage::read(dir + "/native/" + frame, image, error)) << error;
        size_t lit = 0;
        for (size_t i = 0; i + 3 < image.rgba.size(); i += 4) {
            lit += std::max({image.rgba[i], image.rgba[i + 1], image.rgba[i + 2]}) > 12;
        }
        EXPECT_GT(lit, image.rgba.size() / 4 / 2) << frame << " is mostly black";
    }
}

// crack-attack (a GLUT game): Return starts a solo game, then its board of lit blocks rises.
// Its text is GL_ALPHA textures drawn blended without the depth test (they vanished in every
// shading style until 2026-11-25).
TEST(GamesDriven, CrackAttackPlaysStyled)
{
    const std::string program = "/usr/games/crack-attack";
    if (!std::filesystem::exists(program) || !std::filesystem::exists("/usr/bin/xdotool")) {
        GTEST_SKIP() << "needs crack-attack and xdotool (scripts/install-deps.sh)";
    }
    const std::string dir = freshDir("compat_crack_attack");
    const std::string source = NPRGL_TEST_SOURCE_DIR;
    const std::map<std::string, std::string> env = {
        {"NPRGL_SCREENSHOT", "frames=100,600;dir=" + dir},
        {"HOME", freshDir("compat_home_crack_attack")},
        {"SDL_AUDIODRIVER", "dummy"}};
    const std::vector<std::string> argv = {
        source + "/../scripts/with-display.sh", source + "/compat/drive-keys.sh", dir,
        "crack-attack", "600", "100:Return", "--", nprglCommand(), "--style", "coverage", "--",
        program, "--solo"};
    ProcessResult r = runProcess(argv, env);
    ASSERT_EQ(r.exitCode, 0) << r.err.substr(0, 3000);
    EXPECT_EQ(r.err.find("nprgl: error"), std::string::npos) << r.err.substr(0, 2000);
    double share = 0.0;
    ASSERT_NO_FATAL_FAILURE(
        measureStyledShare(dir + "/crack-attack_600.png", "crack-attack", share));
    EXPECT_GE(share, 0.9) << r.err.substr(0, 2000);
}
