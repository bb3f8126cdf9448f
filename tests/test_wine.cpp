// End to end: a Windows legacy-GL program (tests/wine/wingl.c, built with mingw-w64) run by
// Debian's wine natively and through nprgl: styled, recorded and replayed.

#include "tests/support/ImageCompare.h"
#include "tests/support/Process.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

using namespace nprgl;
using namespace nprgl::test;
namespace fs = std::filesystem;

namespace {

const std::string kPrefix = NPRGL_WINE_PREFIX;
// Debian's wine32:i386 installs the 32-bit loader here; without it wine runs no 32-bit .exe.
const std::string kWine32Loader = "/usr/lib/wine/wine";
// Debian's wine64 loader: the one `wine` runs when there is no 32-bit one.
const std::string kWine64Loader = "/usr/lib/wine/wine64";

// Whether wine's 32-bit half can run here: installed, and a kernel that runs 32-bit code.
bool wine32Runs() { return fs::exists(kWine32Loader) && why32BitProgramsCannotRun().empty(); }

// The command that starts a Windows program. Debian's `wine` picks the 32-bit loader whenever
// it is installed, even on a kernel that cannot run it (every program then fails with "Exec
// format error"); there the 64-bit loader is what runs a 64-bit program.
std::vector<std::string> wineCommand()
{
    if (wine32Runs() || !fs::exists(kWine64Loader)) return {"wine"};
    return {kWine64Loader};
}

// The 64-bit program with nprgl's own library; the 32-bit one with the i386 library.
struct WineCase {
    int bits;
    std::string exe;
    std::string library;
};

void PrintTo(const WineCase& c, std::ostream* os) { *os << c.bits << "-bit " << c.exe; }

// A command in PATH, or empty.
std::string inPath(const std::string& name)
{
    const char* path = std::getenv("PATH");
    std::stringstream dirs(path ? path : "");
    std::string dir;
    while (std::getline(dirs, dir, ':')) {
        const fs::path candidate = fs::path(dir.empty() ? "." : dir) / name;
        if (access(candidate.c_str(), X_OK) == 0) return candidate.string();
    }
    return {};
}

// A private prefix in the build tree; no Mono or Gecko installer prompts, no Wine chatter.
std::map<std::string, std::string> wineEnv()
{
    std::map<std::string, std::string> env = {
        {"WINEPREFIX", kPrefix}, {"WINEDEBUG", "-all"}, {"WINEDLLOVERRIDES", "mscoree,mshtml="}};
    // Wine's own child processes (wineboot's services, start.exe) come from WINELOADER.
    if (wineCommand()[0] != "wine") env["WINELOADER"] = wineCommand()[0];
    return env;
}

// Waits until the prefix's wineserver and the processes it started (explorer, services) are
// gone, so no test leaves them behind nor finds them from the one before.
void waitForWineserver()
{
    ProcessResult r = runProcess({"wineserver", "-w"}, wineEnv());
    ASSERT_EQ(r.exitCode, 0) << r.err;
}

// The nprgl command line for a case: the i386 library named for a 32-bit program.
std::map<std::string, std::string> nprglEnv(const WineCase& c)
{
    std::map<std::string, std::string> env = wineEnv();
    if (!c.library.empty()) env["NPRGL_LIBRARY"] = c.library;
    return env;
}

class Wine : public ::testing::TestWithParam<WineCase> {
protected:
    std::string exeName() const { return "wingl" + std::to_string(GetParam().bits) + ".exe"; }
    std::vector<std::string> wingl(int frames) const
    {
        std::vector<std::string> argv = wineCommand();
        argv.insert(argv.end(), {GetParam().exe, "--frames", std::to_string(frames)});
        return argv;
    }
    // For the runs through nprgl: a 32-bit program needs the i386 library.
    void needLibrary() const
    {
        const std::string& library = GetParam().library;
        if (!library.empty() && !fs::exists(library)) {
            GTEST_SKIP() << "no i386 libnprgl.so at " << library
                         << ": the i386 build of the library makes it";
        }
    }
    void SetUp() override
    {
#if defined(__SANITIZE_ADDRESS__)
        // The sanitized library brings the ASan runtime into the preload, and wine's loader
        // does not start with it (wineboot.exe and start.exe fail to load).
        GTEST_SKIP() << "wine does not start with the AddressSanitizer runtime preloaded";
#endif
        if (inPath("wine").empty() || inPath("wineserver").empty()) {
            GTEST_SKIP() << "wine is not installed (scripts/install-deps.sh installs wine64)";
        }
        const WineCase& c = GetParam();
        if (c.exe.empty()) {
            const std::string arch = c.bits == 64 ? "x86-64" : "i686";
            const std::string gcc = c.bits == 64 ? "x86_64" : "i686";
            GTEST_SKIP() << gcc << "-w64-mingw32-gcc was not found when the build was "
                         << "configured: install gcc-mingw-w64-" << arch
                         << "-win32 and reconfigure";
        }
        if (c.bits == 32 && !fs::exists(kWine32Loader)) {
            GTEST_SKIP() << "wine32 is not installed (" << kWine32Loader
                         << "; on Debian: dpkg --add-architecture i386, wine32:i386)";
        }
        if (c.bits == 32 && !wine32Runs()) {
            GTEST_SKIP() << "wine32 cannot run here: " << why32BitProgramsCannotRun();
        }
        const char* display = std::getenv("DISPLAY");
        ASSERT_TRUE(display && *display) << "run through scripts/test.sh (Xvfb)";
        // The first boot makes the prefix; a marker says it finished (a boot cut short is
        // redone from nothing).
        // A prefix booted before wine32 was installed (or removed) has no (or a stale)
        // 32-bit half: the marker names the loaders it was booted with.
        const fs::path booted = fs::path(kPrefix) / "nprgl-booted";
        const std::string loaders = wine32Runs() ? "wine64 wine32" : "wine64";
        std::string was;
        std::getline(std::ifstream(booted.string()) >> std::ws, was);
        if (was != loaders) {
            fs::remove_all(kPrefix);
            std::vector<std::string> boot = wineCommand();
            boot.insert(boot.end(), {"wineboot", "-i"});
            ProcessResult r = runProcess(boot, wineEnv(), 600);
            ASSERT_EQ(r.exitCode, 0) << r.err;
            waitForWineserver();
            std::ofstream(booted.string()) << loaders << "\n";
        }
    }
    void TearDown() override
    {
        if (!IsSkipped()) waitForWineserver();
    }
};

// The one file in dir whose name starts with prefix and ends with suffix, or empty.
std::string onlyFile(const std::string& dir, const std::string& prefix, const std::string& suffix,
                     std::string& all)
{
    std::string found;
    int count = 0;
    for (const auto& entry : fs::directory_iterator(dir)) {
        const std::string name = entry.path().filename().string();
        all += name + " ";
        if (name.starts_with(prefix) && name.ends_with(suffix)) {
            found = entry.path().string();
            ++count;
        }
    }
    return count == 1 ? found : std::string();
}

std::string screenshotOf(const std::string& dir, const std::string& exe, int frame)
{
    std::string all;
    if (!fs::exists(dir)) return {};
    std::string found = onlyFile(dir, exe + "_", "_" + std::to_string(frame) + ".png", all);
    EXPECT_FALSE(found.empty()) << "no " << exe << "_*_" << frame << ".png in " << dir << ": "
                                << all;
    return found;
}

} // namespace

