// End to end: real programs run under `nprgl --style none`, natively and with the library,
// in a GLX window (Xvfb) and offscreen (OSMesa). Their frames must be pixel-identical.

#include "common/PngImage.h"
#include "tests/support/ImageCompare.h"
#include "tests/support/Process.h"

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>

using namespace nprgl;
using namespace nprgl::test;
namespace fs = std::filesystem;

namespace {

constexpr int kFrames = 4;


struct DemoCase {
    std::string app;
    std::vector<std::string> extraArgs;
    bool offscreen;
};

std::string caseName(const ::testing::TestParamInfo<DemoCase>& info)
{
    std::string name = info.param.app + (info.param.offscreen ? "_offscreen" : "_glx");
    for (const std::string& a : info.param.extraArgs) name += "_" + a.substr(2);
    return name;
}

void PrintTo(const DemoCase& c, std::ostream* os)
{
    *os << c.app << (c.offscreen ? " offscreen" : " glx");
    for (const std::string& a : c.extraArgs) *os << " " << a;
}

class DemoPassthrough : public ::testing::TestWithParam<DemoCase> {};

} // namespace

TEST_P(DemoPassthrough, FramesArePixelIdenticalToNative)
{
    const DemoCase& c = GetParam();
    if (!c.offscreen) {
        ASSERT_TRUE(haveDisplay()) << "no DISPLAY: run the tests through scripts/test.sh, "
                                      "which starts Xvfb";
    }
    std::vector<std::string> args = {demo(c.app), "--frames", std::to_string(kFrames),
                                     "--size", "160x120", "--save-frames", "1-4"};
    args.insert(args.end(), c.extraArgs.begin(), c.extraArgs.end());
    if (c.offscreen) args.push_back("--offscreen");

    std::string nativeDir = freshDir("native"), shimDir = freshDir("shim"),
                shotDir = freshDir("shots");
    std::vector<std::string> native = args, shimmed = {nprglCommand(), "--style", "none", "--"};
    native.insert(native.end(), {"--save-dir", nativeDir});
    shimmed.insert(shimmed.end(), args.begin(), args.end());
    shimmed.insert(shimmed.end(), {"--save-dir", shimDir});

    ProcessResult a = runProcess(native);
    ASSERT_EQ(a.exitCode, 0) << a.err;
    ProcessResult b = runProcess(shimmed, {{"NPRGL_SCREENSHOT", "frames=1-4;dir=" + shotDir},
                                           {"NPRGL_LOG_LEVEL", "debug"}});
    ASSERT_EQ(b.exitCode, 0) << b.err;
    EXPECT_EQ(a.out, b.out) << "nprgl must never write to the program's stdout";
    EXPECT_EQ(b.err.find("nprgl: error"), std::string::npos) << b.err;

    for (int frame = 1; frame <= kFrames; ++frame) {
        std::string file = "/" + c.app + "_" + std::to_string(frame) + ".png";
        ImageDiff diff = compareImages(nativeDir + file, shimDir + file);
        ASSERT_TRUE(diff.comparable) << diff.error;
        EXPECT_EQ(diff.differingPixels, 0u) << "frame " << frame;
        PngImage image;
        std::string error;
        ASSERT_TRUE(PngImage::read(nativeDir + file, image, error)) << error;
        EXPECT_GT(coveredFraction(image), 0.02) << "frame " << frame << " is nearly empty";
        // nprgl's own screenshot of the same frame is the same picture.
        std::string shot = shotDir + "/demo_" + c.app + "_" + std::to_string(frame) + ".png";
        ImageDiff shotDiff = compareImages(nativeDir + file, shot);
        ASSERT_TRUE(shotDiff.comparable) << shotDiff.error;
        EXPECT_EQ(shotDiff.differingPixels, 0u) << "screenshot of frame " << frame;
    }
    EXPECT_FALSE(std::filesystem::exists(shotDir + "/demo_" + c.app + "_5.png"));
}

INSTANTIATE_TEST_SUITE_P(
    Demos, DemoPassthrough,
    ::testing::Values(DemoCase{"immediate", {}, false}, DemoCase{"immediate", {}, true},
                      DemoCase{"arrays", {}, false}, DemoCase{"arrays", {"--vbo"}, false},
                      DemoCase{"arrays", {"--vbo"}, true}, DemoCase{"displaylist", {}, false},
                      DemoCase{"displaylist", {}, true}, DemoCase{"textured", {}, false},
                      DemoCase{"textured", {}, true}, DemoCase{"dlopen", {}, false},
                      DemoCase{"dlopen", {}, true}, DemoCase{"overlay", {}, false},
                      DemoCase{"overlay", {}, true}),
    caseName);

