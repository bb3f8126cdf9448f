// Hostile configuration, preset and log paths (shim/ConfigFile, shim/Config, styles/Presets,
// common/Log, common/TextFile): FIFOs, devices, directories, huge, binary and unreadable files,
// at start and swapped in while the program runs, are refused at once with their reason and
// the program runs on. "At once" is checked with a hang guard on a child process, never a
// clock: a refused FIFO is never opened, a reverted fix waits on it until the guard ends it.

#include "common/PngImage.h"
#include "common/TextFile.h"
#include "shim/ConfigFile.h"
#include "tests/support/Process.h"
#include "tests/support/ReloadFrames.h"

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <random>

using namespace nprgl;
using namespace nprgl::test;

namespace {

// Generous: a run takes seconds; only a run that waits on a file reaches it.
constexpr int kHangGuardSeconds = 120;

std::string probe() { return binDir() + "/probe_reload"; }

// The environment of a run that reads its files from `home` only, with `extra` over it.
std::map<std::string, std::string> filesIn(const std::string& home,
                                           const std::map<std::string, std::string>& extra = {})
{
    std::map<std::string, std::string> env = {{"XDG_CONFIG_HOME", home},
                                              {"NPRGL_CONFIG_FILE", ""},
                                              {"NPRGL_STYLE", ""},
                                              {"NPRGL_CONFIG", ""},
                                              {"NPRGL_PRESET", ""},
                                              {"NPRGL_LOG_FILE", ""}};
    for (const auto& [key, value] : extra) env[key] = value;
    return env;
}

// probe_reload under nprgl for `frames` frames (saved in `out`, else a fresh folder) with
// `env` over a run that reads no configuration file.
ProcessResult runProbe(const std::map<std::string, std::string>& env, int frames = 2,
                       std::vector<std::string> args = {}, std::string out = "")
{
    if (out.empty()) out = freshDir("hostile_out");
    std::vector<std::string> program = {probe(), "--frames", std::to_string(frames),
                                        "--save-dir", out};
    program.insert(program.end(), args.begin(), args.end());
    return runProcess(under({nprglCommand()}, program), filesIn(freshDir("hostile_home"), env),
                      kHangGuardSeconds);
}

std::string makeFifo(const std::string& name)
{
    const std::string path = freshDir(name) + "/" + name;
    EXPECT_EQ(mkfifo(path.c_str(), 0644), 0) << std::strerror(errno);
    return path;
}

size_t countOf(const std::string& log, const std::string& text)
{
    size_t n = 0;
    for (size_t at = log.find(text); at != std::string::npos; at = log.find(text, at + 1))
        ++n;
    return n;
}

bool has(const std::string& log, const std::string& text)
{
    return log.find(text) != std::string::npos;
}

// Runs `body` in a child process under the hang guard: its exit status, or -1 when the guard
// had to end it.
int inChild(const std::function<int()>& body)
{
    const pid_t pid = fork();
    if (pid == 0) _exit(body());
    int status = 0;
    for (int waited = 0; waitpid(pid, &status, WNOHANG) != pid; ++waited) {
        if (waited == kHangGuardSeconds * 20) {
            kill(pid, SIGKILL);
            waitpid(pid, &status, 0);
            return -1;
        }
        usleep(50000);
    }
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

} // namespace

TEST(ConfigHostile, AFifoAsTheConfigFileIsRefusedAtOnce)
{
    const std::string fifo = makeFifo("config_fifo");
    const ProcessResult r = runProbe({{"NPRGL_CONFIG_FILE", fifo}});
    ASSERT_FALSE(r.hung) << "waited on the FIFO\n" << r.err;
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.out, "ok\n");
    EXPECT_TRUE(has(r.err, fifo + ": not a regular file (a FIFO); ignored\n")) << r.err;
    EXPECT_TRUE(has(r.err, "configuration files: none read (refused: " + fifo + ")")) << r.err;
    EXPECT_TRUE(has(r.err, "probe_reload: style toon+paper+edges\n")) << r.err;
}