TEST_P(Wine, TheProgramRunsNatively)
{
    ProcessResult r = runProcess(wingl(5), wineEnv());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("wingl: drew 5 frames"), std::string::npos) << r.out;
    EXPECT_EQ(r.err.find("nprgl:"), std::string::npos) << r.err;
}

// `nprgl wine prog.exe`: the library comes into the process that draws through the libGL
// that Wine's winex11 loads with dlopen; the default style changes the picture, and the log
// names the program (not "", as wine rewrites the loader's arguments) and the context.
TEST_P(Wine, DefaultStyleRestylesTheWindowsProgram)
{
    needLibrary();
    if (IsSkipped()) return;
    const std::string dir = freshDir("wine-style");
    ProcessResult native = runProcess(
        under({nprglCommand(), "--style", "none", "--screenshot", "frames=3;dir=" + dir + "/none"},
              wingl(5)),
        nprglEnv(GetParam()));
    ASSERT_EQ(native.exitCode, 0) << native.err;
    ProcessResult styled = runProcess(
        under({nprglCommand(), "--screenshot", "frames=3;dir=" + dir + "/styled"}, wingl(5)),
        nprglEnv(GetParam()));
    ASSERT_EQ(styled.exitCode, 0) << styled.err;
    EXPECT_NE(styled.out.find("wingl: drew 5 frames"), std::string::npos) << styled.out;
    const std::regex named("nprgl: wingl" + std::to_string(GetParam().bits) +
                           "\\.exe: style toon\\+paper\\+edges");
    EXPECT_TRUE(std::regex_search(styled.err, named)) << styled.err;
    EXPECT_TRUE(std::regex_search(
        styled.err, std::regex("context [0-9]+: style toon\\+paper\\+edges on llvmpipe")))
        << styled.err;
    // The cube, the quad and the triangle, five frames: every one restyled.
    EXPECT_TRUE(std::regex_search(
        styled.err, std::regex("context [0-9]+: 3D polygon draws: 15 styled, 0 left")))
        << styled.err;
    const std::string none = screenshotOf(dir + "/none", exeName(), 3);
    const std::string toon = screenshotOf(dir + "/styled", exeName(), 3);
    ASSERT_FALSE(none.empty() || toon.empty());
    ImageDiff diff = compareImages(none, toon, 8);
    ASSERT_TRUE(diff.comparable) << diff.error;
    EXPECT_GT(diff.differingPixels, 320u * 240u / 20) << "the style changed too little";
}

