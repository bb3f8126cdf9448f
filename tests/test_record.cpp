// End to end: `nprgl record`, `replay`, `dump` and `info` on the demo apps, glxgears and the
// committed fixtures; programs stopped by signals or _exit; damaged files.

#include "common/PngImage.h"
#include "tests/support/ImageCompare.h"
#include "tests/support/Process.h"

#include <gtest/gtest.h>

#include <csignal>
#include <fcntl.h>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

using namespace nprgl;
using namespace nprgl::test;
namespace fs = std::filesystem;

namespace {

void expectSameFrames(const std::string& liveDir, const std::string& app,
                      const std::string& replayDir, int frames)
{
    for (int f = 1; f <= frames; ++f) {
        ImageDiff diff = compareImages(liveDir + "/" + app + "_" + std::to_string(f) + ".png",
                                       framePng(replayDir, f));
        ASSERT_TRUE(diff.comparable) << diff.error;
        EXPECT_EQ(diff.differingPixels, 0u) << app << " frame " << f;
    }
}

struct RecordCase {
    std::string app;
    std::vector<std::string> args;
    bool offscreen;
};

void PrintTo(const RecordCase& c, std::ostream* os)
{
    *os << c.app << (c.offscreen ? " offscreen" : " glx");
    for (const std::string& a : c.args) *os << " " << a;
}

class RecordReplay : public ::testing::TestWithParam<RecordCase> {};

std::string recordName(const ::testing::TestParamInfo<RecordCase>& info)
{
    std::string name = info.param.app + (info.param.offscreen ? "_offscreen" : "_glx");
    for (const std::string& a : info.param.args) name += "_" + a.substr(2);
    return name;
}

} // namespace

TEST_P(RecordReplay, ReplayIsPixelIdenticalToTheLiveFrames)
{
    const RecordCase& c = GetParam();
    if (!c.offscreen) {
        ASSERT_TRUE(haveDisplay()) << "run through scripts/test.sh (Xvfb)";
    }
    std::string dir = freshDir("rec"), live = dir + "/live", replay = dir + "/replay";
    std::string file = dir + "/capture.nprgl";
    std::vector<std::string> cmd = {
        nprglCommand(), "record",    "--style",       "none", "-o",     file,
        "--",           demo(c.app), "--frames",      "3",    "--size", "96x72",
        "--save-dir",   live,        "--save-frames", "1-3"};
    cmd.insert(cmd.end(), c.args.begin(), c.args.end());
    if (c.offscreen) cmd.push_back("--offscreen");
    ProcessResult r = runProcess(cmd);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    ProcessResult p = runProcess({nprglCommand(), "replay", "--style", "none", file, "-o", replay});
    ASSERT_EQ(p.exitCode, 0) << p.err;
    expectSameFrames(live, c.app, replay, 3);
    EXPECT_FALSE(fs::exists(framePng(replay, 4)));
}

INSTANTIATE_TEST_SUITE_P(
    Demos, RecordReplay,
    ::testing::Values(RecordCase{"immediate", {}, true}, RecordCase{"immediate", {}, false},
                      RecordCase{"arrays", {}, true}, RecordCase{"arrays", {"--vbo"}, true},
                      RecordCase{"arrays", {"--vbo"}, false},
                      RecordCase{"displaylist", {}, true},
                      RecordCase{"displaylist", {}, false}, RecordCase{"textured", {}, true},
                      RecordCase{"overlay", {}, true}, RecordCase{"overlay", {}, false},
                      RecordCase{"dlopen", {}, true}, RecordCase{"dlopen", {}, false},
                      // Pops the client state of the previous frame first, which puts back
                      // another client texture unit: the replay set the next glTexCoordPointer
                      // on the unit it had seen chosen last, and refused frame 2.
                      RecordCase{"state", {}, true}),
    recordName);

// A capture replayed in a style draws what the program drew under that style, also when the
// program makes objects after the styles made theirs (a texture in frame 2). The styles took
// their names from the driver's glGen*, which in the replay handed them the names the capture
// goes on to bind (the program's own, given out before nprgl existed in the recorded run): the
// demo's new floor texture and a style's shared one name, and the floor came out in the style's
// texture, or the replay was refused (a game's vertex buffer, taken by a style's mesh buffer).
namespace {

// Records demo_textured with `options` in style none, runs it live in the default style and
// replays the capture in that style: frame 3 must be the same pixels. With the program's
// textures drawn as they are (toon.texture_detail=1): live, their drawings are made on a
// worker thread and a frame never waits for one, so which frame first shows them depends on
// the machine's speed (a sanitizer build's live frame 3 showed the program's texture where the
// replay, which does that work at once, showed its drawing).
void expectStyledReplayAsLive(const std::string& name, const std::vector<std::string>& options)
{
    std::string dir = freshDir(name), live = dir + "/live";
    std::string replay = dir + "/replay", file = dir + "/capture.nprgl";
    std::vector<std::string> app = {demo("textured"), "--offscreen", "--frames", "3", "--size",
                                    "160x120"};
    app.insert(app.end(), options.begin(), options.end());
    std::vector<std::string> rec = {nprglCommand(), "record", "--style", "none", "-o", file, "--"};
    rec.insert(rec.end(), app.begin(), app.end());
    ProcessResult r = runProcess(rec);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    std::vector<std::string> styled = {nprglCommand(), "--style", "toon+paper+edges",
                                       "--set=toon.texture_detail=1", "--"};
    styled.insert(styled.end(), app.begin(), app.end());
    for (const char* a : {"--save-dir", live.c_str(), "--save-frames", "3"}) styled.push_back(a);
    ProcessResult s = runProcess(styled);
    ASSERT_EQ(s.exitCode, 0) << s.err;
    ProcessResult p = runProcess({nprglCommand(), "replay", "--style", "toon+paper+edges", file,
                                  "-o", replay, "--frames", "3", "--set=toon.texture_detail=1"});
    ASSERT_EQ(p.exitCode, 0) << p.err;
    ImageDiff diff = compareImages(live + "/textured_3.png", framePng(replay, 3));
    ASSERT_TRUE(diff.comparable) << diff.error;
    EXPECT_EQ(diff.differingPixels, 0u);
}

} // namespace

