// The running program's name and command line from glibc and /proc/self.
#include "common/ProcessName.h"

#include <fstream>

namespace nprgl {

std::vector<std::string> trimCommandLine(std::vector<std::string> words)
{
    while (!words.empty() && words.back().empty()) words.pop_back();
    return words;
}

std::string programNameFrom(const std::vector<std::string>& commandLine, const std::string& comm)
{
    if (!commandLine.empty()) {
        const std::string& first = commandLine.front();
        const size_t cut = first.find_last_of("/\\");
        std::string base = cut == std::string::npos ? first : first.substr(cut + 1);
        if (!base.empty()) return base;
    }
    return comm;
}

std::vector<std::string> processCommandLine()
{
    std::vector<std::string> words;
    std::ifstream in("/proc/self/cmdline", std::ios::binary);
    std::string word;
    while (std::getline(in, word, '\0')) words.push_back(word);
    return trimCommandLine(std::move(words));
}

std::string processName()
{
    std::string comm;
    std::ifstream in("/proc/self/comm");
    std::getline(in, comm);
    return programNameFrom(processCommandLine(), comm);
}

} // namespace nprgl