// `nprgl record -- wine prog.exe`: the capture is the file asked for (the process that draws
// is the one nprgl started: wine execs its loader in place, and wineserver and Wine's own
// processes draw nothing), it names the Windows program, and it replays as drawn.
TEST_P(Wine, RecordedAndReplayedAsDrawn)
{
    needLibrary();
    if (IsSkipped()) return;
    const std::string dir = freshDir("wine-record");
    const std::string file = dir + "/wingl.nprgl";
    ProcessResult r = runProcess(under({nprglCommand(), "record", "--style", "none", "-o", file,
                                        "--screenshot", "frames=3;dir=" + dir + "/live"},
                                       wingl(5)),
                                 nprglEnv(GetParam()));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("nprgl: recorded 5 frames to " + file), std::string::npos) << r.err;
    waitForWineserver();
    std::string all;
    EXPECT_EQ(onlyFile(dir, "", ".nprgl", all), file) << "captures: " << all;

    ProcessResult info = runProcess({nprglCommand(), "info", "--json", file});
    ASSERT_EQ(info.exitCode, 0) << info.err;
    const nlohmann::json meta = nlohmann::json::parse(info.out);
    EXPECT_EQ(meta["program"], exeName());
    ASSERT_FALSE(meta["commandLine"].empty());
    EXPECT_EQ(meta["commandLine"].back(), "5") << meta["commandLine"].dump();

    const std::string replay = dir + "/replay";
    ProcessResult p = runProcess({nprglCommand(), "replay", "--style", "none", file, "-o", replay});
    ASSERT_EQ(p.exitCode, 0) << p.err;
    const std::string live = screenshotOf(dir + "/live", exeName(), 3);
    ASSERT_FALSE(live.empty());
    if (GetParam().bits == 64) {
        ImageDiff diff = compareImages(live, framePng(replay, 3));
        ASSERT_TRUE(diff.comparable) << diff.error;
        EXPECT_EQ(diff.differingPixels, 0u);
    } else {
        // Drawn live by the i386 Mesa, replayed by the amd64 one, which may round a vertex or
        // a shade the other way (as tests/test_i386.cpp says): a pixel along an edge, or 2
        // levels, and nothing else.
        ImageDiff diff = compareImages(live, framePng(replay, 3), 2);
        ASSERT_TRUE(diff.comparable) << diff.error;
        EXPECT_EQ(diff.offEdgePixels, 0u);
        EXPECT_LT(diff.differingPixels, 320u * 240u / 1000);
    }
    EXPECT_TRUE(fs::exists(framePng(replay, 5)));
    EXPECT_FALSE(fs::exists(framePng(replay, 6)));

    // And in the default style, headless.
    const std::string styled = dir + "/styled";
    ProcessResult s = runProcess({nprglCommand(), "replay", file, "-o", styled});
    ASSERT_EQ(s.exitCode, 0) << s.err;
    ImageDiff styledDiff = compareImages(live, framePng(styled, 3), 8);
    ASSERT_TRUE(styledDiff.comparable) << styledDiff.error;
    EXPECT_GT(styledDiff.differingPixels, 320u * 240u / 20);
}

INSTANTIATE_TEST_SUITE_P(Windows, Wine,
                         ::testing::Values(WineCase{64, NPRGL_WINGL64, ""},
                                           WineCase{32, NPRGL_WINGL32, NPRGL_I386_LIBRARY}),
                         [](const ::testing::TestParamInfo<WineCase>& param) {
                             return "bits" + std::to_string(param.param.bits);
                         });