TEST(RecordReplay, AStyledReplayDrawsWhatTheStyledProgramDrew)
{
    expectStyledReplayAsLive("rec_late", {"--late-floor"});
}

// The same for shader and program objects, whose names the driver alone gives out: the
// replay's styles made theirs before the demo's frame 2 made its own, so the capture's
// glShaderSource, glAttachShader, glLinkProgram and glUseProgram named the styles' objects
// (the first style program relinked from the pane's shaders, whose sources replaced its own:
// the HUD bar, drawn by that program, lost its fill, as scorched3d's tank previews lost their
// squares in every replayed shading style).
TEST(RecordReplay, AStyledReplayKeepsTheProgramsShadersApartFromTheStyles)
{
    expectStyledReplayAsLive("rec_shader", {"--late-shader", "--hud-bar"});
}

// A program that leaves alpha below 1 in its framebuffer (glhanoi's materials have alpha 0;
// here the demo clears it to 0.25 and masks it) shows an opaque picture: the window system
// ignores the alpha. nprgl's screenshots and replayed frames are that picture, opaque; with
// the framebuffer's alpha in them a viewer showed the objects see-through or white.
TEST(Record, ScreenshotsAndReplayedFramesAreOpaqueAsTheWindowShowsThem)
{
    const std::string dir = freshDir("opaque_frames"), file = dir + "/capture.nprgl";
    const std::vector<std::string> app = {demo("textured"), "--offscreen", "--alpha-mask",
                                          "--frames", "3", "--size", "64x48"};
    std::vector<std::string> shot = {nprglCommand(), "--style", "none", "--screenshot",
                                     "frames=3;dir=" + dir + "/shots", "--"};
    std::vector<std::string> rec = {nprglCommand(), "record", "--style", "none", "-o", file, "--"};
    shot.insert(shot.end(), app.begin(), app.end());
    rec.insert(rec.end(), app.begin(), app.end());
    ProcessResult r = runProcess(shot);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("alpha frame 3: 64 64 64 64 64"), std::string::npos)
        << "the framebuffer's alpha is not 0.25: no test: " << r.out;
    r = runProcess(rec);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    ProcessResult p =
        runProcess({nprglCommand(), "replay", file, "-o", dir + "/replay", "--frames", "3"});
    ASSERT_EQ(p.exitCode, 0) << p.err;
    std::vector<std::string> pngs = {framePng(dir + "/replay", 3)};
    for (const auto& entry : fs::directory_iterator(dir + "/shots")) {
        pngs.push_back(entry.path().string());
    }
    ASSERT_EQ(pngs.size(), 2u) << "no screenshot written";
    for (const std::string& path : pngs) {
        PngImage image;
        std::string error;
        ASSERT_TRUE(PngImage::read(path, image, error)) << error;
        size_t seeThrough = 0;
        for (size_t i = 3; i < image.rgba.size(); i += 4) seeThrough += image.rgba[i] != 255;
        EXPECT_EQ(seeThrough, 0u) << path;
    }
}

TEST(Fixtures, EveryDemoFixtureReplaysAsTheDemoDrawsToday)
{
    const std::vector<std::pair<std::string, std::vector<std::string>>> fixtures = {
        {"immediate", {}},   {"arrays", {}},  {"arrays_vbo", {"--vbo"}}, {"displaylist", {}},
        {"textured", {}},    {"overlay", {}}, {"dlopen", {}}};
    for (const auto& [name, args] : fixtures) {
        std::string app = name.substr(0, name.find('_'));
        std::string dir = freshDir("fixture"), live = dir + "/live", replay = dir + "/replay";
        std::vector<std::string> cmd = {demo(app), "--offscreen", "--frames", "3", "--size",
                                        "160x120", "--save-dir", live};
        cmd.insert(cmd.end(), args.begin(), args.end());
        ProcessResult r = runProcess(cmd);
        ASSERT_EQ(r.exitCode, 0) << r.err;
        ProcessResult p =
            runProcess({nprglCommand(), "replay", "--style", "none", fixture(name), "-o", replay});
        ASSERT_EQ(p.exitCode, 0) << name << ": " << p.err;
        expectSameFrames(live, app, replay, 3);
    }
}

