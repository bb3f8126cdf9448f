#include "cli/RunCommand.h"

#include "capture/CaptureWriter.h"
#include "cli/ProgramSupervisor.h"
#include "cli/VideoReceiver.h"
#include "common/FrameSet.h"
#include "common/Log.h"
#include "common/ScreenshotSpec.h"
#include "common/VideoFeed.h"
#include "styles/Presets.h"
#include "styles/StyleSettings.h"

#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <sys/stat.h>
#include <unistd.h>

namespace nprgl::cli {

namespace fs = std::filesystem;

namespace {

// The program as execvp finds it: a name with a slash as it is, else the first executable
// of that name on PATH.
std::string findProgram(const std::string& name)
{
    if (name.find('/') != std::string::npos) return name;
    const char* path = std::getenv("PATH");
    std::string dirs = path && *path ? path : "/usr/local/bin:/usr/bin:/bin";
    for (size_t start = 0; start <= dirs.size();) {
        size_t end = dirs.find(':', start);
        if (end == std::string::npos) end = dirs.size();
        const std::string dir = end > start ? dirs.substr(start, end - start) : ".";
        const std::string candidate = dir + "/" + name;
        if (access(candidate.c_str(), X_OK) == 0) return candidate;
        start = end + 1;
    }
    return {};
}

// A set-user-ID or set-group-ID program that changes the ids runs in secure-execution mode,
// where the dynamic loader ignores LD_PRELOAD: nprgl would silently not be there.
void warnIfSecureExecution(const std::string& name)
{
    const std::string program = findProgram(name);
    struct stat st {};
    if (program.empty() || stat(program.c_str(), &st) != 0) return;
    const bool uid = (st.st_mode & S_ISUID) && st.st_uid != getuid();
    const bool gid = (st.st_mode & S_ISGID) && st.st_gid != getgid();
    if (!uid && !gid) return;
    std::fprintf(stderr,
                 "nprgl: warning: %s is set-%s-ID: the dynamic loader ignores LD_PRELOAD for "
                 "it, so nprgl cannot reach its GL calls and it runs as it is (no style, no "
                 "capture). Run a copy without the bit: cp %s ./%s && chmod u-s,g-s ./%s\n",
                 program.c_str(), uid ? "user" : "group", program.c_str(),
                 fs::path(program).filename().c_str(), fs::path(program).filename().c_str());
}

// 2: a usage error (a bad option or value); 1: anything else that stops the run.
int fail(const std::string& message, int code = 2)
{
    std::fprintf(stderr, "nprgl: %s\n", message.c_str());
    return code;
}

std::string joined(const std::vector<std::string>& items, const char* separator)
{
    std::string out;
    for (const std::string& item : items) out += (out.empty() ? "" : separator) + item;
    return out;
}

// A launcher's command line (Steam's %command%, a shell's) may begin with NAME=value words:
// they go to the environment, as the shell and env(1) take them, before nprgl reads it, and
// the program is the first word after them. Returns how many there were.
size_t applyAssignments(const std::vector<std::string>& command)
{
    size_t count = 0;
    for (const std::string& word : command) {
        const size_t eq = word.find('=');
        if (eq == 0 || eq == std::string::npos || std::isdigit((unsigned char)word[0])) break;
        bool name = true;
        for (size_t i = 0; i < eq; ++i) {
            name = name && (std::isalnum((unsigned char)word[i]) || word[i] == '_');
        }
        if (!name) break;
        setenv(word.substr(0, eq).c_str(), word.c_str() + eq + 1, 1);
        ++count;
    }
    return count;
}

} // namespace

std::string findLibrary(std::string& error)
{
    if (const char* env = std::getenv("NPRGL_LIBRARY"); env && *env) {
        if (fs::exists(env)) return fs::absolute(env).string();
        error = std::string("NPRGL_LIBRARY=") + env + " does not exist";
        return {};
    }
    std::error_code ec;
    fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    // The build tree's first (build/bin/nprgl, build/lib/libnprgl.so), then the installed
    // layout (<prefix>/bin/nprgl, <prefix>/<libdir>/nprgl/libnprgl.so).
    for (const char* rel : {"../lib/libnprgl.so", NPRGL_BIN_TO_LIBDIR "/libnprgl.so",
                            "../lib/nprgl/libnprgl.so", "libnprgl.so"}) {
        fs::path candidate = exe.parent_path() / rel;
        if (!ec && fs::exists(candidate)) return fs::canonical(candidate).string();
    }
    error = "cannot find libnprgl.so next to " + exe.string() + " (set NPRGL_LIBRARY)";
    return {};
}

std::string preloadEntry(const std::string& library)
{
#ifdef NPRGL_LIBDIR_IS_LOADER_LIB
    // Installed in <prefix>/<libdir>/nprgl with libdir what the loader's $LIB expands to
    // (Debian: lib/x86_64-linux-gnu, lib/i386-linux-gnu): <prefix>/$LIB/nprgl/libnprgl.so
    // loads the library of each program's own architecture, in its children too, as
    // MangoHud's command does. The build tree mirrors that layout (build/bin/nprgl,
    // build/lib/<multiarch>/nprgl/libnprgl.so, the 32-bit one from scripts/build-i386.sh).
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (ec || std::getenv("NPRGL_LIBRARY")) return library;
    const fs::path prefix = fs::weakly_canonical(exe.parent_path() / NPRGL_BIN_TO_PREFIX, ec);
    const fs::path installed = prefix / NPRGL_INSTALL_LIBDIR / "nprgl" / "libnprgl.so";
    if (!ec && fs::equivalent(installed, library, ec)) {
        return (prefix / "$LIB" / "nprgl" / "libnprgl.so").string();
    }
#endif
    return library;
}

int runProgram(const RunOptions& options)
{
    std::vector<std::string> command = options.command;
    command.erase(command.begin(), command.begin() + long(applyAssignments(command)));
    if (command.empty()) return fail("no program to run (see nprgl --help)");

    // Refuse bad settings here, before the program starts, rather than in the library where
    // the only safe answer is to fall back to passthrough.
    std::string config = joined(options.settings, ",");
    if (const char* env = std::getenv("NPRGL_CONFIG"); env && *env && !config.empty()) {
        config = std::string(env) + "," + config;
    } else if (config.empty() && std::getenv("NPRGL_CONFIG")) {
        config = std::getenv("NPRGL_CONFIG");
    }
    std::string style = options.style;
    if (style.empty() && std::getenv("NPRGL_STYLE")) style = std::getenv("NPRGL_STYLE");
    std::string preset = options.preset;
    if (preset.empty() && std::getenv("NPRGL_PRESET")) preset = std::getenv("NPRGL_PRESET");
    // A recording is the program's own stream at its own speed, as apitrace records; a style
    // is applied at replay, or while recording when asked for.
    if (options.record && style.empty() && preset.empty()) style = "none";
    std::string error;
    if (!Presets::combine(preset, style, config, error)) return fail("--preset: " + error);
    StyleSettings settings;
    if (!StyleSettings::parse(style, config, settings, error)) return fail(error);
    unsetenv("NPRGL_PRESET"); // resolved here: the library gets the chain and values
    ScreenshotSpec screenshot;
    if (!options.screenshot.empty() &&
        !ScreenshotSpec::parse(options.screenshot, screenshot, error)) {
        return fail("--screenshot: " + error + " (expected frames=LIST;dir=DIR)");
    }
    LogLevel level;
    if (!options.logLevel.empty() && !parseLogLevel(options.logLevel.c_str(), level)) {
        return fail("--log-level: unknown level '" + options.logLevel +
                    "' (use error, warn, info or debug)");
    }
    std::string library = findLibrary(error);
    if (library.empty()) return fail(error, 1);
    std::string recordPath;
    if (options.record) {
        FrameSet frames;
        if (!options.recordFrames.empty() &&
            !FrameSet::parse(options.recordFrames, frames, error)) {
            return fail("--frames: " + error);
        }
        std::string file = options.recordFile.empty()
                               ? fs::path(command[0]).filename().string() + ".nprgl"
                               : options.recordFile;
        // Refused before the program starts: a file that is not a capture is never
        // overwritten, a capture only with --force, and a FIFO or device is never opened.
        std::string why;
        const auto target = capture::CaptureWriter::checkTarget(file, why);
        if (target == capture::CaptureWriter::Target::Other ||
            target == capture::CaptureWriter::Target::Refused) {
            std::fprintf(stderr, "nprgl: cannot record to %s: it %s\n", file.c_str(), why.c_str());
            return 1;
        }
        if (target == capture::CaptureWriter::Target::Capture && !options.recordForce) {
            std::fprintf(stderr,
                         "nprgl: %s is a capture already; --force replaces it, -o FILE writes "
                         "another\n",
                         file.c_str());
            return 1;
        }
        if (options.recordForce) {
            setenv("NPRGL_RECORD_FORCE", "1", 1);
        } else {
            unsetenv("NPRGL_RECORD_FORCE");
        }
        // Absolute: the program may change its directory before its first frame.
        recordPath = fs::absolute(file).string();
        setenv("NPRGL_RECORD", recordPath.c_str(), 1);
        // This command says what was recorded when the program ends (the library, alone,
        // says it at exit); the program sets NPRGL_RECORD_PID as it starts.
        setenv("NPRGL_RECORD_SUMMARY", "command", 1);
        if (!options.recordFrames.empty()) {
            setenv("NPRGL_RECORD_FRAMES", options.recordFrames.c_str(), 1);
        }
    }

    // A chain given here (or by a preset) wins over the configuration files; none given,
    // the library takes the files' chain, else the default.
    if (!style.empty()) {
        setenv("NPRGL_STYLE", settings.chainName().c_str(), 1);
    } else {
        unsetenv("NPRGL_STYLE");
    }
    setenv("NPRGL_CONFIG", config.c_str(), 1);
    if (!options.screenshot.empty()) setenv("NPRGL_SCREENSHOT", options.screenshot.c_str(), 1);
    if (!options.logLevel.empty()) setenv("NPRGL_LOG_LEVEL", options.logLevel.c_str(), 1);
    if (!options.logFile.empty()) setenv("NPRGL_LOG_FILE", options.logFile.c_str(), 1);
    std::string preload = preloadEntry(library);
    if (const char* old = std::getenv("LD_PRELOAD"); old && *old) {
        if (std::strstr(old, preload.c_str())) {
            preload = old;
        } else {
            preload += std::string(":") + old;
        }
    }
#ifdef NPRGL_SANITIZER_RUNTIME
    // A sanitizer build of the library: the runtime must be the first library loaded.
    if (preload.find(NPRGL_SANITIZER_RUNTIME) == std::string::npos) {
        preload = std::string(NPRGL_SANITIZER_RUNTIME) + ":" + preload;
    }
#endif
    setenv("LD_PRELOAD", preload.c_str(), 1);

    // The frames come to this process, which encodes them while the program runs: FFmpeg is
    // never loaded into the program.
    VideoReceiver video;
    if (!options.video.empty()) {
        if (!video.open(options.video, options.fps, error)) return fail("--video: " + error);
        setenv(video::kSocketVariable, video.socketName().c_str(), 1);
        setenv(video::kFpsVariable, std::to_string(options.fps).c_str(), 1);
        if (options.videoOnKey) {
            setenv(video::kStartVariable, "key", 1);
        } else {
            unsetenv(video::kStartVariable);
        }
    } else {
        // A feed of an nprgl command this one runs under is not this program's.
        unsetenv(video::kSocketVariable);
    }

    warnIfSecureExecution(command.front());
    if (options.record || !options.video.empty()) {
        superviseProgram(command, recordPath, options.video.empty() ? nullptr : &video);
    }
    return execProgram(command);
}

} // namespace nprgl::cli