TEST(ConfigHostile, AFifoAsTheLogFileIsRefusedAtOnce)
{
    const std::string fifo = makeFifo("log_fifo");
    const ProcessResult r = runProbe({{"NPRGL_LOG_FILE", fifo}});
    ASSERT_FALSE(r.hung) << "waited on the FIFO\n" << r.err;
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.out, "ok\n");
    EXPECT_TRUE(has(r.err, "NPRGL_LOG_FILE=" + fifo +
                               ": not a regular file (a FIFO); logging to stderr\n"))
        << r.err;
    EXPECT_TRUE(has(r.err, "probe_reload: style toon+paper+edges\n")) << "not logged\n" << r.err;
}

// Without the look before the open, /dev/zero and /dev/urandom were read until memory ran out.
TEST(ConfigHostile, DevicesAsTheConfigFileAreRefusedUnread)
{
    for (const std::string device : {"/dev/zero", "/dev/urandom", "/dev/null"}) {
        const ProcessResult r = runProbe({{"NPRGL_CONFIG_FILE", device}});
        ASSERT_FALSE(r.hung) << device << " read without end\n" << r.err;
        ASSERT_EQ(r.exitCode, 0) << device << "\n" << r.err;
        EXPECT_TRUE(
            has(r.err, device + ": not a regular file (a character device); ignored\n"))
            << r.err;
        EXPECT_TRUE(has(r.err, "probe_reload: style toon+paper+edges\n")) << r.err;
    }
}

TEST(ConfigHostile, ADirectoryAsTheConfigFileIsNotListedAsRead)
{
    const std::string dir = freshDir("config_dir");
    const ProcessResult r = runProbe({{"NPRGL_CONFIG_FILE", dir}});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(has(r.err, dir + ": not a regular file (a directory); ignored\n")) << r.err;
    EXPECT_TRUE(has(r.err, "configuration files: none read (refused: " + dir + ")")) << r.err;
}

// A file over 1 MiB is not read at all (a 100 MB one took 50 s); one of exactly 1 MiB is.
TEST(ConfigHostile, AConfigFileOverTheLimitIsRefusedUnread)
{
    const std::string dir = freshDir("config_big");
    const std::string line = "# a comment line of sixteen+ bytes\n";
    std::string text = "style=toon\n";
    while (text.size() + line.size() <= TextFile::kLimit) text += line;
    text.append(TextFile::kLimit - text.size(), '#');
    ASSERT_EQ(text.size(), TextFile::kLimit);
    std::ofstream(dir + "/limit.conf") << text;
    std::ofstream(dir + "/over.conf") << text << "\n";

    const ProcessResult at = runProbe({{"NPRGL_CONFIG_FILE", dir + "/limit.conf"}});
    ASSERT_EQ(at.exitCode, 0) << at.err;
    EXPECT_TRUE(has(at.err, "probe_reload: style toon\n")) << at.err;

    const ProcessResult over = runProbe({{"NPRGL_CONFIG_FILE", dir + "/over.conf"}});
    ASSERT_EQ(over.exitCode, 0) << over.err;
    EXPECT_TRUE(has(over.err, dir + "/over.conf: 1048577 bytes, over the 1 MiB a configuration "
                                    "file may have; not read; ignored\n"))
        << over.err;
    EXPECT_TRUE(has(over.err, "probe_reload: style toon+paper+edges\n")) << over.err;
}

// 1 MB of random bytes after a good line: one line says so, with where the binary data
// starts, and nothing of the file applies (it had written thousands of lines, and applied
// the first).
TEST(ConfigHostile, ABinaryConfigFileGetsOneMessage)
{
    const std::string path = freshDir("config_binary") + "/random.conf";
    std::string text = "style=toon\n";
    std::mt19937 random(41);
    for (int i = 0; i < 1000000; ++i) text += char(random() & 0xff);
    text[11] = '\0';
    std::ofstream(path, std::ios::binary) << text;
    const ProcessResult r = runProbe({{"NPRGL_CONFIG_FILE", path}});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(countOf(r.err, path + ":"), 1u) << r.err.substr(0, 4000);
    EXPECT_TRUE(has(r.err, path + ": not a configuration file (binary data at offset 11); "
                                  "ignored\n"))
        << r.err.substr(0, 4000);
    EXPECT_TRUE(has(r.err, "probe_reload: style toon+paper+edges\n")) << r.err.substr(0, 4000);
}