TEST(Dlopen, ProgramsThatLoadGlThemselvesAreIntercepted)
{
    ASSERT_TRUE(haveDisplay());
    ProcessResult r = runProcess(
        {nprglCommand(), "--", demo("dlopen"), "--frames", "2", "--print-resolved"},
        {{"NPRGL_LOG_LEVEL", "debug"}});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("dlopen(\"libGL.so.1\") answered with nprgl"), std::string::npos)
        << r.err;
    // Pointers from dlsym and from glXGetProcAddressARB both lead into nprgl.
    EXPECT_NE(r.err.find("glClear: ") , std::string::npos) << r.err;
    EXPECT_NE(r.err.find("libnprgl.so"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("libGLX_mesa"), std::string::npos) << r.err;

    ProcessResult native = runProcess({demo("dlopen"), "--frames", "2", "--print-resolved"});
    ASSERT_EQ(native.exitCode, 0) << native.err;
    EXPECT_EQ(native.err.find("libnprgl.so"), std::string::npos) << native.err;
}

TEST(Glxgears, RunsForFramesWithoutErrorAndIsCaptured)
{
    ASSERT_TRUE(haveDisplay());
    std::string shots = freshDir("gears");
    // glxgears runs until it is stopped: stop it once its 30th frame is on disk.
    ProcessResult r = runUntilFile({nprglCommand(), "--style", "none", "--screenshot",
                                    "frames=3,30;dir=" + shots, "glxgears"},
                                   {}, shots + "/glxgears_30.png", SIGINT);
    // Still running happily when our SIGINT ended it: glxgears' own status for that.
    EXPECT_TRUE(r.stopped) << r.err;
    EXPECT_FALSE(r.hung) << r.err;
    EXPECT_EQ(r.exitCode, 128 + SIGINT) << r.err;
    EXPECT_EQ(r.err.find("nprgl: error"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("GL error"), std::string::npos) << r.err;
    expectGlxgearsPicture(shots + "/glxgears_3.png");
    expectGlxgearsPicture(shots + "/glxgears_30.png");
}

TEST(OddPrograms, ProgramsWithoutGlSeeNoDifference)
{
    ProcessResult t = runProcess({nprglCommand(), "--", "/bin/true"});
    EXPECT_EQ(t.exitCode, 0);
    EXPECT_EQ(t.out, "");
    EXPECT_EQ(t.err, "");
    ProcessResult f = runProcess({nprglCommand(), "--", "/bin/false"});
    EXPECT_EQ(f.exitCode, 1);
    // A directory no other test touches, so both listings see the same thing.
    std::string quiet = freshDir("ls");
    std::ofstream(quiet + "/file") << "x";
    ProcessResult lsNative = runProcess({"ls", "-l", quiet});
    ProcessResult lsShim = runProcess({nprglCommand(), "ls", "-l", quiet});
    EXPECT_EQ(lsShim.exitCode, lsNative.exitCode);
    EXPECT_EQ(lsShim.out, lsNative.out);
    EXPECT_EQ(lsShim.err, "");
    // Plain LD_PRELOAD works the same way.
    ProcessResult preload = runProcess({"ls", "-l", quiet}, {{"LD_PRELOAD", preloadValue()}});
    EXPECT_EQ(preload.out, lsNative.out);
    EXPECT_EQ(preload.err, "");
}

// A set-group-ID program that changes the group runs in secure-execution mode, where the
// dynamic loader ignores LD_PRELOAD: nprgl cannot be there, and says so instead of running
// the program silently as it is (/usr/games/pinball is one).
TEST(OddPrograms, ASetGroupIdProgramIsNamedAsOneNprglCannotReach)
{
    if (geteuid() != 0) GTEST_SKIP() << "needs root to give a copy another group";
    const std::string dir = freshDir("setgid");
    const std::string program = dir + "/demo_immediate";
    fs::copy_file(demo("immediate"), program);
    ASSERT_EQ(chown(program.c_str(), 0, 65534), 0) << std::strerror(errno);
    ASSERT_EQ(chmod(program.c_str(), 02755), 0) << std::strerror(errno);
    ProcessResult r = runProcess({nprglCommand(), "--style", "none", "--", program,
                                  "--offscreen", "--frames", "1", "--size", "64x48"});
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find(program + " is set-group-ID: the dynamic loader ignores LD_PRELOAD"),
              std::string::npos)
        << r.err;
}

TEST(OddPrograms, CallsWithoutAContextBehaveAsNative)
{
    std::string probe = binDir() + "/probe_nocontext";
    ProcessResult native = runProcess({probe});
    ProcessResult shim = runProcess({probe}, {{"LD_PRELOAD", preloadValue()}});
    ASSERT_EQ(native.exitCode, 0) << native.err;
    EXPECT_EQ(shim.exitCode, native.exitCode);
    EXPECT_EQ(shim.out, native.out);
    EXPECT_FALSE(native.out.empty());
    EXPECT_EQ(shim.err, native.err);
}

