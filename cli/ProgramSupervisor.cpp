#include "cli/ProgramSupervisor.h"

#include "capture/CaptureReader.h"
#include "cli/VideoReceiver.h"

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <optional>
#include <set>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace nprgl::cli {

namespace {

volatile sig_atomic_t gChild = 0;

constexpr int kPassedOn[] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGUSR1, SIGUSR2};

// A signal the kernel raised for the terminal (Ctrl-C, a hang-up) went to the whole
// foreground process group, the program included: passing it on would deliver it twice.
// One a process sent (kill, a supervisor's SIGTERM) reached only this process.
void passOn(int signal, siginfo_t* info, void*)
{
    const bool sentByAProcess = info && info->si_code <= 0;
    if (gChild > 0 && sentByAProcess) kill(pid_t(gChild), signal);
}

std::string megabytes(uint64_t bytes)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.1f MB", double(bytes) / 1e6);
    return text;
}

[[noreturn]] void endAsTheProgramDid(int status)
{
    if (WIFEXITED(status)) std::exit(WEXITSTATUS(status));
    const int signal = WIFSIGNALED(status) ? WTERMSIG(status) : SIGABRT;
    // The program's core, if any, is the program's; this process leaves none of its own.
    rlimit none{0, 0};
    setrlimit(RLIMIT_CORE, &none);
    std::signal(signal, SIG_DFL);
    sigset_t set;
    sigemptyset(&set);
    sigaddset(&set, signal);
    sigprocmask(SIG_UNBLOCK, &set, nullptr);
    raise(signal);
    std::_Exit(128 + signal);
}

// The pid that wrote the capture at path, when this run wrote it (its header's start is not
// before the run's); nullopt for no capture or an older one.
std::optional<uint32_t> writerSince(const std::string& path, uint64_t since)
{
    capture::CaptureReader reader;
    std::string error;
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec) || !reader.open(path, error)) return {};
    const auto& meta = reader.metadata();
    if (meta.startTimeUnix < since) return {};
    return meta.pid;
}

// A capture another process of this run wrote beside the one asked for.
struct OtherCapture {
    std::string path;
    uint32_t pid = 0;
};

// <stem>.<pid>.nprgl beside path (the name CaptureSession gives a process other than the one
// started) whose header names that pid and a start not before the run's, by name.
std::vector<OtherCapture> capturesOfOtherProcesses(const std::string& path, uint64_t since)
{
    namespace fs = std::filesystem;
    const fs::path asked(path);
    std::string stem = asked.filename().string();
    if (stem.ends_with(".nprgl")) stem.resize(stem.size() - 6);
    std::vector<OtherCapture> found;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(asked.parent_path(), ec)) {
        const std::string name = entry.path().filename().string();
        if (!name.starts_with(stem + ".") || !name.ends_with(".nprgl")) continue;
        const std::string pid = name.substr(stem.size() + 1, name.size() - stem.size() - 7);
        if (pid.empty() || pid.size() > 10 || pid.find_first_not_of("0123456789") != pid.npos)
            continue;
        const auto writer = writerSince(entry.path().string(), since);
        if (writer && *writer == std::stoul(pid)) found.push_back({entry.path().string(), *writer});
    }
    std::sort(found.begin(), found.end(),
              [](const OtherCapture& x, const OtherCapture& y) { return x.path < y.path; });
    return found;
}

} // namespace

std::string recordingSummary(const std::string& path, const std::string& howItEnded)
{
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) {
        return "nothing recorded: the program " + howItEnded + " before its first frame (no " +
               path + ")";
    }
    capture::CaptureReader reader;
    std::string error;
    if (!reader.open(path, error)) return "the recording cannot be read: " + error;
    std::set<uint32_t> contexts;
    for (const auto& frame : reader.frames()) contexts.insert(frame.contextId);
    std::string line = "recorded " + std::to_string(reader.frames().size()) + " frames";
    if (contexts.size() > 1) line += " of " + std::to_string(contexts.size()) + " contexts";
    line += " to " + path + " (" + megabytes(reader.fileBytes()) + ")";
    if (reader.recovered()) {
        line +=
            "; the program " + howItEnded + " without closing it: it reads to its last whole frame";
    }
    std::string uncaptured;
    for (const auto& [name, count] : reader.callCounts()) {
        uncaptured += (uncaptured.empty() ? "" : ", ") + name + " x" + std::to_string(count);
    }
    line += "; not captured: " + (uncaptured.empty() ? std::string("nothing") : uncaptured);
    // Damage is worth a word here; an unclosed end is said above already.
    if (!reader.damage().empty()) line += "; " + reader.warning();
    return line;
}

