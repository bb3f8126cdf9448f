// The running program's name and command line, as nprgl names files and logs after them.
#pragma once

#include <string>
#include <vector>

namespace nprgl {

// The words of /proc/self/cmdline, without the empty words a program that rewrote its
// arguments in place leaves at the end (wine pads them with NULs).
std::vector<std::string> processCommandLine();

// The last part ('/' or '\\' separated) of the command line's first word, else the kernel's
// name: not glibc's program_invocation_short_name, which points into the arguments as they
// were at start. A program may rewrite them in place: wine moves the Windows program's command
// line over its loader's, and that name became "" or a tail such as "uild/wine/prog.exe".
std::string processName();

// The rules behind the two, for tests.
std::vector<std::string> trimCommandLine(std::vector<std::string> words);
std::string programNameFrom(const std::vector<std::string>& commandLine, const std::string& comm);

} // namespace nprgl
