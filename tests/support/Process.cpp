#include "tests/support/Process.h"

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <spawn.h>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace nprgl::test {

namespace {

std::string slurp(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

} // namespace

ProcessResult runProcess(const std::vector<std::string>& argv,
                         const std::map<std::string, std::string>& env, int timeoutSeconds)
{
    return runUntil(argv, env, nullptr, SIGINT, timeoutSeconds);
}

ProcessResult runUntilFile(const std::vector<std::string>& argv,
                           const std::map<std::string, std::string>& env,
                           const std::string& stopFile, int stopSignal, int timeoutSeconds)
{
    return runUntil(
        argv, env, [&] { return std::filesystem::exists(stopFile); }, stopSignal, timeoutSeconds);
}

ProcessResult runUntil(const std::vector<std::string>& argv,
                       const std::map<std::string, std::string>& env,
                       const std::function<bool()>& stopWhen, int stopSignal, int timeoutSeconds)
{
    ProcessResult result;
    std::map<std::string, std::string> merged;
    for (char** e = environ; *e; ++e) {
        const char* eq = std::strchr(*e, '=');
        if (eq) merged[std::string(*e, size_t(eq - *e))] = eq + 1;
    }
    for (const auto& [key, value] : env) {
        if (value.empty()) {
            merged.erase(key);
        } else {
            merged[key] = value;
        }
    }
    std::vector<std::string> envStrings;
    for (const auto& [key, value] : merged)
        envStrings.push_back(key + "=" + value);
    std::vector<char*> envp, args;
    for (auto& s : envStrings)
        envp.push_back(s.data());
    envp.push_back(nullptr);
    std::vector<std::string> argCopy = argv;
    for (auto& s : argCopy)
        args.push_back(s.data());
    args.push_back(nullptr);

    std::string dir = freshDir("proc");
    std::string outPath = dir + "/out", errPath = dir + "/err";
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 1, outPath.c_str(), O_WRONLY | O_CREAT, 0644);
    posix_spawn_file_actions_addopen(&actions, 2, errPath.c_str(), O_WRONLY | O_CREAT, 0644);
    pid_t pid = 0;
    int rc = posix_spawnp(&pid, args[0], &actions, nullptr, args.data(), envp.data());
    posix_spawn_file_actions_destroy(&actions);
    if (rc != 0) {
        result.err = std::string("spawn failed: ") + std::strerror(rc);
        return result;
    }
    int status = 0;
    for (int waited = 0;; ++waited) {
        pid_t done = waitpid(pid, &status, WNOHANG);
        if (done == pid) break;
        if (stopWhen && !result.stopped && stopWhen()) {
            result.stopped = true;
            kill(pid, stopSignal);
        }
        if (timeoutSeconds > 0 && waited == timeoutSeconds * 20) {
            result.hung = true;
            kill(pid, SIGTERM);
        }
        usleep(50000);
    }
    result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    result.out = slurp(outPath);
    result.err = slurp(errPath);
    return result;
}

std::string binDir() { return NPRGL_TEST_BIN_DIR; }

std::string libPath() { return NPRGL_TEST_LIB_PATH; }

std::string nprglCommand() { return binDir() + "/nprgl"; }

std::string demo(const std::string& name) { return binDir() + "/demo_" + name; }

std::string framePng(const std::string& dir, int frame)
{
    char name[32];
    std::snprintf(name, sizeof name, "/frame_%010d.png", frame);
    return dir + name;
}

std::string preloadValue()
{
#ifdef NPRGL_SANITIZER_RUNTIME
    return std::string(NPRGL_SANITIZER_RUNTIME) + ":" + libPath();
#else
    return libPath();
#endif
}

namespace {

// Removes this process's scratch files at exit, unless NPRGL_KEEP_TEST_FILES is set.
struct ScratchArea {
    std::filesystem::path base =
        std::filesystem::temp_directory_path() / ("nprgl-test-" + std::to_string(getpid()));
    ~ScratchArea()
    {
        std::error_code ec;
        if (!std::getenv("NPRGL_KEEP_TEST_FILES")) std::filesystem::remove_all(base, ec);
    }
};

} // namespace

std::string freshDir(const std::string& name)
{
    static int counter = 0;
    static ScratchArea scratch;
    const auto& base = scratch.base;
    auto dir = base / (name + "-" + std::to_string(++counter));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir.string();
}

std::vector<std::string> under(std::vector<std::string> nprgl,
                               const std::vector<std::string>& program)
{
    nprgl.push_back("--");
    nprgl.insert(nprgl.end(), program.begin(), program.end());
    return nprgl;
}

int coveredCount(const std::string& out)
{
    const size_t at = out.find("covered ");
    return at == std::string::npos ? -1 : std::atoi(out.c_str() + at + 8);
}

std::string fixture(const std::string& name)
{
    return std::string(NPRGL_TEST_SOURCE_DIR) + "/fixtures/" + name + ".nprgl";
}

std::string readAll(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

void writeAll(const std::string& path, const std::string& data)
{
    std::ofstream(path, std::ios::binary | std::ios::trunc) << data;
}

bool haveDisplay()
{
    const char* d = std::getenv("DISPLAY");
    return d && *d;
}

std::string why32BitProgramsCannotRun()
{
    static const std::string why = [] {
        const std::string loader = "/lib/ld-linux.so.2";
        if (access(loader.c_str(), X_OK) != 0) return "no i386 loader at " + loader;
        // The loader's own --help: a 32-bit executable that needs nothing else.
        const ProcessResult r = runProcess({loader, "--help"}, {}, 60);
        if (r.exitCode == 0) return std::string();
        const std::string how =
            r.exitCode < 0 ? "did not start" : "exit " + std::to_string(r.exitCode);
        return "this kernel does not run 32-bit programs (" + loader + " --help " + how +
               (r.err.empty() ? "" : ": " + r.err) + "; a kernel without IA32 emulation)";
    }();
    return why;
}

} // namespace nprgl::test
