// The nprgl command's own interface: exit statuses, help and version.
#include "tests/support/Process.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

using namespace nprgl::test;

namespace {

ProcessResult runNprgl(std::vector<std::string> args)
{
    args.insert(args.begin(), nprglCommand());
    return runProcess(args, {}, 120);
}

} // namespace

// CLI11 ends with its own codes (106, 109, 114...); scripts need one: 2 for every misuse.
TEST(Cli, EveryUsageErrorExitsWithTwo)
{
    const std::string missing = freshDir("cli") + "/none.nprgl";
    const std::vector<std::vector<std::string>> misuses = {
        {"replay"},
        {"replay", missing, "-o", freshDir("cli_o"), "--frames", "abc"},
        {"replay", missing, "--size", "big", "--stats"},
        {"replay", missing, "--no-such-option"},
        {"replay", missing},
        {"dump"},
        {"dump", missing, "--frames", "1-x"},
        {"info"},
        {"info", missing, "extra"},
        {"export", missing},
        {"export", missing, "--frame", "one", "-o", "x.obj"},
        {"compare"},
        {"compare", std::string(NPRGL_TEST_SOURCE_DIR) + "/fixtures/glxgears.nprgl", "--style",
         "no-such-style"},
        {"compare", std::string(NPRGL_TEST_SOURCE_DIR) + "/fixtures/glxgears.nprgl", "--set",
         "toon.tones=99"},
        {"styles", "extra"},
        {"help", "no-such-command"},
        {"--style", "no-such-style", "--", "true"},
        {"--set", "toon.no_such=1", "--", "true"},
        {"--log-level", "loud", "--", "true"},
        {"record", "--frames", "x", "--", "true"},
        {"--no-such-option", "--", "true"},
        {},
    };
    for (const auto& args : misuses) {
        std::string line;
        for (const std::string& a : args) line += " " + a;
        ProcessResult r = runNprgl(args);
        EXPECT_EQ(r.exitCode, 2) << "nprgl" << line << "\n" << r.err;
        EXPECT_EQ(r.err.rfind("nprgl", 0), 0u) << "nprgl" << line << "\n" << r.err;
    }
}

TEST(Cli, AFailureThatIsNotMisuseExitsWithOne)
{
    ProcessResult r = runNprgl({"info", freshDir("cli_fail") + "/none.nprgl"});
    EXPECT_EQ(r.exitCode, 1) << r.err;
}

TEST(Cli, HelpAndVersionAreCommands)
{
    ProcessResult help = runNprgl({"help"});
    EXPECT_EQ(help.exitCode, 0) << help.err;
    EXPECT_NE(help.out.find("Commands:"), std::string::npos) << help.out;
    ProcessResult replay = runNprgl({"help", "replay"});
    EXPECT_EQ(replay.exitCode, 0) << replay.err;
    EXPECT_NE(replay.out.find("nprgl replay"), std::string::npos) << replay.out;
    EXPECT_NE(replay.out.find("--frames"), std::string::npos) << replay.out;
    const std::regex version(R"(nprgl \d+\.\d+\.\d+\n)");
    ProcessResult v = runNprgl({"version"});
    EXPECT_EQ(v.exitCode, 0) << v.err;
    EXPECT_TRUE(std::regex_match(v.out, version)) << v.out;
    ProcessResult dashed = runNprgl({"--version"});
    EXPECT_TRUE(std::regex_match(dashed.out, version)) << dashed.out;
    // A program that has a command's name runs after "run".
    ProcessResult program = runNprgl({"run", "help"});
    EXPECT_EQ(program.exitCode, 127) << program.err;
    EXPECT_NE(program.err.find("cannot run 'help'"), std::string::npos) << program.err;
}

// The nprgl command links the library's code to replay, but its start-up (the log file, the
// recording's claim) is the program's: a log file it cannot use is said once, by the program.
TEST(Cli, TheProgramAloneOpensTheLogFile)
{
    const std::string folder = freshDir("cli_log");
    ProcessResult r = runProcess({nprglCommand(), "--style", "none", "--", demo("immediate"),
                                  "--offscreen", "--frames", "1"},
                                 {{"NPRGL_LOG_FILE", folder}}, 120);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    size_t said = 0;
    for (size_t at = r.err.find("NPRGL_LOG_FILE"); at != std::string::npos;
         at = r.err.find("NPRGL_LOG_FILE", at + 1)) {
        ++said;
    }
    EXPECT_EQ(said, 1u) << r.err;
}