// A text file that is no configuration (1,000 lines of prose): its first five bad lines, then
// their count; a good line in it still applies.
TEST(ConfigHostile, ATextFileOfBadLinesGetsFiveMessagesAndACount)
{
    const std::string path = freshDir("config_prose") + "/prose.conf";
    std::string text;
    for (int i = 0; i < 1000; ++i) text += "lorem ipsum dolor sit amet\n";
    text += "style=toon\n";
    std::ofstream(path) << text;
    const ProcessResult r = runProbe({{"NPRGL_CONFIG_FILE", path}});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(countOf(r.err, path + ":"), 6u) << r.err.substr(0, 4000);
    EXPECT_TRUE(has(r.err, path + ":5: expected key=value")) << r.err.substr(0, 4000);
    EXPECT_TRUE(has(r.err, path + ": 995 more bad lines skipped\n")) << r.err.substr(0, 4000);
    EXPECT_TRUE(has(r.err, "probe_reload: style toon\n")) << r.err.substr(0, 4000);
}

// A file that is there but cannot be read says why, not "not found". As root every permission
// check passes, so the path that always fails to open is a symbolic link to itself; the
// permission case runs when the tests do not run as root.
TEST(ConfigHostile, AnUnreadableConfigFileSaysWhyAndIsNotCalledMissing)
{
    const std::string dir = freshDir("config_unreadable");
    const std::string loop = dir + "/loop.conf";
    std::filesystem::create_symlink("loop.conf", loop);
    const ProcessResult r = runProbe({{"NPRGL_CONFIG_FILE", loop}});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(has(r.err, loop + ": cannot read: " + std::strerror(ELOOP) + "; ignored\n"))
        << r.err;
    EXPECT_FALSE(has(r.err, "not found")) << r.err;

    if (geteuid() == 0) {
        GTEST_LOG_(INFO) << "running as root: a file without read permission opens; not tried";
        return;
    }
    const std::string locked = dir + "/locked.conf";
    std::ofstream(locked) << "style=toon\n";
    std::filesystem::permissions(locked, std::filesystem::perms::none);
    const ConfigFile f = ConfigFile::read(locked);
    EXPECT_FALSE(f.found);
    EXPECT_EQ(f.refused, std::string("cannot read: ") + std::strerror(EACCES));
}

// The file replaced by a FIFO after frame 2 (as an editor renames a new file over it): the
// frame end that notices it does not wait on it, says so once and keeps the file's look.
TEST(ConfigHostile, AConfigSwappedForAFifoWhileRunningKeepsItsLook)
{
    const std::string home = freshDir("swap_fifo"), file = home + "/nprgl/nprgl.conf";
    std::filesystem::create_directories(home + "/nprgl");
    std::ofstream(file) << "style=toon+edges\n";
    const std::string styled = freshDir("swap_fifo_styled"), live = freshDir("swap_fifo_live");
    const ProcessResult s = runProbe({{"NPRGL_STYLE", "toon+edges"}}, 4, {}, styled);
    ASSERT_EQ(s.exitCode, 0) << s.err;
    const ProcessResult r =
        runProcess(under({nprglCommand()}, {probe(), "--frames", "4", "--save-dir", live,
                                            "--file", file, "--fifo-at", "2"}),
                   filesIn(home), kHangGuardSeconds);
    ASSERT_FALSE(r.hung) << "waited on the FIFO\n" << r.err;
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(countOf(r.err, file + ": not a regular file (a FIFO); ignored, its previous lines "
                                    "stay\n"),
              1u)
        << r.err;
    EXPECT_FALSE(has(r.err, "configuration changed")) << r.err;
    EXPECT_EQ(differing(frame(styled, 4), frame(live, 4)), 0);
}