TEST(Fixtures, CharacterFixturesReplayAsTheDemoDrawsToday)
{
    const std::string models = "/usr/share/assimp/models/";
    const std::vector<std::pair<std::string, std::string>> fixtures = {
        {"character_morph", "MD2/sydney.md2"},
        {"character_skin", "X/Testwuson.X"},
        {"character_rigid", "BVH/01_01.bvh"}};
    for (const auto& [name, model] : fixtures) {
        if (!fs::exists(models + model)) GTEST_SKIP() << "assimp-testmodels is not installed";
        std::string dir = freshDir("character"), live = dir + "/live", replay = dir + "/replay";
        ProcessResult r = runProcess({demo("character"), "--model", models + model,
                                      "--offscreen", "--frames", "3", "--size", "160x120",
                                      "--save-dir", live});
        ASSERT_EQ(r.exitCode, 0) << r.err;
        ProcessResult p =
            runProcess({nprglCommand(), "replay", "--style", "none", fixture(name), "-o", replay});
        ASSERT_EQ(p.exitCode, 0) << name << ": " << p.err;
        expectSameFrames(live, "character", replay, 3);
    }
}

TEST(Fixtures, GlxgearsReplaysAsGlxgears)
{
    std::string replay = freshDir("gears");
    ProcessResult p = runProcess(
        {nprglCommand(), "replay", "--style", "none", fixture("glxgears"), "-o", replay});
    ASSERT_EQ(p.exitCode, 0) << p.err;
    expectGlxgearsPicture(framePng(replay, 3));
}

namespace {

// Pixels of `small` that differ by more than `tolerance` (a channel) from `big` averaged
// over the 2x2 block it covers; -1 unless `big` is twice `small` each way.
long differingFromHalved(const PngImage& big, const PngImage& small, int tolerance)
{
    if (big.width != 2 * small.width || big.height != 2 * small.height) return -1;
    long n = 0;
    for (int y = 0; y < small.height; ++y) {
        for (int x = 0; x < small.width; ++x) {
            bool differs = false;
            for (int c = 0; c < 3; ++c) {
                int sum = 0;
                for (int dy = 0; dy < 2; ++dy) {
                    for (int dx = 0; dx < 2; ++dx)
                        sum += big.rgba[size_t(((2 * y + dy) * big.width + 2 * x + dx) * 4 + c)];
                }
                const int v = small.rgba[size_t((y * small.width + x) * 4 + c)];
                differs = differs || std::abs(v - (sum + 2) / 4) > tolerance;
            }
            n += differs;
        }
    }
    return n;
}

} // namespace

// `replay --size` at half the recorded size draws the program's picture resized, not the
// lower left quarter of it: each frame is the full-size frame halved (2x2 averages), but for
// edges drawn at the smaller size. glxgears (its viewport), demo_textured (its scissored
// clear; with --env-map the corner it draws the scene in, copies into a texture with
// glCopyTexSubImage2D and shows) and demo_immediate.
TEST(Replay, ASmallerSizeScalesTheProgramsPicture)
{
    const std::string envMap = freshDir("size_env") + "/env.nprgl";
    ProcessResult recorded = runProcess(
        {nprglCommand(), "record", "--style", "none", "-o", envMap, "--", demo("textured"),
         "--offscreen", "--env-map", "--frames", "3", "--size", "160x120"});
    ASSERT_EQ(recorded.exitCode, 0) << recorded.err;
    for (const std::string name : {"glxgears", "textured", "immediate", "env"}) {
        const std::string capture = name == "env" ? envMap : fixture(name);
        const std::string dir = freshDir("size_" + name);
        ProcessResult info = runProcess({nprglCommand(), "info", capture});
        ASSERT_EQ(info.exitCode, 0) << info.err;
        std::smatch size;
        ASSERT_TRUE(std::regex_search(info.out, size, std::regex("size: +(\\d+)x(\\d+)")))
            << info.out;
        const int w = std::stoi(size[1]), h = std::stoi(size[2]);
        ASSERT_TRUE(w % 2 == 0 && h % 2 == 0) << info.out;
        for (const auto& [sub, extra] :
             std::vector<std::pair<std::string, std::vector<std::string>>>{
                 {"full", {}}, {"half", {"--size", std::to_string(w / 2) + "x" +
                                                       std::to_string(h / 2)}}}) {
            std::vector<std::string> cmd = {nprglCommand(), "replay", "--style", "none",
                                            capture, "-o", dir + "/" + sub, "--frames",
                                            "3"};
            cmd.insert(cmd.end(), extra.begin(), extra.end());
            ProcessResult p = runProcess(cmd);
            ASSERT_EQ(p.exitCode, 0) << name << ": " << p.err;
        }
        PngImage full, half;
        std::string error;
        ASSERT_TRUE(PngImage::read(framePng(dir + "/full", 3), full, error)) << error;
        ASSERT_TRUE(PngImage::read(framePng(dir + "/half", 3), half, error)) << error;
        const long differing = differingFromHalved(full, half, 48);
        ASSERT_GE(differing, 0) << name;
        EXPECT_LT(differing, long(half.width * half.height / 20)) << name;
    }
}