// `nprgl %command%` as a Steam launch option: the launcher's command line may start with
// NAME=value words and holds wrappers with options of their own, some named like nprgl's, and
// a "--" of their own. The assignments go to the environment (as the shell takes them); from
// the program on, every word reaches it untouched and in order.
TEST(Cli, ALaunchersCommandLinePassesThroughUntouched)
{
    const std::string script = "printf '<%s>' \"$NPRGL_TEST_GAME\" \"$@\"; printf '\\n%s\\n' "
                               "\"$LD_PRELOAD\"";
    const std::vector<std::string> program = {
        "sh", "-c", script, "wrapper", "--style", "toon", "--", "-o", "x.nprgl", "A=1", "--help",
        "--set=toon.x=1"};
    for (const char* command : {"run", "record"}) {
        SCOPED_TRACE(command);
        std::vector<std::string> args = {command, "--style", "none"};
        if (std::string(command) == "record") {
            args.insert(args.end(), {"-o", freshDir("cli_launcher") + "/sh.nprgl"});
        }
        args.insert(args.end(), {"NPRGL_TEST_GAME=game=1", "NPRGL_TEST_OTHER=2"});
        args.insert(args.end(), program.begin(), program.end());
        ProcessResult r = runNprgl(args);
        ASSERT_EQ(r.exitCode, 0) << r.err;
        const size_t line = r.out.find('\n');
        EXPECT_EQ(r.out.substr(0, line),
                  "<game=1><--style><toon><--><-o><x.nprgl><A=1><--help><--set=toon.x=1>");
        EXPECT_NE(r.out.find("libnprgl.so", line), std::string::npos) << r.out;
    }
    // After "--" too, and a word that is no NAME=value is the program.
    ProcessResult dashed =
        runNprgl({"--", "NPRGL_TEST_GAME=2", "sh", "-c", "echo $NPRGL_TEST_GAME"});
    EXPECT_EQ(dashed.out, "2\n") << dashed.err;
    ProcessResult notName = runNprgl({"--style", "none", "1A=2", "true"});
    EXPECT_EQ(notName.exitCode, 127) << notName.err;
    EXPECT_NE(notName.err.find("cannot run '1A=2'"), std::string::npos) << notName.err;
}

// The build tree mirrors the installed layout: build/bin/nprgl preloads
// build/$LIB/nprgl/libnprgl.so, which the loader reads as this build's library in a
// 64-bit program and as scripts/build-i386.sh's in a 32-bit one (tests/i386).
TEST(Cli, TheBuildTreesCommandPreloadsThroughTheLoadersLib)
{
    ProcessResult preload = runNprgl({"--style", "none", "--", "printenv", "LD_PRELOAD"});
    ASSERT_EQ(preload.exitCode, 0) << preload.err;
    const std::string entry =
        std::filesystem::canonical(binDir() + "/..").string() + "/$LIB/nprgl/libnprgl.so";
    EXPECT_NE(preload.out.find(entry), std::string::npos) << preload.out;
    // ...and the loader maps this build's library through it.
    ProcessResult maps = runNprgl({"--style", "none", "--", "cat", "/proc/self/maps"});
    ASSERT_EQ(maps.exitCode, 0) << maps.err;
    EXPECT_NE(maps.out.find(libPath()), std::string::npos) << libPath() << "\n" << maps.out;
}

// A style reads its parameters by name; one it does not declare (a misspelling in nprgl) gets
// 0, and is said. Every style that `nprgl styles` lists renders a fixture's frames without
// that message, with its defaults and in the chain alone.
TEST(Cli, EveryStyleReadsOnlyTheParametersItDeclares)
{
    ProcessResult list = runProcess({nprglCommand(), "styles"});
    ASSERT_EQ(list.exitCode, 0);
    std::istringstream lines(list.out.substr(0, list.out.find("Presets")));
    std::string line;
    std::getline(lines, line); // the title
    const std::regex styleLine(R"(([a-z][a-z_-]*)( \[[a-z]+\])?)");
    std::smatch m;
    int count = 0;
    while (std::getline(lines, line)) {
        if (!std::regex_match(line, m, styleLine) || m[1] == "none") continue;
        const std::string dir = freshDir("params_" + m[1].str());
        ProcessResult r = runProcess({nprglCommand(), "replay", fixture("textured"), "--style",
                                      m[1].str(), "--frames", "2", "-o", dir});
        EXPECT_EQ(r.exitCode, 0) << m[1] << ": " << r.err;
        EXPECT_EQ(r.err.find("which no style declares"), std::string::npos)
            << m[1] << ": " << r.err;
        ++count;
    }
    EXPECT_GE(count, 10) << list.out;
}