int execProgram(const std::vector<std::string>& argv)
{
    std::vector<char*> args;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    execvp(args[0], args.data());
    const int err = errno;
    std::fprintf(stderr, "nprgl: cannot run '%s': %s\n", args[0], std::strerror(err));
    return err == ENOENT ? 127 : 126;
}

void superviseProgram(const std::vector<std::string>& argv, const std::string& path,
                      VideoReceiver* video)
{
    struct sigaction action {};
    action.sa_sigaction = passOn;
    action.sa_flags = SA_SIGINFO | SA_RESTART;
    sigemptyset(&action.sa_mask);
    for (int signal : kPassedOn) sigaction(signal, &action, nullptr);

    std::fflush(nullptr);
    const uint64_t start = uint64_t(std::time(nullptr));
    const pid_t self = getpid();
    const pid_t child = fork();
    if (child < 0) {
        std::fprintf(stderr, "nprgl: cannot start the program: %s\n", std::strerror(errno));
        std::exit(1);
    }
    if (child == 0) {
        // exec resets the handlers above to the default; the program finds its usual ones.
        // Should this process be killed outright, the program is told to end rather than
        // left running unwatched.
        prctl(PR_SET_PDEATHSIG, SIGTERM);
        if (getppid() != self) std::_Exit(128 + SIGTERM);
        if (!path.empty()) setenv("NPRGL_RECORD_PID", std::to_string(getpid()).c_str(), 1);
        std::fflush(stderr);
        std::_Exit(execProgram(argv));
    }
    gChild = child;
    // The encoder shares the processors with the program: the program comes first (a frame
    // the encoder has no time for is counted, the program never waits for it).
    if (video) setpriority(PRIO_PROCESS, 0, 10);
    int status = 0;
    for (;;) {
        if (video) video->serve(50);
        const pid_t ended = waitpid(child, &status, video ? WNOHANG : 0);
        if (ended == child) break;
        if (ended < 0 && errno != EINTR) {
            std::fprintf(stderr, "nprgl: waiting for the program: %s\n", std::strerror(errno));
            std::exit(1);
        }
    }
    gChild = 0;
    if (video) video->finish();
    const bool couldNotStart = !path.empty() && WIFEXITED(status) &&
                               (WEXITSTATUS(status) == 127 || WEXITSTATUS(status) == 126) &&
                               !std::filesystem::exists(path);
    if (!path.empty() && !couldNotStart) {
        std::string how = "exited with status " + std::to_string(WEXITSTATUS(status));
        if (WIFSIGNALED(status)) {
            const char* name = sigabbrev_np(WTERMSIG(status));
            how = "was stopped by " +
                  (name ? "SIG" + std::string(name) : "signal " + std::to_string(WTERMSIG(status)));
        }
        std::vector<OtherCapture> others = capturesOfOtherProcesses(path, start);
        const bool startedWrote = writerSince(path, start).has_value();
        std::string by;
        if (!startedWrote && others.size() == 1) {
            // The process started did not draw, the one it started did (wine's loader
            // starts wine64 for a 64-bit .exe, a launcher its game): its capture is the
            // one asked for.
            std::error_code ec;
            std::filesystem::rename(others.front().path, path, ec);
            if (!ec) {
                by = " (by process " + std::to_string(others.front().pid) +
                     ", which the program started)";
                others.clear();
            }
        }
        if (!others.empty() && !startedWrote) {
            std::fprintf(stderr, "nprgl: the program recorded nothing itself (no %s); %zu "
                         "processes it started did:\n", path.c_str(), others.size());
        } else {
            std::fprintf(stderr, "nprgl: %s%s\n", recordingSummary(path, how).c_str(),
                         by.c_str());
        }
        for (const OtherCapture& other : others) {
            std::fprintf(stderr, "nprgl: and by process %u, which the program started: %s\n",
                         other.pid, recordingSummary(other.path, how).c_str());
        }
    }
    endAsTheProgramDid(status);
}

} // namespace nprgl::cli