TEST(OddPrograms, ForkExitInAFrameAndUnderscoreExitKeepWorking)
{
    std::string probe = binDir() + "/probe_fork";
    for (const char* mode : {"fork", "exit-mid-frame", "underscore-exit"}) {
        ProcessResult native = runProcess({probe, mode});
        ProcessResult shim = runProcess({probe, mode}, {{"LD_PRELOAD", preloadValue()}});
        EXPECT_EQ(native.exitCode, std::string(mode) == "fork" ? 0 : mode[0] == 'e' ? 3 : 5);
        EXPECT_EQ(shim.exitCode, native.exitCode) << mode << ": " << shim.err;
        EXPECT_EQ(shim.out, native.out) << mode;
        EXPECT_NE(native.out.find("ok"), std::string::npos) << mode << ": " << native.out;
    }
}

TEST(OddPrograms, AMissingRealLibGlGivesOneClearMessage)
{
    // probe_nogl links no GL library; with the fallback pointed at a missing file there is
    // nothing real to forward to, exactly as on a machine without libGL.
    ProcessResult r = runProcess({binDir() + "/probe_nogl"},
                                 {{"LD_PRELOAD", preloadValue()},
                                  {"NPRGL_REAL_LIBGL", "/nonexistent/libGL.so.1"}});
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("glGetString=null"), std::string::npos) << r.out;
    size_t first = r.err.find("no OpenGL library was found");
    EXPECT_NE(first, std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("no OpenGL library was found", first + 1), std::string::npos)
        << "said more than once: " << r.err;
    EXPECT_NE(r.err.find("/nonexistent/libGL.so.1"), std::string::npos) << r.err;
}

TEST(OddPrograms, ARealLibGlNamedByTheOverrideLoadsQuietly)
{
    // The override names a library that exists: it is used, and nothing says it failed.
    ProcessResult r = runProcess({binDir() + "/probe_nogl"},
                                 {{"LD_PRELOAD", preloadValue()}, {"NPRGL_REAL_LIBGL", "libGL.so.1"},
                                  {"NPRGL_LOG_LEVEL", "debug"}});
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.err.find("cannot load"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("no OpenGL library was found"), std::string::npos) << r.err;
}

TEST(Cli, RefusesUnknownStylesAndBadOptionsBeforeStarting)
{
    std::string marker = freshDir("marker") + "/ran";
    ProcessResult r = runProcess({nprglCommand(), "--style", "sparkles", "--", "touch", marker});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("unknown style 'sparkles'"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(marker));
    r = runProcess({nprglCommand(), "--set", "none.width=2", "--", "touch", marker});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("none.width"), std::string::npos) << r.err;
    r = runProcess({nprglCommand(), "--screenshot", "frames=0", "--", "touch", marker});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_FALSE(std::filesystem::exists(marker));
    r = runProcess({nprglCommand(), "--", "/no/such/program"});
    EXPECT_EQ(r.exitCode, 127);
    EXPECT_NE(r.err.find("/no/such/program"), std::string::npos);
    r = runProcess({nprglCommand(), "run", "--", "touch", marker});
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(std::filesystem::exists(marker));
}

TEST(Cli, ListsStylesAndVersion)
{
    ProcessResult r = runProcess({nprglCommand(), "styles"});
    EXPECT_EQ(r.exitCode, 0);
    EXPECT_NE(r.out.find("none"), std::string::npos);
    r = runProcess({nprglCommand(), "--version"});
    EXPECT_EQ(r.exitCode, 0);
    EXPECT_NE(r.out.find("nprgl "), std::string::npos);
    r = runProcess({nprglCommand(), "--help"});
    EXPECT_EQ(r.exitCode, 0);
    EXPECT_NE(r.out.find("NPRGL_SCREENSHOT"), std::string::npos);
}

TEST(Library, AnUnknownStyleInTheEnvironmentFallsBackToPassthrough)
{
    std::string dir = freshDir("envstyle");
    ProcessResult r = runProcess({demo("immediate"), "--offscreen", "--frames", "1",
                                  "--size", "64x64"},
                                 {{"LD_PRELOAD", preloadValue()}, {"NPRGL_STYLE", "sparkles"},
                                  {"NPRGL_SCREENSHOT", "frames=1;dir=" + dir}});
    EXPECT_EQ(r.exitCode, 0);
    EXPECT_NE(r.err.find("unknown style 'sparkles'"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("using style none"), std::string::npos) << r.err;
    EXPECT_TRUE(std::filesystem::exists(dir + "/demo_immediate_1.png"));
}