TEST(Dump, PrintsOneCallPerLineWithNamedArguments)
{
    ProcessResult d = runProcess({nprglCommand(), "dump", fixture("immediate"), "--frames",
                                  "2"});
    ASSERT_EQ(d.exitCode, 0) << d.err;
    EXPECT_NE(d.out.find("== context 1 frame 2 =="), std::string::npos);
    EXPECT_EQ(d.out.find("frame 1 =="), std::string::npos);
    EXPECT_NE(d.out.find("-- end of frame 2 --"), std::string::npos);
    EXPECT_NE(d.out.find("glBegin(mode=GL_QUAD_STRIP)"), std::string::npos);
    EXPECT_NE(d.out.find("glMaterialfv(face=GL_FRONT"), std::string::npos) << d.out.substr(0, 2000);
    std::regex vertex(R"(glVertex3f\(x=-?[0-9.e+-]+, y=-?[0-9.e+-]+, z=-?[0-9.e+-]+\))");
    EXPECT_TRUE(std::regex_search(d.out, vertex));

    ProcessResult g = runProcess({nprglCommand(), "dump", fixture("immediate"), "--grep",
                                  "glBegin"});
    ASSERT_EQ(g.exitCode, 0) << g.err;
    std::istringstream lines(g.out);
    std::string line;
    size_t calls = 0;
    while (std::getline(lines, line)) {
        if (line.rfind("==", 0) == 0) continue;
        EXPECT_TRUE(std::regex_match(line, std::regex(R"(\d+ glBegin\(.*)"))) << line;
        ++calls;
    }
    EXPECT_GT(calls, 3u);
}

// As apitrace numbers calls: a call's number is its place in its context's stream, the same
// whichever frames or names the dump selects.
TEST(Dump, NumbersEachCallByItsPlaceInTheStream)
{
    ProcessResult all = runProcess({nprglCommand(), "dump", fixture("glxgears")});
    ASSERT_EQ(all.exitCode, 0) << all.err;
    std::map<std::string, std::string> numberOf; // "frame 2: glClear(...)" -> its number
    std::istringstream lines(all.out);
    std::string line, frame;
    uint64_t expected = 0;
    const std::regex numbered(R"((\d+) (gl\w+\(.*))");
    while (std::getline(lines, line)) {
        std::smatch m;
        if (line.rfind("== context 1 frame ", 0) == 0) frame = line;
        if (!std::regex_match(line, m, numbered)) continue;
        EXPECT_EQ(std::stoull(m[1]), expected++) << line;
        if (m[2].str().rfind("glClear(", 0) == 0) numberOf[frame] = m[1];
    }
    ASSERT_GE(numberOf.size(), 3u) << all.out.substr(0, 2000);
    ProcessResult some = runProcess({nprglCommand(), "dump", fixture("glxgears"), "--frames",
                                     "3", "--grep", "glClear"});
    ASSERT_EQ(some.exitCode, 0) << some.err;
    EXPECT_EQ(some.out, "== context 1 frame 3 ==\n" + numberOf["== context 1 frame 3 =="] +
                            " glClear(mask=GL_DEPTH_BUFFER_BIT|GL_COLOR_BUFFER_BIT)\n");
}