// The file replaced by binary data while running: one line, and the look it had stays (it
// had become the default look, the garbage read as a file of one bad line).
TEST(ConfigHostile, AConfigSwappedForBinaryDataWhileRunningKeepsItsLook)
{
    const std::string home = freshDir("swap_binary"), file = home + "/nprgl/nprgl.conf";
    std::filesystem::create_directories(home + "/nprgl");
    std::ofstream(file) << "style=toon+edges\n";
    const std::string styled = freshDir("swap_binary_styled"), live = freshDir("swap_bin_live");
    const ProcessResult s = runProbe({{"NPRGL_STYLE", "toon+edges"}}, 4, {}, styled);
    ASSERT_EQ(s.exitCode, 0) << s.err;
    const ProcessResult r =
        runProcess(under({nprglCommand()}, {probe(), "--frames", "4", "--save-dir", live,
                                            "--file", file, "--at", "2", "--text", "\x01\x7f"}),
                   filesIn(home), kHangGuardSeconds);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(countOf(r.err, file + ":"), 1u) << r.err;
    EXPECT_TRUE(has(r.err, file + ": not a configuration file (binary data at offset 0); "
                                  "ignored, its previous lines stay\n"))
        << r.err;
    EXPECT_FALSE(has(r.err, "configuration changed")) << r.err;
    EXPECT_EQ(differing(frame(styled, 4), frame(live, 4)), 0);
}

// A preset file that is a FIFO: refused at once by the library (NPRGL_PRESET, and a preset=
// line of a configuration file) and by the command (--preset).
TEST(ConfigHostile, APresetFileThatIsAFifoIsRefusedAtOnce)
{
    const std::string fifo = makeFifo("preset_fifo");
    const std::string why = "preset file " + fifo + ": not a regular file (a FIFO)";
    std::map<std::string, std::string> env = filesIn(freshDir("preset_home"));
    env["LD_PRELOAD"] = preloadValue();
    env["NPRGL_PRESET"] = fifo;
    const std::vector<std::string> program = {probe(), "--frames", "1", "--save-dir",
                                              freshDir("preset_out")};
    const ProcessResult lib = runProcess(program, env, kHangGuardSeconds);
    ASSERT_FALSE(lib.hung) << "waited on the FIFO\n" << lib.err;
    ASSERT_EQ(lib.exitCode, 0) << lib.err;
    EXPECT_TRUE(has(lib.err, "NPRGL_PRESET: " + why + "; preset ignored\n")) << lib.err;

    const std::string conf = freshDir("preset_conf") + "/p.conf";
    std::ofstream(conf) << "preset=" << fifo << "\n";
    const ProcessResult line = runProbe({{"NPRGL_CONFIG_FILE", conf}}, 1);
    ASSERT_FALSE(line.hung) << "waited on the FIFO\n" << line.err;
    ASSERT_EQ(line.exitCode, 0) << line.err;
    EXPECT_TRUE(has(line.err, conf + ":1: preset: " + why + "; line skipped\n")) << line.err;

    const ProcessResult command =
        runProcess(under({nprglCommand(), "--preset", fifo}, program),
                   filesIn(freshDir("preset_home")), kHangGuardSeconds);
    ASSERT_FALSE(command.hung) << "waited on the FIFO\n" << command.err;
    EXPECT_NE(command.exitCode, 0) << command.err;
    EXPECT_TRUE(has(command.err, why)) << command.err;
}

// The overlay's save over a configuration path that is a FIFO: refused, not waited on.
TEST(ConfigHostile, SavingALookOverAFifoIsRefused)
{
    const std::string fifo = makeFifo("save_fifo");
    const int status = inChild([&] {
        std::string error;
        if (ConfigFile::writeLook(fifo, "toon", "", {}, error)) return 1;
        return error == "not saved: " + fifo + ": not a regular file (a FIFO)" ? 0 : 2;
    });
    EXPECT_EQ(status, 0) << "1: saved over it, 2: another reason, -1: waited on it";
    struct stat st {};
    ASSERT_EQ(stat(fifo.c_str(), &st), 0);
    EXPECT_TRUE(S_ISFIFO(st.st_mode)) << "replaced";
}
