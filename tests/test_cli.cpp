// The nprgl command's own interface: exit statuses, help and version.
#include "tests/support/Process.h"

#include <gtest/gtest.h>

#include <regex>
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
