#pragma once

#include <csignal>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace nprgl::test {

struct ProcessResult {
    int exitCode = -1; // -1: did not start; 128+N: killed by signal N
    std::string out;
    std::string err;
    bool hung = false;    // the hang guard ran out and sent SIGTERM
    bool stopped = false; // runUntilFile's file appeared and the program was told to stop
};

// Runs argv with extra environment variables (an empty value removes the variable) and waits,
// capturing stdout and stderr. The hang guard (timeoutSeconds > 0) sends SIGTERM when it runs
// out; it is a guard against a hung program, never a speed check: how long a run takes is a
// benchmark's business.
ProcessResult runProcess(const std::vector<std::string>& argv,
                         const std::map<std::string, std::string>& env = {},
                         int timeoutSeconds = 300);

// For programs that run until they are told to stop (glxgears): runs argv until stopFile
// exists (a screenshot of frame N, written whole by a rename), then sends stopSignal. The
// run lasts a number of frames, however fast the machine is.
ProcessResult runUntilFile(const std::vector<std::string>& argv,
                           const std::map<std::string, std::string>& env,
                           const std::string& stopFile, int stopSignal = SIGINT,
                           int timeoutSeconds = 300);
// The same with any condition on what the program has done so far (a file's size...).
ProcessResult runUntil(const std::vector<std::string>& argv,
                       const std::map<std::string, std::string>& env,
                       const std::function<bool()>& stopWhen, int stopSignal = SIGINT,
                       int timeoutSeconds = 300);

// Paths of the build tree, passed in by CMake.
std::string binDir();
std::string libPath();
// The LD_PRELOAD value that loads libnprgl.so into an uninstrumented program: the library,
// behind the sanitizer runtime in a sanitizer build (the runtime must be loaded first).
std::string preloadValue();
// The nprgl command, a demo app, and the PNG `nprgl replay -o DIR` writes for a frame.
std::string nprglCommand();
std::string demo(const std::string& name);
std::string framePng(const std::string& dir, int frame);
// A fresh empty directory under the test's temporary area.
std::string freshDir(const std::string& name);
// The nprgl command line followed by "--" and the program's own.
std::vector<std::string> under(std::vector<std::string> nprgl,
                               const std::vector<std::string>& program);
// tests/fixtures/NAME.nprgl in the source tree: the captures the tests replay.
std::string fixture(const std::string& name);
// A file's bytes ("" when it cannot be read).
std::string readAll(const std::string& path);
// Writes `data` as the whole of the file at `path`.
void writeAll(const std::string& path, const std::string& data);
// Whether an X display is named (tests that need one skip or fail with a reason without).
bool haveDisplay();
// Why this machine cannot run a 32-bit x86 program, or empty: no i386 loader
// (/lib/ld-linux.so.2, libc6:i386), or a kernel built without IA32 emulation, where every
// 32-bit executable fails with "Exec format error" (some virtual machines' kernels).
std::string why32BitProgramsCannotRun();
// The "covered N" a probe prints (pixels of its last frame not of its clear colour), or -1.
int coveredCount(const std::string& out);

} // namespace nprgl::test