TEST(Info, ReportsProgramFramesCallsAndWhatWasNotCaptured)
{
    std::string dir = freshDir("info"), file = dir + "/d.nprgl";
    ProcessResult r = runProcess({nprglCommand(), "record", "--style", "none", "-o", file, "--",
                                  demo("displaylist"), "--offscreen", "--frames", "4", "--size",
                                  "64x64", "--save-dir", dir + "/live"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    // The demo reads its frames back with glReadPixels into its own memory: a readback, which
    // changes nothing a replay needs, so the capture lacks nothing (test_buffers covers calls
    // that are left out, and the frames they are left out of).
    EXPECT_NE(r.err.find("not captured: nothing"), std::string::npos) << r.err;
    ProcessResult i = runProcess({nprglCommand(), "info", file});
    ASSERT_EQ(i.exitCode, 0) << i.err;
    EXPECT_NE(i.out.find("program:     demo_displaylist"), std::string::npos) << i.out;
    EXPECT_NE(i.out.find("frames:      4"), std::string::npos) << i.out;
    EXPECT_NE(i.out.find("glCallList"), std::string::npos) << i.out;
    EXPECT_NE(i.out.find("glNewList"), std::string::npos) << i.out;
    EXPECT_NE(i.out.find("size:        64x64"), std::string::npos) << i.out;
    EXPECT_NE(i.out.find("not captured:\n  (none)"), std::string::npos) << i.out;
}

// A program that sizes its window after making its context current (glretrace, SDL games)
// is replayed at the size its frames were shown at, not the first one's; a later resize is
// said at record time (its frames still replay at the first frame's size).
TEST(Record, TheCaptureTakesTheSizeItsFirstFrameWasShownAt)
{
    ASSERT_TRUE(haveDisplay()) << "no DISPLAY: run the tests through scripts/test.sh";
    std::string dir = freshDir("resized");
    auto record = [&](const std::string& growAt, const std::string& file) {
        ProcessResult r = runProcess({nprglCommand(), "record", "--style", "none", "-o", file,
                                      "--", demo("immediate"), "--size", "48x32", "--frames",
                                      "4", "--grow-at", growAt});
        EXPECT_EQ(r.exitCode, 0) << r.err;
        ProcessResult i = runProcess({nprglCommand(), "info", file});
        EXPECT_EQ(i.exitCode, 0) << i.err;
        return std::pair{r.err, i.out};
    };
    const auto [atStartLog, atStart] = record("1", dir + "/start.nprgl");
    EXPECT_NE(atStart.find("size:        96x64"), std::string::npos) << atStart;
    EXPECT_EQ(atStartLog.find("the window is"), std::string::npos) << atStartLog;
    const auto [laterLog, later] = record("3", dir + "/later.nprgl");
    EXPECT_NE(later.find("size:        48x32"), std::string::npos) << later;
    EXPECT_NE(laterLog.find("the window is 96x64 from frame 3 on"), std::string::npos)
        << laterLog;
}

TEST(Record, DefaultFileIsNamedAfterTheProgramAndFramesLimitTheRecording)
{
    std::string dir = freshDir("default");
    std::string cmd = "cd " + dir + " && " + nprglCommand() + " record --frames 2-3 -- " +
                      demo("immediate") + " --offscreen --frames 6 --size 32x32";
    ProcessResult r = runProcess({"sh", "-c", cmd});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    std::string file = dir + "/demo_immediate.nprgl";
    ASSERT_TRUE(fs::exists(file));
    ProcessResult i = runProcess({nprglCommand(), "info", file});
    ASSERT_EQ(i.exitCode, 0) << i.err;
    // Frame 1 is kept (it sets up state frames 2 and 3 need); nothing after frame 3.
    EXPECT_NE(i.out.find("frames:      3"), std::string::npos) << i.out;
    EXPECT_EQ(i.out.find("recovered"), std::string::npos) << i.out;
}

namespace {

// Starts a recording of an endless offscreen demo, lets it draw until the file holds some
// frames, then stops it.
ProcessResult recordAndStop(const std::string& file, int signal)
{
    auto enough = [&] {
        std::error_code ec;
        return fs::file_size(file, ec) >= 20000 && !ec;
    };
    return runUntil({nprglCommand(), "record", "-o", file, "--", demo("immediate"),
                     "--offscreen", "--frames", "0", "--size", "64x64"},
                    {}, enough, signal);
}

} // namespace

TEST(Record, ProgramsStoppedBySignalsOrUnderscoreExitLeaveReadableFiles)
{
    for (int signal : {SIGINT, SIGTERM}) {
        std::string dir = freshDir("signal"), file = dir + "/s.nprgl";
        ProcessResult stopped = recordAndStop(file, signal);
        EXPECT_EQ(stopped.exitCode, 128 + signal);
        ProcessResult i = runProcess({nprglCommand(), "info", file});
        ASSERT_EQ(i.exitCode, 0) << i.err;
        std::smatch m;
        ASSERT_TRUE(std::regex_search(i.out, m, std::regex(R"(frames:\s+(\d+))"))) << i.out;
        EXPECT_GE(std::stoi(m[1]), 1);
        ProcessResult p =
            runProcess({nprglCommand(), "replay", "--style", "none", file, "-o", dir + "/r"});
        EXPECT_EQ(p.exitCode, 0) << p.err;
        EXPECT_TRUE(fs::exists(framePng(dir + "/r", 1)));
    }
    std::string dir = freshDir("uexit"), file = dir + "/u.nprgl";
    ProcessResult u = runProcess({nprglCommand(), "record", "--style", "none", "-o", file, "--",
                                  binDir() + "/probe_fork", "underscore-exit"});
    EXPECT_EQ(u.exitCode, 5);
    ProcessResult i = runProcess({nprglCommand(), "info", file});
    ASSERT_EQ(i.exitCode, 0) << i.err;
    EXPECT_NE(i.out.find("frames:      1"), std::string::npos) << i.out;
}

// What `nprgl record` says when the program ends, from the file: the same frame count as
// `nprgl info`, on a normal exit, a Ctrl-C, a kill and an _exit alike.
TEST(Record, SaysWhatItRecordedHoweverTheProgramEnds)
{
    auto infoFrames = [](const std::string& file) {
        ProcessResult i = runProcess({nprglCommand(), "info", file});
        std::smatch m;
        EXPECT_TRUE(std::regex_search(i.out, m, std::regex(R"(frames:\s+(\d+))"))) << i.out;
        return m.size() > 1 ? m[1].str() : std::string("?");
    };
    for (int signal : {SIGINT, SIGTERM}) {
        std::string dir = freshDir("summary"), file = dir + "/s.nprgl";
        ProcessResult stopped = recordAndStop(file, signal);
        EXPECT_EQ(stopped.exitCode, 128 + signal);
        const std::string said = "nprgl: recorded " + infoFrames(file) + " frames to " + file;
        EXPECT_NE(stopped.err.find(said), std::string::npos) << said << "\n" << stopped.err;
        EXPECT_NE(stopped.err.find("without closing it"), std::string::npos) << stopped.err;
    }
    std::string dir = freshDir("summary_exit"), file = dir + "/e.nprgl";
    ProcessResult r = runProcess({nprglCommand(), "record", "-o", file, "--", demo("immediate"),
                                  "--offscreen", "--frames", "2", "--size", "64x64"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("nprgl: recorded 2 frames to " + file), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("without closing it"), std::string::npos) << r.err;
    // Said once: the library leaves it to the command.
    EXPECT_EQ(r.err.find("recorded"), r.err.rfind("recorded")) << r.err;
    file = dir + "/u.nprgl";
    ProcessResult u = runProcess({nprglCommand(), "record", "-o", file, "--",
                                  binDir() + "/probe_fork", "underscore-exit"});
    EXPECT_EQ(u.exitCode, 5);
    EXPECT_NE(u.err.find("nprgl: recorded 1 frames to " + file), std::string::npos) << u.err;
}

// apitrace records the program as it is: so does `nprgl record` unless a style is asked for.
// The frames the program saw while recording are its own, the same as an unstyled replay.
TEST(Record, RecordsTheProgramUnstyledUnlessAStyleIsAskedFor)
{
    std::string dir = freshDir("unstyled"), file = dir + "/u.nprgl";
    ProcessResult r = runProcess({nprglCommand(), "record", "-o", file, "--", demo("immediate"),
                                  "--offscreen", "--frames", "2", "--size", "96x72",
                                  "--save-dir", dir + "/live", "--save-frames", "1-2"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    ProcessResult p =
        runProcess({nprglCommand(), "replay", "--style", "none", file, "-o", dir + "/none"});
    ASSERT_EQ(p.exitCode, 0) << p.err;
    expectSameFrames(dir + "/live", "immediate", dir + "/none", 2);

    std::string styled = dir + "/s.nprgl";
    ProcessResult s = runProcess({nprglCommand(), "record", "--style", "toon", "-o", styled,
                                  "--", demo("immediate"), "--offscreen", "--frames", "1",
                                  "--size", "96x72", "--save-dir", dir + "/styled",
                                  "--save-frames", "1"});
    ASSERT_EQ(s.exitCode, 0) << s.err;
    ImageDiff diff = compareImages(dir + "/styled/immediate_1.png", framePng(dir + "/none", 1));
    ASSERT_TRUE(diff.comparable) << diff.error;
    EXPECT_GT(diff.differingPixels, 100u) << "--style toon was not applied while recording";
}

TEST(Record, AForkedChildWritesItsOwnFile)
{
    std::string dir = freshDir("fork"), file = dir + "/f.nprgl";
    ProcessResult r = runProcess({nprglCommand(), "record", "--style", "none", "-o", file, "--",
                                  binDir() + "/probe_fork", "fork"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    std::vector<std::string> files;
    for (const auto& e : fs::directory_iterator(dir)) files.push_back(e.path().string());
    ASSERT_EQ(files.size(), 2u);
    for (const std::string& f : files) {
        ProcessResult i = runProcess({nprglCommand(), "info", f});
        EXPECT_EQ(i.exitCode, 0) << f << ": " << i.err;
        // The parent drew two frames, the child one.
        EXPECT_NE(i.out.find(f == file ? "frames:      2" : "frames:      1"),
                  std::string::npos)
            << f << "\n" << i.out;
    }
}

// A launcher that draws nothing and starts the program that draws (a shell script, wine's
// loader starting wine64 for a 64-bit .exe): the capture asked for is the drawing process's,
// and the line at the end says whose. Two drawing children: both said, neither renamed.
TEST(Record, TheCaptureOfTheOneProcessThatDrewIsTheFileAsked)
{
    const std::string run = demo("immediate") + " --offscreen --frames 3 --size 64x48";
    for (int children : {1, 2}) {
        SCOPED_TRACE(std::to_string(children) + " drawing children");
        const std::string dir = freshDir("launcher"), file = dir + "/l.nprgl";
        // The status kept and returned: the shell forks each command, it execs none.
        std::string script = run + "; status=$?";
        if (children == 2) script += "; " + run + " || status=$?";
        script += "; exit $status";
        ProcessResult r = runProcess({nprglCommand(), "record", "--style", "none", "-o", file,
                                      "--", "sh", "-c", script});
        ASSERT_EQ(r.exitCode, 0) << r.err;
        std::vector<std::string> files;
        for (const auto& e : fs::directory_iterator(dir)) files.push_back(e.path().string());
        if (children == 1) {
            EXPECT_EQ(files, std::vector<std::string>{file}) << r.err;
            EXPECT_TRUE(std::regex_search(r.err,
                                          std::regex("nprgl: recorded 3 frames to " + file +
                                                     " .*\\(by process [0-9]+, which the program "
                                                     "started\\)")))
                << r.err;
            ProcessResult info = runProcess({nprglCommand(), "info", file});
            EXPECT_EQ(info.exitCode, 0) << info.err;
            EXPECT_NE(info.out.find("program:     demo_immediate"), std::string::npos)
                << info.out;
            EXPECT_NE(info.out.find("frames:      3"), std::string::npos) << info.out;
        } else {
            EXPECT_EQ(files.size(), 2u) << r.err;
            EXPECT_FALSE(fs::exists(file));
            EXPECT_NE(r.err.find("the program recorded nothing itself (no " + file +
                                 "); 2 processes it started did:"),
                      std::string::npos)
                << r.err;
            for (const std::string& f : files) {
                EXPECT_NE(r.err.find("which the program started: recorded 3 frames to " + f),
                          std::string::npos)
                    << r.err;
            }
        }
    }
}

TEST(Record, EachContextHasItsOwnStream)
{
    std::string dir = freshDir("threads"), file = dir + "/t.nprgl";
    ProcessResult r = runProcess({nprglCommand(), "record", "--style", "none", "-o", file, "--",
                                  binDir() + "/probe_threads"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    ProcessResult i = runProcess({nprglCommand(), "info", file});
    ASSERT_EQ(i.exitCode, 0) << i.err;
    EXPECT_NE(i.out.find("(context 1: 2)  (context 2: 2)"), std::string::npos) << i.out;
    // Context 1 cleared to red, context 2 to blue.
    for (int ctx : {1, 2}) {
        std::string out = dir + "/ctx" + std::to_string(ctx);
        ProcessResult p = runProcess({nprglCommand(), "replay", "--style", "none", file,
                                      "--context", std::to_string(ctx), "-o", out});
        ASSERT_EQ(p.exitCode, 0) << p.err;
        PngImage image;
        std::string error;
        ASSERT_TRUE(PngImage::read(framePng(out, 2), image, error)) << error;
        EXPECT_EQ(image.width, 48);
        EXPECT_EQ(image.rgba[0], ctx == 1 ? 255 : 0);
        EXPECT_EQ(image.rgba[2], ctx == 1 ? 0 : 255);
    }
}

namespace {

struct ObjGroupStats {
    size_t faces = 0;
    size_t borderEdges = 0;
};

// Faces and border edges (used by one face only) of each group of an OBJ file.
std::vector<ObjGroupStats> objGroups(const std::string& path)
{
    std::vector<ObjGroupStats> groups;
    std::vector<std::map<std::pair<long, long>, int>> edges;
    std::ifstream in(path);
    std::string line;
    while (std::getline(in, line)) {
        if (line.rfind("g ", 0) == 0) {
            groups.emplace_back();
            edges.emplace_back();
        } else if (line.rfind("f ", 0) == 0 && !groups.empty()) {
            std::istringstream words(line.substr(2));
            std::vector<long> v;
            std::string word;
            while (words >> word) v.push_back(std::stol(word.substr(0, word.find('/'))));
            for (size_t i = 0; i < v.size(); ++i) {
                long a = v[i], b = v[(i + 1) % v.size()];
                ++edges.back()[{std::min(a, b), std::max(a, b)}];
            }
            ++groups.back().faces;
        }
    }
    for (size_t g = 0; g < groups.size(); ++g) {
        for (const auto& [edge, uses] : edges[g]) groups[g].borderEdges += uses == 1;
    }
    return groups;
}

} // namespace

TEST(Export, AGlxgearsFrameIsThreeClosedGears)
{
    std::string dir = freshDir("export");
    ProcessResult r = runProcess({nprglCommand(), "export", fixture("glxgears"), "--frame", "2",
                                  "-o", dir + "/gears.obj"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    std::vector<ObjGroupStats> groups = objGroups(dir + "/gears.obj");
    ASSERT_EQ(groups.size(), 3u);
    for (const ObjGroupStats& g : groups) {
        EXPECT_GT(g.faces, 100u);
        EXPECT_EQ(g.borderEdges, 0u);
    }
    for (const char* ext : {".ply", ".off"}) {
        std::string out = dir + "/gears" + ext;
        ProcessResult p = runProcess({nprglCommand(), "export", fixture("glxgears"), "--frame",
                                      "2", "--space", "object", "-o", out});
        EXPECT_EQ(p.exitCode, 0) << p.err;
        EXPECT_GT(fs::file_size(out), 1000u);
    }
    ProcessResult missing = runProcess({nprglCommand(), "export", fixture("glxgears"),
                                        "--frame", "99", "-o", dir + "/none.obj"});
    EXPECT_EQ(missing.exitCode, 1);
    EXPECT_NE(missing.err.find("no frame 99"), std::string::npos) << missing.err;
}

TEST(Export, LiveExportWritesTheRequestedFrame)
{
    std::string dir = freshDir("liveexport");
    ProcessResult r = runProcess({nprglCommand(), "--", demo("displaylist"), "--offscreen",
                                  "--frames", "4", "--size", "64x64"},
                                 {{"NPRGL_EXPORT", "frame=3;dir=" + dir}});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    std::vector<ObjGroupStats> groups = objGroups(dir + "/demo_displaylist_3.obj");
    EXPECT_GE(groups.size(), 4u) << r.err; // the back plate and three gears
    EXPECT_FALSE(fs::exists(dir + "/demo_displaylist_4.obj"));
    ProcessResult bad = runProcess({demo("displaylist"), "--offscreen", "--frames", "2"},
                                   {{"LD_PRELOAD", preloadValue()}, {"NPRGL_EXPORT", "frame=x"}});
    EXPECT_EQ(bad.exitCode, 0);
    EXPECT_NE(bad.err.find("NPRGL_EXPORT"), std::string::npos) << bad.err;
}

namespace {

// Every command refuses a damaged file with one line naming it, never crashes.
void expectRefusedOrPrefix(const std::string& path, bool mustRefuse)
{
    for (const char* command : {"info", "dump", "replay"}) {
        std::vector<std::string> cmd = {nprglCommand(), command, path};
        if (std::string(command) == "replay") cmd.insert(cmd.end(), {"-o", path + ".out"});
        ProcessResult r = runProcess(cmd);
        ASSERT_LT(r.exitCode, 128) << command << " crashed on " << path << ": " << r.err;
        if (r.exitCode != 0) {
            EXPECT_NE(r.err.find("nprgl: "), std::string::npos) << r.err;
            EXPECT_NE(r.err.find(fs::path(path).filename().string()), std::string::npos)
                << command << ": " << r.err;
        } else {
            EXPECT_FALSE(mustRefuse) << command << " accepted " << path;
        }
    }
}

} // namespace

TEST(DamagedFiles, AreRefusedCleanly)
{
    std::string dir = freshDir("damaged");
    const std::string good = readAll(fixture("displaylist"));
    ASSERT_GT(good.size(), 1000u);

    writeAll(dir + "/empty.nprgl", "");
    expectRefusedOrPrefix(dir + "/empty.nprgl", true);
    std::string magic = good;
    magic[0] ^= 0x55;
    writeAll(dir + "/magic.nprgl", magic);
    expectRefusedOrPrefix(dir + "/magic.nprgl", true);
    writeAll(dir + "/text.nprgl", "this is not a capture file at all\n");
    expectRefusedOrPrefix(dir + "/text.nprgl", true);
    expectRefusedOrPrefix(dir + "/missing.nprgl", true);

    for (size_t cut : {size_t(9), size_t(40), good.size() / 3, good.size() / 2, good.size() - 5}) {
        std::string path = dir + "/cut" + std::to_string(cut) + ".nprgl";
        writeAll(path, good.substr(0, cut));
        expectRefusedOrPrefix(path, cut < 64);
    }
    for (size_t at = 16; at < good.size(); at += good.size() / 7) {
        std::string flipped = good;
        flipped[at] ^= 0x10;
        std::string path = dir + "/flip" + std::to_string(at) + ".nprgl";
        writeAll(path, flipped);
        expectRefusedOrPrefix(path, false);
    }
}

namespace {

// The pid a probe_fork child printed ("child pid=N").
std::string childPid(const std::string& out)
{
    std::smatch m;
    return std::regex_search(out, m, std::regex(R"(child pid=(\d+))")) ? m[1].str() : "";
}

// A capture of probe_fork's parent or child: complete, with only that process's frames and
// colours (the parent clears to blue, the child to red), and replayable.
void expectWholeCapture(const std::string& file, bool parent)
{
    ProcessResult i = runProcess({nprglCommand(), "info", file});
    ASSERT_EQ(i.exitCode, 0) << file << ": " << i.err;
    EXPECT_NE(i.out.find(parent ? "frames:      5" : "frames:      3"), std::string::npos)
        << file << "\n" << i.out;
    EXPECT_NE(i.out.find("program:     probe_fork"), std::string::npos) << i.out;
    EXPECT_EQ(i.out.find("recovered"), std::string::npos) << file << "\n" << i.out;
    ProcessResult d = runProcess({nprglCommand(), "dump", file, "--grep", "glClearColor"});
    ASSERT_EQ(d.exitCode, 0) << d.err;
    const std::string mine = parent ? "glClearColor(red=0, green=0, blue=1, alpha=1)"
                                    : "glClearColor(red=1, green=0, blue=0, alpha=1)";
    size_t clears = 0;
    std::istringstream lines(d.out);
    std::string line;
    while (std::getline(lines, line)) {
        if (line.rfind("==", 0) == 0) continue;
        EXPECT_EQ(line.substr(line.find(' ') + 1), mine) << file; // after the call number
        ++clears;
    }
    EXPECT_EQ(clears, parent ? 5u : 3u) << d.out;
    std::string out = file + ".replay";
    ProcessResult p = runProcess({nprglCommand(), "replay", "--style", "none", file, "-o", out});
    ASSERT_EQ(p.exitCode, 0) << p.err;
    PngImage image;
    std::string error;
    ASSERT_TRUE(PngImage::read(framePng(out, parent ? 5 : 3), image, error)) << error;
    // The triangle covers the whole picture: yellow for the parent, green for the child.
    EXPECT_EQ(image.rgba[0], parent ? 255 : 0) << file;
    EXPECT_EQ(image.rgba[1], 255) << file;
    EXPECT_EQ(image.rgba[2], 0) << file;
}

} // namespace

// A GL program that starts another one (fork+exec, posix_spawn, system) while it records:
// the child inherits NPRGL_RECORD, yet must write <name>.<pid>.nprgl and leave the parent's
// file whole. The two draw alternately, so a shared file would be truncated or interleaved.
TEST(Record, AnExecutedOrSpawnedChildWritesItsOwnFile)
{
    for (const char* mode : {"exec", "spawn", "system"}) {
        for (bool command : {true, false}) {
            SCOPED_TRACE(std::string(mode) + (command ? " with nprgl record" : " with LD_PRELOAD"));
            std::string dir = freshDir(std::string("spawn_") + mode), file = dir + "/p.nprgl";
            ProcessResult r =
                command ? runProcess({nprglCommand(), "record", "--style", "none", "-o", file,
                                      "--", binDir() + "/probe_fork", mode})
                        : runProcess({binDir() + "/probe_fork", mode},
                                     {{"LD_PRELOAD", preloadValue()}, {"NPRGL_RECORD", file}});
            ASSERT_EQ(r.exitCode, 0) << r.err;
            EXPECT_NE(r.out.find("child status=0"), std::string::npos) << r.out;
            std::string pid = childPid(r.out);
            ASSERT_FALSE(pid.empty()) << r.out;
            std::string childFile = dir + "/p." + pid + ".nprgl";
            ASSERT_TRUE(fs::exists(childFile)) << r.err;
            size_t files = 0;
            for (const auto& e : fs::directory_iterator(dir)) files += e.is_regular_file();
            EXPECT_EQ(files, 2u) << r.err;
            expectWholeCapture(file, true);
            expectWholeCapture(childFile, false);
        }
    }
}
