// nprgl record and run --video: the program as a child, Ctrl-C passed on, its video encoded
// meanwhile, a summary of the capture at its end.
#pragma once

#include <string>
#include <vector>

namespace nprgl::cli {

class VideoReceiver;

// Runs argv (the environment already set up for the recording) as a child and waits for it,
// however it ends: a signal the terminal sends reaches the child itself, one sent to this
// process alone (kill PID) is passed on. Then prints one line about the capture at path (and
// one for each capture other processes of the program wrote beside it; when the started
// process recorded nothing and one other did, that capture is moved to path) and ends the
// way the program ended (its exit status, or the same signal), so a shell or a script sees
// the program's own result. No path: nothing is recorded. With a video: its frames are taken
// while the program runs, and its files finished when it ends.
[[noreturn]] void superviseProgram(const std::vector<std::string>& argv, const std::string& path,
                                   VideoReceiver* video);

// Replaces this process with argv (PATH searched); returns only on failure, having said why,
// with the shell's status for it (127: not found, 126: not runnable).
int execProgram(const std::vector<std::string>& argv);

// The summary line for a capture file, as `nprgl record` prints it when the program ends.
std::string recordingSummary(const std::string& path, const std::string& howItEnded);

} // namespace nprgl::cli
